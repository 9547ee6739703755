//! The scene file as written: TOML, deserialised with serde into typed records,
//! then checked and turned into a [`Scene`].
//!
//! Two choices keep every error pointing at the right place:
//!
//! * Each number, vector and colour is a small type whose `Deserialize` checks
//!   it (finite, positive, three components, ...). An error found there carries
//!   toml's span (the line) and serde_path_to_error's path (`objects[3].radius`).
//! * Objects and lights are *flat* records (`type` plus every field any kind
//!   may have) rather than serde's internally tagged enums, which buffer a
//!   table before choosing the variant and so lose the field's path and line.
//!   Turning a record into a [`Shape`] or [`Light`] then names the fields a
//!   kind needs and refuses the ones it does not take.

use std::collections::BTreeMap;
use std::ops::Range;

use glam::Vec3;
use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use toml::Spanned;

use super::{
    CameraSpec, Effect, ImageSpec, Light, Material, Object, Scene, SceneError, Shape, TraceSpec,
};

/// The largest image side we accept: beyond this a typo, not a picture.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Parses TOML text into a validated scene.
pub(super) fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    let toml_error = |path: &str, e: &toml::de::Error| {
        SceneError::at(file, text, e.span(), path, e.message().trim_end())
    };
    let deserializer = toml::Deserializer::parse(text).map_err(|e| toml_error("", &e))?;
    let scene: SceneFile = serde_path_to_error::deserialize(deserializer).map_err(|e| {
        // `Spanned` shows up in serde's path as a private field: leave it out.
        let path = e
            .path()
            .to_string()
            .replace(".$__serde_spanned_private_value", "");
        let path = if path == "." { String::new() } else { path };
        toml_error(&path, e.inner())
    })?;
    scene.validate(&Checker { file, text })
}

// ---------------------------------------------------------------------------
// The records, one per TOML table.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    camera: CameraFile,
    image: ImageFile,
    #[serde(default)]
    trace: TraceFile,
    #[serde(default)]
    materials: BTreeMap<String, MaterialFile>,
    #[serde(default)]
    lights: Vec<Spanned<LightFile>>,
    #[serde(default)]
    objects: Vec<Spanned<ObjectFile>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraFile {
    eye: Xyz,
    look_at: Spanned<Xyz>,
    up: Spanned<Direction>,
    vfov: FieldOfView,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ImageFile {
    width: Side,
    height: Side,
    #[serde(default)]
    background: Rgb,
    #[serde(default)]
    samples: Samples,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TraceFile {
    #[serde(default = "default_max_depth")]
    max_depth: Depth,
    #[serde(default = "default_min_weight")]
    min_weight: Unit,
    effects: Option<Vec<Effect>>,
}

fn default_max_depth() -> Depth {
    Depth(5)
}

fn default_min_weight() -> Unit {
    Unit(0.001)
}

impl Default for TraceFile {
    fn default() -> Self {
        TraceFile {
            max_depth: default_max_depth(),
            min_weight: default_min_weight(),
            effects: None,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MaterialFile {
    #[serde(default = "default_albedo")]
    color: Albedo,
    #[serde(default)]
    reflectance: Albedo,
    #[serde(default)]
    specular: Unit,
    #[serde(default = "default_shininess")]
    shininess: Positive,
    #[serde(default)]
    transparency: Unit,
    #[serde(default = "default_ior")]
    ior: Positive,
    #[serde(default)]
    fresnel: bool,
}

fn default_albedo() -> Albedo {
    Albedo(Vec3::splat(0.8))
}

fn default_shininess() -> Positive {
    Positive(50.0)
}

fn default_ior() -> Positive {
    Positive(1.0)
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
enum LightKind {
    Ambient,
    Point,
    Spot,
}

/// Every field any light may have; [`LightFile::into_light`] picks its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightFile {
    #[serde(rename = "type")]
    kind: LightKind,
    color: Option<Rgb>,
    intensity: Option<NonNegative>,
    position: Option<Xyz>,
    direction: Option<Direction>,
    inner_angle: Option<HalfAngle>,
    outer_angle: Option<HalfAngle>,
    shadows: Option<bool>,
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
enum ObjectKind {
    Sphere,
    Plane,
    Triangle,
    Mesh,
}

/// Every field any object may have; [`ObjectFile::shape`] picks its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectFile {
    #[serde(rename = "type")]
    kind: ObjectKind,
    center: Option<Xyz>,
    radius: Option<Positive>,
    normal: Option<Direction>,
    offset: Option<Number>,
    vertices: Option<Corners>,
    /// A mesh's OBJ file, relative to the scene file.
    path: Option<Spanned<String>>,
    material: Spanned<String>,
    shadows: Option<bool>,
}

// ---------------------------------------------------------------------------
// From records to the scene.

/// Makes errors for places in one file.
struct Checker<'a> {
    file: &'a str,
    text: &'a str,
}

impl Checker<'_> {
    fn error(&self, span: Range<usize>, path: String, message: impl Into<String>) -> SceneError {
        SceneError::at(self.file, self.text, Some(span), &path, message)
    }
}

impl SceneFile {
    fn validate(self, check: &Checker) -> Result<Scene, SceneError> {
        let camera = self.camera.validate(check)?;
        let names: Vec<&String> = self.materials.keys().collect();
        let objects = self
            .objects
            .iter()
            .enumerate()
            .map(|(i, object)| object_from_record(object, i, &names, check))
            .collect::<Result<Vec<_>, _>>()?
            .concat();
        let lights = self
            .lights
            .iter()
            .enumerate()
            .map(|(i, light)| light_from_record(light, i, check))
            .collect::<Result<Vec<_>, _>>()?;
        let materials = self
            .materials
            .into_iter()
            .map(|(name, m)| m.into_material(name))
            .collect();
        Ok(Scene {
            camera,
            image: ImageSpec {
                width: self.image.width.0,
                height: self.image.height.0,
                background: self.image.background.0,
                samples: self.image.samples.0,
            },
            trace: TraceSpec {
                max_depth: self.trace.max_depth.0,
                min_weight: self.trace.min_weight.0,
                effects: self.trace.effects,
            },
            materials,
            lights,
            objects,
        })
    }
}

impl CameraFile {
    fn validate(self, check: &Checker) -> Result<CameraSpec, SceneError> {
        let eye = self.eye.0;
        let look_at = self.look_at.get_ref().0;
        let up = self.up.get_ref().0;
        let view = look_at - eye;
        if view.length_squared() == 0.0 {
            return Err(check.error(
                self.look_at.span(),
                "camera.look_at".into(),
                "look_at equals eye, so the camera looks nowhere; move look_at away from eye",
            ));
        }
        if nearly_parallel(view, up) {
            return Err(check.error(
                self.up.span(),
                "camera.up".into(),
                "up is parallel to the view direction (look_at - eye), so the image has no \
                 'up'; choose a vector across the view, such as [0, 1, 0] for a level camera",
            ));
        }
        Ok(CameraSpec {
            eye,
            look_at,
            up,
            vfov_degrees: self.vfov.0,
        })
    }
}

/// True when a and b (non-zero) point along one line: |a × b| ≤ 1e-6 |a| |b|.
fn nearly_parallel(a: Vec3, b: Vec3) -> bool {
    a.cross(b).length() <= 1e-6 * a.length() * b.length()
}

impl MaterialFile {
    fn into_material(self, name: String) -> Material {
        Material {
            name,
            color: self.color.0,
            reflectance: self.reflectance.0,
            specular: self.specular.0,
            shininess: self.shininess.0,
            transparency: self.transparency.0,
            ior: self.ior.0,
            fresnel: self.fresnel,
        }
    }
}

/// One object or light record: its place in the file, for errors.
struct Record<'a> {
    span: Range<usize>,
    path: String,
    check: &'a Checker<'a>,
}

impl Record<'_> {
    /// The value of a field this kind needs, or an error naming it.
    fn need<T>(&self, value: Option<T>, field: &str, kind: &str) -> Result<T, SceneError> {
        value.ok_or_else(|| {
            let message = format!("missing field `{field}`: a {kind} needs it");
            self.check
                .error(self.span.clone(), self.path.clone(), message)
        })
    }

    /// Refuses the first field that is set but that this kind does not take.
    fn refuse(&self, fields: &[(&str, bool)], kind: &str, takes: &str) -> Result<(), SceneError> {
        match fields.iter().find(|(_, is_set)| *is_set) {
            Some((field, _)) => Err(self.check.error(
                self.span.clone(),
                format!("{}.{field}", self.path),
                format!("a {kind} has no `{field}`; a {kind} takes {takes}"),
            )),
            None => Ok(()),
        }
    }
}

fn object_from_record(
    record: &Spanned<ObjectFile>,
    index: usize,
    materials: &[&String],
    check: &Checker,
) -> Result<Vec<Object>, SceneError> {
    let path = format!("objects[{index}]");
    let r = Record {
        span: record.span(),
        path: path.clone(),
        check,
    };
    let o = record.get_ref();
    let shapes = match o.kind {
        ObjectKind::Sphere => {
            let extra = [
                ("normal", o.normal.is_some()),
                ("offset", o.offset.is_some()),
                ("vertices", o.vertices.is_some()),
                ("path", o.path.is_some()),
            ];
            let takes = "center, radius, material, shadows";
            r.refuse(&extra, "sphere", takes)?;
            vec![Shape::Sphere {
                center: r.need(o.center.map(|c| c.0), "center", "sphere")?,
                radius: r.need(o.radius.map(|r| r.0), "radius", "sphere")?,
            }]
        }
        ObjectKind::Plane => {
            let extra = [
                ("center", o.center.is_some()),
                ("radius", o.radius.is_some()),
                ("vertices", o.vertices.is_some()),
                ("path", o.path.is_some()),
            ];
            let takes = "normal, offset, material, shadows";
            r.refuse(&extra, "plane", takes)?;
            vec![plane(
                r.need(o.normal, "normal", "plane")?,
                r.need(o.offset.map(|d| d.0), "offset", "plane")?,
            )]
        }
        ObjectKind::Triangle => {
            let extra = [
                ("center", o.center.is_some()),
                ("radius", o.radius.is_some()),
                ("normal", o.normal.is_some()),
                ("offset", o.offset.is_some()),
                ("path", o.path.is_some()),
            ];
            let takes = "vertices, material, shadows";
            r.refuse(&extra, "triangle", takes)?;
            vec![Shape::Triangle {
                vertices: r.need(o.vertices.map(|v| v.0), "vertices", "triangle")?,
            }]
        }
        ObjectKind::Mesh => {
            let extra = [
                ("center", o.center.is_some()),
                ("radius", o.radius.is_some()),
                ("normal", o.normal.is_some()),
                ("offset", o.offset.is_some()),
                ("vertices", o.vertices.is_some()),
            ];
            r.refuse(&extra, "mesh", "path, material, shadows")?;
            let file = r.need(o.path.as_ref(), "path", "mesh")?;
            mesh(file, &format!("{path}.path"), check)?
        }
    };
    let name = o.material.get_ref();
    let Some(material) = materials.iter().position(|m| *m == name) else {
        let known = if materials.is_empty() {
            "none is defined: add a [materials.NAME] table".to_owned()
        } else {
            let list: Vec<&str> = materials.iter().map(|m| m.as_str()).collect();
            format!("known materials: {}", list.join(", "))
        };
        return Err(check.error(
            o.material.span(),
            format!("{path}.material"),
            format!("unknown material `{name}`; {known}"),
        ));
    };
    let shadows = o.shadows.unwrap_or(true);
    let object = |shape| Object {
        shape,
        material,
        shadows,
    };
    Ok(shapes.into_iter().map(object).collect())
}

/// The triangles of a mesh's OBJ file, found relative to the scene file.
fn mesh(file: &Spanned<String>, path: &str, check: &Checker) -> Result<Vec<Shape>, SceneError> {
    let scene_dir = std::path::Path::new(check.file).parent();
    let obj = scene_dir.map_or_else(|| file.get_ref().into(), |d| d.join(file.get_ref()));
    super::mesh::load_obj(&obj).map_err(|message| {
        let message = format!("{message} ({})", obj.display());
        check.error(file.span(), path.to_owned(), message)
    })
}

/// The plane n·x + d = 0 with n scaled to unit length (and d with it: the same plane).
fn plane(normal: Direction, offset: f32) -> Shape {
    Shape::Plane {
        normal: normal.0,
        offset: offset / normal.1,
    }
}

fn light_from_record(
    record: &Spanned<LightFile>,
    index: usize,
    check: &Checker,
) -> Result<Light, SceneError> {
    let path = format!("lights[{index}]");
    let r = Record {
        span: record.span(),
        path: path.clone(),
        check,
    };
    let l = record.get_ref();
    let color = l.color.map_or(Vec3::ONE, |c| c.0);
    let intensity = l.intensity.map_or(1.0, |i| i.0);
    let shadows = l.shadows.unwrap_or(true);
    let light = match l.kind {
        LightKind::Ambient => {
            let extra = [
                ("intensity", l.intensity.is_some()),
                ("position", l.position.is_some()),
                ("direction", l.direction.is_some()),
                ("inner_angle", l.inner_angle.is_some()),
                ("outer_angle", l.outer_angle.is_some()),
                ("shadows", l.shadows.is_some()),
            ];
            r.refuse(&extra, "ambient light", "color")?;
            Light::Ambient { color }
        }
        LightKind::Point => {
            let extra = [
                ("direction", l.direction.is_some()),
                ("inner_angle", l.inner_angle.is_some()),
                ("outer_angle", l.outer_angle.is_some()),
            ];
            let takes = "position, color, intensity, shadows";
            r.refuse(&extra, "point light", takes)?;
            Light::Point {
                position: r.need(l.position.map(|p| p.0), "position", "point light")?,
                color,
                intensity,
                shadows,
            }
        }
        LightKind::Spot => {
            let inner = r.need(l.inner_angle.map(|a| a.0), "inner_angle", "spot light")?;
            let outer = r.need(l.outer_angle.map(|a| a.0), "outer_angle", "spot light")?;
            if inner > outer {
                return Err(check.error(
                    r.span,
                    format!("{path}.inner_angle"),
                    format!(
                        "inner_angle ({inner}°) is wider than outer_angle ({outer}°); \
                         the smooth edge runs from inner out to outer, so inner ≤ outer"
                    ),
                ));
            }
            Light::Spot {
                position: r.need(l.position.map(|p| p.0), "position", "spot light")?,
                direction: r.need(l.direction.map(|d| d.0), "direction", "spot light")?,
                color,
                intensity,
                inner_degrees: inner,
                outer_degrees: outer,
                shadows,
            }
        }
    };
    Ok(light)
}

// ---------------------------------------------------------------------------
// Values that check themselves while they are read.

/// Reads a TOML number (integer or float) as f32, refusing NaN, infinities and
/// values beyond f32's range.
fn number<'de, D: Deserializer<'de>>(d: D) -> Result<f32, D::Error> {
    let x = f64::deserialize(d)?;
    if !x.is_finite() {
        return Err(de::Error::custom(format!(
            "expected a finite number, found {x}"
        )));
    }
    if x.abs() > f32::MAX as f64 {
        return Err(de::Error::custom(format!(
            "{x:e} is too large for the tracer's f32 numbers (largest {:e})",
            f32::MAX
        )));
    }
    Ok(x as f32)
}

/// Any finite number.
#[derive(Clone, Copy)]
struct Number(f32);

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d).map(Number)
    }
}

/// A finite number > 0.
#[derive(Clone, Copy)]
struct Positive(f32);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if x <= 0.0 {
            return Err(de::Error::custom(format!(
                "must be greater than 0, found {x}"
            )));
        }
        Ok(Positive(x))
    }
}

/// A finite number ≥ 0.
#[derive(Clone, Copy)]
struct NonNegative(f32);

impl<'de> Deserialize<'de> for NonNegative {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if x < 0.0 {
            return Err(de::Error::custom(format!("must be 0 or more, found {x}")));
        }
        Ok(NonNegative(x))
    }
}

/// A weight in [0, 1].
#[derive(Clone, Copy, Default)]
struct Unit(f32);

impl<'de> Deserialize<'de> for Unit {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if !(0.0..=1.0).contains(&x) {
            return Err(de::Error::custom(format!(
                "must be between 0 and 1, found {x}"
            )));
        }
        Ok(Unit(x))
    }
}

/// A vertical field of view in degrees, strictly between 0 and 180.
#[derive(Clone, Copy)]
struct FieldOfView(f32);

impl<'de> Deserialize<'de> for FieldOfView {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if !(x > 0.0 && x < 180.0) {
            return Err(de::Error::custom(format!(
                "the field of view is in degrees, strictly between 0 and 180; found {x}"
            )));
        }
        Ok(FieldOfView(x))
    }
}

/// A spot light's half-angle in degrees, in [0, 90].
#[derive(Clone, Copy)]
struct HalfAngle(f32);

impl<'de> Deserialize<'de> for HalfAngle {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if !(0.0..=90.0).contains(&x) {
            return Err(de::Error::custom(format!(
                "a cone's half-angle is in degrees, from 0 to 90; found {x}"
            )));
        }
        Ok(HalfAngle(x))
    }
}

/// An image side in pixels: 1 to [`MAX_IMAGE_SIDE`].
#[derive(Clone, Copy)]
struct Side(u32);

impl<'de> Deserialize<'de> for Side {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = i64::deserialize(d)?;
        if !(1..=MAX_IMAGE_SIDE as i64).contains(&x) {
            return Err(de::Error::custom(format!(
                "an image side is a whole number of pixels from 1 to {MAX_IMAGE_SIDE}; found {x}"
            )));
        }
        Ok(Side(x as u32))
    }
}

/// Rays per pixel: a square number (1, 4, 9, 16, ...) up to 1024, so that
/// a pixel splits into a √N × √N grid of cells, one ray in each.
#[derive(Clone, Copy)]
struct Samples(u32);

impl Default for Samples {
    fn default() -> Self {
        Samples(1)
    }
}

impl<'de> Deserialize<'de> for Samples {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let n = i64::deserialize(d)?;
        match u32::try_from(n) {
            Ok(n) if is_square_sample_count(n) => Ok(Samples(n)),
            _ => Err(de::Error::custom(format!(
                "samples per pixel must be a square number from 1 to 1024 \
                 (1, 4, 9, 16, ...); found {n}"
            ))),
        }
    }
}

/// Is `n` one of 1, 4, 9, ..., 1024?
pub fn is_square_sample_count(n: u32) -> bool {
    let side = (n as f64).sqrt().round() as u32;
    (1..=1024).contains(&n) && side * side == n
}

/// A recursion depth: 0 to 64.
#[derive(Clone, Copy)]
struct Depth(u32);

impl<'de> Deserialize<'de> for Depth {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = i64::deserialize(d)?;
        if !(0..=64).contains(&x) {
            return Err(de::Error::custom(format!(
                "max_depth counts bounces, from 0 to 64; found {x}"
            )));
        }
        Ok(Depth(x as u32))
    }
}

/// Reads exactly three finite numbers `[x, y, z]`: fewer or more is an error,
/// never silently cut.
fn three_numbers<'de, D: Deserializer<'de>>(d: D) -> Result<Vec3, D::Error> {
    struct Three;
    impl<'de> Visitor<'de> for Three {
        type Value = Vec3;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an array of three numbers [x, y, z]")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec3, A::Error> {
            let mut values = Vec::with_capacity(3);
            while let Some(Number(x)) = seq.next_element()? {
                values.push(x);
            }
            match values[..] {
                [x, y, z] => Ok(Vec3::new(x, y, z)),
                _ => Err(de::Error::custom(format!(
                    "expected three numbers [x, y, z], found {}",
                    values.len()
                ))),
            }
        }
    }
    d.deserialize_seq(Three)
}

/// A point or vector `[x, y, z]`.
#[derive(Clone, Copy)]
struct Xyz(Vec3);

impl<'de> Deserialize<'de> for Xyz {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        three_numbers(d).map(Xyz)
    }
}

/// A direction: a non-zero vector, kept as its unit vector and its length.
#[derive(Clone, Copy)]
struct Direction(Vec3, f32);

impl<'de> Deserialize<'de> for Direction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = three_numbers(d)?;
        let length = v.length();
        if length == 0.0 || !length.is_finite() {
            return Err(de::Error::custom(
                "a direction must have non-zero length (such as [0, 1, 0]); found [0, 0, 0]",
            ));
        }
        Ok(Direction(v / length, length))
    }
}

/// A light's colour: three numbers ≥ 0 (brighter than 1 is allowed).
#[derive(Clone, Copy, Default)]
struct Rgb(Vec3);

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = three_numbers(d)?;
        if c.min_element() < 0.0 {
            return Err(de::Error::custom(format!(
                "colour components must be 0 or more, found {c}"
            )));
        }
        Ok(Rgb(c))
    }
}

/// A surface weight per channel: three numbers in [0, 1].
#[derive(Clone, Copy, Default)]
struct Albedo(Vec3);

impl<'de> Deserialize<'de> for Albedo {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = three_numbers(d)?;
        if c.min_element() < 0.0 || c.max_element() > 1.0 {
            return Err(de::Error::custom(format!(
                "a surface reflects between 0 and 1 of each channel, found {c}"
            )));
        }
        Ok(Albedo(c))
    }
}

/// A triangle's three corners, refused when they are (nearly) collinear:
/// |e1 × e2| ≤ 1e-6 |e1| |e2| means the angle between the edges is below 1e-6
/// radians, and such a triangle has no usable normal.
#[derive(Clone, Copy)]
struct Corners([Vec3; 3]);

impl<'de> Deserialize<'de> for Corners {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let corners: Vec<Xyz> = Vec::deserialize(d)?;
        let [a, b, c] = corners[..] else {
            return Err(de::Error::custom(format!(
                "a triangle has three vertices [[x, y, z], [x, y, z], [x, y, z]], found {}",
                corners.len()
            )));
        };
        let (e1, e2) = (b.0 - a.0, c.0 - a.0);
        if e1.length() == 0.0 || e2.length() == 0.0 || nearly_parallel(e1, e2) {
            return Err(de::Error::custom(
                "the triangle has zero area (two vertices coincide or all three lie on a line)",
            ));
        }
        Ok(Corners([a.0, b.0, c.0]))
    }
}
