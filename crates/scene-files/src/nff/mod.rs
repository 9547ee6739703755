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
//! | `l x y z [r g b]` | point light without falloff; without a colour, each of the n lights is grey 1/√n, as the SPD generators make them for POV-Ray |
//! | `f r g b Kd Ks Shine T ior` | material: colour = Kd·(r, g, b); reflectance = Ks (mirror, grey) and specular = Ks with shininess = Shine (the highlight); transparency = T; ior (ignored when T = 0) |
//! | `s x y z r` | sphere |
//! | `p n` + n corners | planar polygon, convex or not, cut into n − 2 compact triangles by ear clipping (`polygon.rs`) |
//! | `pp n` + n corners with normals | the same, smooth: triangles with vertex normals |
//! | `c` + base `x y z r` + apex `x y z r` (on the `c` line or two lines of their own) | cone or cylinder without caps, one [`Shape::Cone`]; negative radii (both): only the inside is seen, so its normals point in (`inside_out`) |
//!
//! NFF lights do not fall off with distance, so they become raybook point
//! lights with [`Falloff::None`]. NFF leaves the brightness of a light
//! without a colour open ("a useful intensity as desired"); the SPD
//! generators write their POV-Ray scenes with n lights of colour 1/√n each
//! ("for raytracers that don't scale the light intensity, we will do it for
//! them"), and so does this reader, so that both pictures match. The
//! highlight is Blinn–Phong (n·h)^Shine where SPD renderers use Phong's
//! (r·v)^Shine, so highlights are somewhat wider. NFF has no ambient light.
//!
//! The viewpoint, image sides, triangles and trace settings are checked by
//! the same rules as TOML scenes (`scene/rules.rs`), and NFF scenes get the
//! TOML defaults for what NFF does not say (one sample per pixel, the
//! default [`TraceSpec`]).

use std::path::Path;

use crate::Vec3;

use super::MemoryLimit;
use super::rules::{self, has_area};
use super::{
    CameraSpec, Falloff, ImageSpec, Light, Material, MaterialId, Object, Scene, SceneError, Shape,
    TraceSpec,
};
use crate::Color;
use reader::{Line, Reader};

mod polygon;
mod reader;
mod viewpoint;

/// Is `path` an NFF file, by its name (`.nff`, in any case)?
pub fn is_nff(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("nff"))
}

/// Reads and converts an NFF file. As with a TOML scene, a file larger than
/// the memory the machine has is refused before it is read, and one whose
/// scene would need more before it is converted (see [`parse_within`]).
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    load_within(path, MemoryLimit::of_machine().as_ref())
}

/// [`load`] within `limit`; `None` checks nothing.
pub fn load_within(
    path: impl AsRef<Path>,
    limit: Option<&MemoryLimit>,
) -> Result<Scene, SceneError> {
    let (text, name) = super::read_within(path.as_ref(), limit)?;
    parse_within(&text, &name, limit)
}

/// Parses NFF text; `file` names it in error messages. A scene that would
/// need more memory than the machine has is refused first.
pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    parse_within(text, file, MemoryLimit::of_machine().as_ref())
}

/// [`parse`], refusing a scene that would need more than `limit`: its text
/// and [`BYTES_PER_OBJECT`](super::BYTES_PER_OBJECT) for each line (an
/// object takes one line at least); `None` checks nothing.
pub fn parse_within(
    text: &str,
    file: &str,
    limit: Option<&MemoryLimit>,
) -> Result<Scene, SceneError> {
    super::file::check_nff(file, text, limit)?;
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
    fn entity<'a>(&mut self, line: &Line<'a>, reader: &mut Reader<'a>) -> Result<(), SceneError> {
        match line.keyword() {
            "v" => self.camera = Some(viewpoint::viewpoint(line, reader)?),
            "b" => self.background = color(reader, line, &reader.numbers(line, 3, "b r g b")?)?,
            "l" => self.light(line, reader)?,
            "f" => self.material(line, reader)?,
            "s" => self.sphere(line, reader)?,
            "p" | "pp" => self.polygon(line, reader)?,
            "c" => self.cone(line, reader)?,
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

    /// A `p` or `pp` polygon, cut into triangles by ear clipping
    /// (`polygon.rs`), which is right for concave polygons too.
    fn polygon(&mut self, line: &Line, reader: &mut Reader) -> Result<(), SceneError> {
        let smooth = line.keyword() == "pp";
        let corners = polygon_corners(line, reader, smooth)?;
        let points: Vec<Vec3> = corners.iter().map(|c| c.0).collect();
        let mut shapes = Vec::with_capacity(corners.len() - 2);
        for [a, b, c] in polygon::triangulate(&points)
            .into_iter()
            .map(|t| t.map(|i| corners[i]))
        {
            let vertices = [a.0, b.0, c.0];
            if !has_area(vertices) {
                continue; // a triangle of collinear corners: nothing to see
            }
            shapes.push(match smooth {
                true => Shape::SmoothTriangle {
                    vertices,
                    normals: [a.1, b.1, c.1],
                },
                false => Shape::Triangle { vertices },
            });
        }
        if shapes.is_empty() {
            let message = "the polygon has zero area (its corners lie on a line)";
            return Err(reader.error(line, 1, message));
        }
        self.add_all(line, reader, shapes)
    }

    /// A `c` cone or cylinder: one [`Shape::Cone`].
    fn cone<'a>(&mut self, line: &Line<'a>, reader: &mut Reader<'a>) -> Result<(), SceneError> {
        let shape = cone_shape(line, reader)?;
        self.add(line, reader, shape)
    }

    /// Adds shapes with the current material.
    fn add_all(
        &mut self,
        line: &Line,
        reader: &Reader,
        shapes: Vec<Shape>,
    ) -> Result<(), SceneError> {
        shapes
            .into_iter()
            .try_for_each(|shape| self.add(line, reader, shape))
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
        // The SPD generators' grey for n lights without a colour: 1/√n.
        let grey = 1.0 / (self.lights.len().max(1) as f32).sqrt();
        let lights = (self.lights.iter())
            .map(|&(position, colour)| Light::Point {
                position,
                color: colour.unwrap_or(Color::splat(grey)),
                intensity: 1.0,
                shadows: true,
                falloff: Falloff::None,
            })
            .collect();
        Ok(Scene {
            camera,
            image: ImageSpec {
                width,
                height,
                background: self.background,
                samples: 1, // one ray per pixel, as the benchmark asks
                seed: None,
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
    let count = polygon::corner_count(count, reader.lines_left())
        .map_err(|message| reader.error(line, line.column(1), message))?;
    let mut corners = Vec::with_capacity(count);
    for i in 0..count {
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

/// The cone of a `c` entity.
///
/// The radii are both ≥ 0, one of them > 0; or, by NFF's rule, both
/// negative, meaning that only the inside of the cone is visible: the cone
/// of their magnitudes, `inside_out`. The ends are then checked by the rules
/// of TOML scenes ([`rules::cone`]).
fn cone_shape<'a>(line: &Line<'a>, reader: &mut Reader<'a>) -> Result<Shape, SceneError> {
    let [base_end, apex_end] = cone_numbers(line, reader)?;
    let (b, a) = (base_end.numbers, apex_end.numbers);
    if b[..3] == a[..3] {
        return Err(apex_end.error(reader, 0, rules::CONE_AXIS));
    }
    let inside_out = b[3] < 0.0 && a[3] < 0.0;
    if !inside_out && b[3].min(a[3]) < 0.0 {
        let wrong = if b[3] < 0.0 { &base_end } else { &apex_end };
        let message = "a radius is negative only if both are (then only the inside is seen)";
        return Err(wrong.error(reader, 3, message));
    }
    if b[3] == 0.0 && a[3] == 0.0 {
        return Err(apex_end.error(reader, 3, rules::CONE_RADII));
    }
    let (base, base_radius) = (Vec3::new(b[0], b[1], b[2]), b[3].abs());
    let (apex, apex_radius) = (Vec3::new(a[0], a[1], a[2]), a[3].abs());
    rules::cone(base, base_radius, apex, apex_radius).map_err(|m| reader.error(line, 1, m))?;
    Ok(Shape::Cone {
        base,
        base_radius,
        apex,
        apex_radius,
        inside_out,
    })
}

/// The numbers `x y z radius` of one end of a cone, and where they are.
struct ConeEnd<'a> {
    line: Line<'a>,
    /// The word of the line where they start.
    first: usize,
    numbers: [f32; 4],
}

impl ConeEnd<'_> {
    /// An error at number `i` (0 to 3) of this end.
    fn error(&self, reader: &Reader, i: usize, message: &str) -> SceneError {
        reader.error(&self.line, self.line.column(self.first + i), message)
    }
}

/// The base and the apex of a `c` entity. NFF writes `c` and then
/// `base.x base.y base.z base_radius` and `apex.x apex.y apex.z apex_radius`
/// on two lines of their own; the SPD generators write all eight numbers on
/// the `c` line. Both are read.
fn cone_numbers<'a>(
    line: &Line<'a>,
    reader: &mut Reader<'a>,
) -> Result<[ConeEnd<'a>; 2], SceneError> {
    let four = |n: &[f32]| [n[0], n[1], n[2], n[3]];
    if line.words.len() > 1 {
        let form = "c base.x base.y base.z base_radius apex.x apex.y apex.z apex_radius";
        let n = reader.numbers(line, 8, form)?;
        let end = |first: usize| ConeEnd {
            line: line.clone(),
            first,
            numbers: four(&n[first - 1..]),
        };
        return Ok([end(1), end(5)]);
    }
    let mut end = |what: &str| {
        let line = reader.expect_line(line, &format!("the {what} of the cone"))?;
        let form = format!("{what}.x {what}.y {what}.z {what}_radius");
        let n = reader.numbers_from(&line, 0, 4..=4, &form)?;
        Ok(ConeEnd {
            line,
            first: 0,
            numbers: four(&n),
        })
    };
    Ok([end("base")?, end("apex")?])
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
