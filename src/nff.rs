//! Eric Haines' Neutral File Format (NFF), the format of the Standard
//! Procedural Databases (SPD), read into a raybook [`Scene`].
//!
//! One entity per line, numbers separated by white space, `#` starts a
//! comment:
//!
//! | NFF | raybook |
//! | --- | --- |
//! | `v` + `from`, `at`, `up`, `angle`, `hither`, `resolution` | camera and image size. `angle` spans the centres of the first and last pixel row, so vfov = 2·atan(tan(angle/2) / (1 − 1/height)); `hither` is ignored (rays start at the eye) |
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

use std::path::Path;

use crate::toolkit::scene::{
    CameraSpec, ImageSpec, Light, Material, MaterialId, Object, Shape, TraceSpec,
};
use crate::toolkit::{Color, Scene, SceneError, Vec3};

/// Reads and converts an NFF file.
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SceneError {
        file: name.clone(),
        line: None,
        column: None,
        path: String::new(),
        message: format!("cannot read the scene file: {e}"),
        source_line: None,
    })?;
    parse(&text, &name)
}

/// Parses NFF text; `file` names it in error messages.
pub fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    let mut reader = Reader {
        file,
        lines: text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .map(|(i, l)| Line::new(i + 1, l))
            .collect(),
        next: 0,
    };
    let mut nff = Nff::default();
    while let Some(line) = reader.next_line() {
        nff.entity(&line, &mut reader)?;
    }
    nff.into_scene(&reader)
}

/// One line of the file, cut into words.
#[derive(Debug, Clone)]
struct Line<'a> {
    number: usize,
    text: &'a str,
    /// Each word with its 1-based column.
    words: Vec<(usize, &'a str)>,
}

impl<'a> Line<'a> {
    fn new(number: usize, text: &'a str) -> Line<'a> {
        let text = text.split('#').next().unwrap_or("");
        let words = text
            .split_whitespace()
            .map(|w| (w.as_ptr() as usize - text.as_ptr() as usize + 1, w))
            .collect();
        Line {
            number,
            text,
            words,
        }
    }

    fn keyword(&self) -> &'a str {
        self.words[0].1
    }
}

/// The lines still to read, and the file's name for errors.
struct Reader<'a> {
    file: &'a str,
    lines: Vec<Line<'a>>,
    next: usize,
}

impl<'a> Reader<'a> {
    fn next_line(&mut self) -> Option<Line<'a>> {
        let line = self.lines.get(self.next).cloned();
        self.next += 1;
        line
    }

    /// The next line, which `what` needs.
    fn expect_line(&mut self, after: &Line, what: &str) -> Result<Line<'a>, SceneError> {
        self.next_line()
            .ok_or_else(|| self.error(after, 1, format!("the file ends, but {what} is missing")))
    }

    /// An error at a column of a line.
    fn error(&self, line: &Line, column: usize, message: impl Into<String>) -> SceneError {
        SceneError {
            file: self.file.to_owned(),
            line: Some(line.number as u32),
            column: Some(column as u32),
            path: String::new(),
            message: message.into(),
            source_line: Some(line.text.to_owned()),
        }
    }

    /// The `count` numbers after the keyword of `line` (exactly that many).
    fn numbers(&self, line: &Line, count: usize, form: &str) -> Result<Vec<f32>, SceneError> {
        self.numbers_from(line, 1, count..=count, form)
    }

    /// The numbers of `line` from word `skip` on, how many `counts` allows.
    fn numbers_from(
        &self,
        line: &Line,
        skip: usize,
        counts: std::ops::RangeInclusive<usize>,
        form: &str,
    ) -> Result<Vec<f32>, SceneError> {
        let words = &line.words[skip.min(line.words.len())..];
        if !counts.contains(&words.len()) {
            return Err(self.error(
                line,
                line.words.get(skip).map_or(line.text.len() + 1, |w| w.0),
                format!("expected `{form}`, found {} numbers", words.len()),
            ));
        }
        words
            .iter()
            .map(|&(column, word)| match word.parse::<f32>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(self.error(
                    line,
                    column,
                    format!("expected a finite number in `{form}`, found `{word}`"),
                )),
            })
            .collect()
    }
}

/// What has been read so far.
#[derive(Default)]
struct Nff {
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
            "v" => self.camera = Some(viewpoint(line, reader)?),
            "b" => self.background = color(reader, line, &reader.numbers(line, 3, "b r g b")?)?,
            "l" => self.light(line, reader)?,
            "f" => self.material(line, reader)?,
            "s" => {
                let n = reader.numbers(line, 4, "s x y z radius")?;
                if n[3] <= 0.0 {
                    return Err(reader.error(line, line.words[4].0, "the radius must be > 0"));
                }
                let shape = Shape::Sphere {
                    center: Vec3::new(n[0], n[1], n[2]),
                    radius: n[3],
                };
                self.add(line, reader, shape)?;
            }
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
                return Err(reader.error(line, line.words[i + 1].0, message));
            }
        }
        if shine <= 0.0 {
            return Err(reader.error(line, line.words[6].0, "Shine must be > 0"));
        }
        if t > 0.0 && ior <= 0.0 {
            let message = "a transparent material (T > 0) needs an index of refraction > 0";
            return Err(reader.error(line, line.words[8].0, message));
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

    /// A `p` or `pp` polygon, as the fan of triangles (v0, vi, vi+1).
    fn polygon(&mut self, line: &Line, reader: &mut Reader) -> Result<(), SceneError> {
        let smooth = line.keyword() == "pp";
        let form = if smooth { "pp count" } else { "p count" };
        let count = reader.numbers(line, 1, form)?[0];
        if count < 3.0 || count.fract() != 0.0 || count > 1e6 {
            let message =
                format!("a polygon has a whole number of corners, 3 or more; found {count}");
            return Err(reader.error(line, line.words[1].0, message));
        }
        let mut corners = Vec::with_capacity(count as usize);
        for i in 0..count as usize {
            let what = format!("corner {} of {count}", i + 1);
            let corner = reader.expect_line(line, &what)?;
            corners.push(polygon_corner(&corner, reader, smooth)?);
        }
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
            let end = Line::new(reader.lines.last().map_or(1, |l| l.number), "");
            return Err(reader.error(&end, 1, "the file has no viewpoint (a `v` entity)"));
        };
        // Equal shares of white for the lights without a colour.
        let share = 1.0 / self.lights.len().max(1) as f32;
        let lights = self
            .lights
            .iter()
            .map(|&(position, colour)| Light::Point {
                position,
                color: colour.unwrap_or(Color::splat(share)),
                // 1/r² falloff, calibrated to be 1 at the `at` point.
                intensity: position
                    .distance_squared(camera.look_at)
                    .max(f32::MIN_POSITIVE),
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
            trace: TraceSpec {
                max_depth: 5,
                min_weight: 0.001,
                effects: None,
            },
            materials: self.materials,
            lights,
            objects: self.objects,
        })
    }
}

/// The lines of a `v` entity: the camera and the image size.
fn viewpoint(line: &Line, reader: &mut Reader) -> Result<(CameraSpec, u32, u32), SceneError> {
    let mut values: [Option<Vec<f32>>; 6] = Default::default();
    let fields = ["from", "at", "up", "angle", "hither", "resolution"];
    let counts = [3, 3, 3, 1, 1, 2];
    for _ in 0..fields.len() {
        let next = reader.expect_line(line, "a line of the viewpoint")?;
        let Some(i) = fields.iter().position(|&f| f == next.keyword()) else {
            let message = format!(
                "expected a viewpoint line (from, at, up, angle, hither, resolution), found `{}`",
                next.keyword()
            );
            return Err(reader.error(&next, 1, message));
        };
        let form = format!("{} and {} numbers", fields[i], counts[i]);
        values[i] = Some(reader.numbers(&next, counts[i], &form)?);
    }
    let [
        Some(from),
        Some(at),
        Some(up),
        Some(angle),
        Some(_),
        Some(size),
    ] = values
    else {
        return Err(reader.error(
            line,
            1,
            "the viewpoint needs from, at, up, angle, hither and resolution",
        ));
    };
    let side = |x: f32| ((1.0..=16384.0).contains(&x) && x.fract() == 0.0).then_some(x as u32);
    let (Some(width), Some(height)) = (side(size[0]), side(size[1])) else {
        return Err(reader.error(
            line,
            1,
            "the resolution is two whole numbers from 1 to 16384",
        ));
    };
    let (eye, look_at, up) = (
        Vec3::from_slice(&from),
        Vec3::from_slice(&at),
        Vec3::from_slice(&up),
    );
    let view = look_at - eye;
    if view.length() == 0.0
        || up.length() == 0.0
        || view.cross(up).length() <= 1e-6 * view.length() * up.length()
    {
        return Err(reader.error(
            line,
            1,
            "from, at and up must give a view direction (at − from ≠ 0) not parallel to up",
        ));
    }
    if !(angle[0] > 0.0 && angle[0] < 180.0) {
        return Err(reader.error(
            line,
            1,
            format!(
                "the angle is in degrees, strictly between 0 and 180; found {}",
                angle[0]
            ),
        ));
    }
    // NFF's angle spans the centres of the first and the last pixel row;
    // raybook's vfov spans the image's edges, half a pixel further out.
    let half = (angle[0].to_radians() / 2.0).tan() / (1.0 - 1.0 / height as f32);
    let camera = CameraSpec {
        eye,
        look_at,
        up: up.normalize(),
        vfov_degrees: 2.0 * half.atan().to_degrees(),
    };
    Ok((camera, width, height))
}

/// A corner of a polygon: `x y z`, or `x y z nx ny nz` for a patch.
fn polygon_corner(line: &Line, reader: &Reader, smooth: bool) -> Result<(Vec3, Vec3), SceneError> {
    if !smooth {
        let n = reader.numbers_from(line, 0, 3..=3, "x y z")?;
        return Ok((Vec3::from_slice(&n), Vec3::ZERO));
    }
    let n = reader.numbers_from(line, 0, 6..=6, "x y z nx ny nz")?;
    let normal = Vec3::from_slice(&n[3..]);
    if normal.length() == 0.0 {
        return Err(reader.error(line, line.words[3].0, "a vertex normal must not be zero"));
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

/// Refuses triangles whose corners are (nearly) on a line, as scene files do:
/// |e1 × e2| ≤ 1e-6 |e1| |e2|.
fn has_area([a, b, c]: [Vec3; 3]) -> bool {
    let (e1, e2) = (b - a, c - a);
    e1.cross(e2).length() > 1e-6 * e1.length() * e2.length()
}

/// The scene `args` names, read as NFF if its name ends in `.nff` and as a
/// TOML scene otherwise, with the size overrides applied, and its name.
pub fn load_scene(
    args: &crate::toolkit::cli::RenderArgs,
    chapter: &crate::toolkit::cli::Chapter,
) -> Result<(Scene, String), SceneError> {
    match &args.scene {
        Some(path)
            if path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("nff")) =>
        {
            let scene = load(path)?;
            let width = args.width.unwrap_or(scene.image.width);
            let height = args.height.unwrap_or(scene.image.height);
            Ok((scene.with_size(width, height), path.display().to_string()))
        }
        _ => args.load_scene(chapter),
    }
}
