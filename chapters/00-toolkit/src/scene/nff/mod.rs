//! Eric Haines' Neutral File Format (NFF), the format of the Standard
//! Procedural Databases (SPD), read into a raybook [`Scene`].
//!
//! One entity per line, numbers separated by white space, `#` starts a
//! comment:
//!
//! | NFF | raybook |
//! | --- | --- |
//! | `v` + `from`, `at`, `up`, `angle`, `hither`, `resolution` | camera and image size. `angle` spans the centres of the first and last pixel row, so vfov = 2·atan(tan(angle/2) / (1 − 1/height)) (vfov = angle for one row); `hither` is ignored (rays start at the eye) |
//! | `b r g b` | background colour |
//! | `l x y z [r g b]` | point light; without a colour, each of the n lights gets 1/n of a total of white |
//! | `f r g b Kd Ks Shine T ior` | material: colour = Kd·(r, g, b); reflectance = Ks (mirror, grey) and specular = Ks with shininess = Shine (the highlight); transparency = T; ior (ignored when T = 0) |
//! | `s x y z r` | sphere |
//! | `p n` + n corners | convex polygon, split into the fan of triangles from its first corner |
//! | `pp n` + n corners with normals | the same, smooth: triangles with vertex normals |
//! | `c` (cone or cylinder) | refused, naming the line |
//!
//! NFF lights do not fall off with distance; raybook's point lights fall off
//! with 1/r². Each light's intensity is therefore scaled by r₀², its distance
//! to the camera's `at` point, so that it has its NFF brightness there. The
//! highlight is Blinn–Phong (n·h)^Shine where SPD renderers use Phong's
//! (r·v)^Shine, so highlights are somewhat wider. NFF has no ambient light.
//!
//! The viewpoint, image sides, triangles and trace settings are checked by
//! the same rules as TOML scenes (`scene/rules.rs`), and NFF scenes get the
//! TOML defaults for what NFF does not say (one sample per pixel, the
//! default [`TraceSpec`]).

use std::path::Path;

use glam::Vec3;

use super::rules::{self, has_area};
use super::{
    CameraSpec, ImageSpec, Light, Material, MaterialId, Object, Scene, SceneError, Shape, TraceSpec,
};
use crate::Color;
use reader::{Line, Reader};

mod reader;
mod viewpoint;

/// Is `path` an NFF file, by its name (`.nff`, in any case)?
pub fn is_nff(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("nff"))
}

/// Reads and converts an NFF file.
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SceneError::io(&name, &e))?;
    parse(&text, &name)
}

/// Parses NFF text; `file` names it in error messages.
pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    let mut reader = Reader::new(text, file);
    let mut nff = Nff::default();
    while let Some(line) = reader.next_line() {
        nff.entity(&line, &mut reader)?;
    }
    nff.into_scene(&reader)
}

/// What has been read so far.
#[derive(Default)]
struct Nff {
    /// The camera and the image's width and height.
    camera: Option<(CameraSpec, u32, u32)>,
    background: Color,
    /// Position and colour (`None`: an equal share) of each light.
    lights: Vec<(Vec3, Option<Color>)>,
    materials: Vec<Material>,
    objects: Vec<Object>,
}

impl Nff {
    /// Reads the entity that starts on `line` (and the lines it takes).
    fn entity(&mut self, line: &Line, reader: &mut Reader) -> Result<(), SceneError> {
        match line.keyword() {
            "v" => self.camera = Some(viewpoint::viewpoint(line, reader)?),
            "b" => self.background = color(reader, line, &reader.numbers(line, 3, "b r g b")?)?,
            "l" => self.light(line, reader)?,
            "f" => self.material(line, reader)?,
            "s" => self.sphere(line, reader)?,
            "p" | "pp" => self.polygon(line, reader)?,
            "c" => {
                return Err(reader.error(
                    line,
                    1,
                    "cones and cylinders (`c`) are not supported by raybook; \
                     replace the `c` entity and its two lines by polygons",
                ));
            }
            other => {
                return Err(reader.error(
                    line,
                    1,
                    format!(
                        "unknown entity `{other}`; NFF has v, b, l, f, c, s, p and pp \
                         (and # for comments)"
                    ),
                ));
            }
        }
        Ok(())
    }

    fn light(&mut self, line: &Line, reader: &Reader) -> Result<(), SceneError> {
        let n = reader.numbers_from(line, 1, 3..=6, "l x y z [r g b]")?;
        if n.len() != 3 && n.len() != 6 {
            return Err(reader.error(line, 1, "expected `l x y z` or `l x y z r g b`"));
        }
        let colour = match n.len() {
            6 => Some(color(reader, line, &n[3..])?),
            _ => None,
        };
        self.lights.push((Vec3::new(n[0], n[1], n[2]), colour));
        Ok(())
    }

    fn material(&mut self, line: &Line, reader: &Reader) -> Result<(), SceneError> {
        let form = "f r g b Kd Ks Shine T index_of_refraction";
        let n = reader.numbers(line, 8, form)?;
        let (kd, ks, shine, t, ior) = (n[3], n[4], n[5], n[6], n[7]);
        for (i, name) in [(3, "Kd"), (4, "Ks"), (6, "T")] {
            if !(0.0..=1.0).contains(&n[i]) {
                let message = format!("{name} is a weight between 0 and 1, found {}", n[i]);
                return Err(reader.error(line, line.column(i + 1), message));
            }
        }
        if shine <= 0.0 {
            return Err(reader.error(line, line.column(6), "Shine must be > 0"));
        }
        if t > 0.0 && ior <= 0.0 {
            let message = "a transparent material (T > 0) needs an index of refraction > 0";
            return Err(reader.error(line, line.column(8), message));
        }
        self.materials.push(Material {
            name: format!("f (line {})", line.number),
            color: kd * color(reader, line, &n[..3])?,
            reflectance: Color::splat(ks),
            specular: ks,
            shininess: shine,
            transparency: t,
            ior: if t > 0.0 { ior } else { 1.0 },
            fresnel: false,
        });
        Ok(())
    }

    fn sphere(&mut self, line: &Line, reader: &Reader) -> Result<(), SceneError> {
        let n = reader.numbers(line, 4, "s x y z radius")?;
        if n[3] <= 0.0 {
            return Err(reader.error(line, line.column(4), "the radius must be > 0"));
        }
        let shape = Shape::Sphere {
            center: Vec3::new(n[0], n[1], n[2]),
            radius: n[3],
        };
        self.add(line, reader, shape)
    }

    /// A `p` or `pp` polygon, as the fan of triangles (v0, vi, vi+1).
    fn polygon(&mut self, line: &Line, reader: &mut Reader) -> Result<(), SceneError> {
        let smooth = line.keyword() == "pp";
        let corners = polygon_corners(line, reader, smooth)?;
        let mut added = 0;
        for i in 1..corners.len() - 1 {
            let [a, b, c] = [corners[0], corners[i], corners[i + 1]];
            let vertices = [a.0, b.0, c.0];
            if !has_area(vertices) {
                continue; // a fan triangle of collinear corners: nothing to see
            }
            let shape = match smooth {
                true => Shape::SmoothTriangle {
                    vertices,
                    normals: [a.1, b.1, c.1],
                },
                false => Shape::Triangle { vertices },
            };
            self.add(line, reader, shape)?;
            added += 1;
        }
        if added == 0 {
            return Err(reader.error(
                line,
                1,
                "the polygon has zero area (its corners lie on a line)",
            ));
        }
        Ok(())
    }

    /// Adds a shape with the current material.
    fn add(&mut self, line: &Line, reader: &Reader, shape: Shape) -> Result<(), SceneError> {
        let Some(material) = self.materials.len().checked_sub(1) else {
            return Err(reader.error(
                line,
                1,
                "an object needs a material: put an `f` line before the first object",
            ));
        };
        self.objects.push(Object {
            shape,
            material: material as MaterialId,
            shadows: true,
        });
        Ok(())
    }

    fn into_scene(self, reader: &Reader) -> Result<Scene, SceneError> {
        let Some((camera, width, height)) = self.camera else {
            let message = "the file has no viewpoint (a `v` entity)";
            return Err(reader.error(&reader.end(), 1, message));
        };
        // Equal shares of white for the lights without a colour.
        let share = 1.0 / self.lights.len().max(1) as f32;
        let lights = (self.lights.iter())
            .map(|&(position, colour)| Light::Point {
                position,
                color: colour.unwrap_or(Color::splat(share)),
                // 1/r² falloff, calibrated to be 1 at the `at` point.
                intensity: (position.distance_squared(camera.look_at)).max(f32::MIN_POSITIVE),
                shadows: true,
            })
            .collect();
        Ok(Scene {
            camera,
            image: ImageSpec {
                width,
                height,
                background: self.background,
                samples: 1, // one ray per pixel, as the benchmark asks
            },
            trace: TraceSpec::default(),
            materials: self.materials,
            lights,
            objects: self.objects,
        })
    }
}

/// The corners after a `p count` or `pp count` line, with their normals
/// (zero for `p`).
fn polygon_corners(
    line: &Line,
    reader: &mut Reader,
    smooth: bool,
) -> Result<Vec<(Vec3, Vec3)>, SceneError> {
    let form = if smooth { "pp count" } else { "p count" };
    let count = reader.numbers(line, 1, form)?[0];
    if count < 3.0 || count.fract() != 0.0 || count > 1e6 {
        let message = format!("a polygon has a whole number of corners, 3 or more; found {count}");
        return Err(reader.error(line, line.column(1), message));
    }
    let mut corners = Vec::with_capacity(count as usize);
    for i in 0..count as usize {
        let what = format!("corner {} of {count}", i + 1);
        let corner = reader.expect_line(line, &what)?;
        corners.push(polygon_corner(&corner, reader, smooth)?);
    }
    Ok(corners)
}

/// A corner of a polygon: `x y z`, or `x y z nx ny nz` for a patch.
fn polygon_corner(line: &Line, reader: &Reader, smooth: bool) -> Result<(Vec3, Vec3), SceneError> {
    if !smooth {
        let n = reader.numbers_from(line, 0, 3..=3, "x y z")?;
        return Ok((Vec3::from_slice(&n), Vec3::ZERO));
    }
    let n = reader.numbers_from(line, 0, 6..=6, "x y z nx ny nz")?;
    let normal = Vec3::from_slice(&n[3..]);
    if rules::direction(normal).is_err() {
        let message =
            format!("a vertex normal must not be zero (nor beyond f32 to measure); found {normal}");
        return Err(reader.error(line, line.column(3), message));
    }
    Ok((Vec3::from_slice(&n[..3]), normal.normalize()))
}

/// A colour with components in [0, 1].
fn color(reader: &Reader, line: &Line, rgb: &[f32]) -> Result<Color, SceneError> {
    let c = Color::from_slice(rgb);
    if c.min_element() < 0.0 || c.max_element() > 1.0 {
        return Err(reader.error(
            line,
            1,
            format!("colour components are between 0 and 1, found {c}"),
        ));
    }
    Ok(c)
}
