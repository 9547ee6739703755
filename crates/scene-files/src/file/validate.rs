//! From the records to the runtime [`Scene`]: the checks that need more than
//! one value (the camera's points, a spot's two angles), the fields each kind
//! of object and light needs or refuses, material names and mesh files.

use std::ops::Range;

use toml::Spanned;

use super::MeshBudget;
use super::records::{
    CameraFile, LightFile, LightKind, MaterialFile, ObjectFile, ObjectKind, SceneFile,
};
use crate::Color;
use crate::rules::{self, CameraWords};
use crate::{
    CameraSpec, ImageSpec, Light, Material, MaterialId, Object, Scene, SceneError, Shape, TraceSpec,
};

/// Makes errors for places in one file, from spans in a part of it parsed
/// on its own (or in all of it).
pub(super) struct Checker<'a> {
    pub file: &'a str,
    /// The whole file's text.
    pub text: &'a str,
    /// The pieces the parsed text was put together from: where each starts
    /// in the parsed text and in the file, in order, the first at 0.
    pub pieces: Vec<(usize, usize)>,
    /// What the meshes may take of the memory (`None`: no limit).
    pub budget: Option<&'a MeshBudget>,
}

impl<'a> Checker<'a> {
    /// For text that is all of the file.
    pub fn whole(file: &'a str, text: &'a str) -> Self {
        Checker::from(file, text, 0)
    }

    /// For the file's text from `start` on.
    pub fn from(file: &'a str, text: &'a str, start: usize) -> Self {
        let pieces = vec![(0, start)];
        Checker {
            file,
            text,
            pieces,
            budget: None,
        }
    }

    /// The same checker, its meshes taking from `budget`.
    pub fn within(self, budget: Option<&'a MeshBudget>) -> Self {
        Checker { budget, ..self }
    }

    /// For the file's `ranges` put together, in order. No ranges at all (a
    /// file of nothing but `[[objects]]` tables has an empty head) stand for
    /// the empty text at the file's start, so that an error there, such as
    /// the missing camera, points at its first line.
    pub fn of_ranges(file: &'a str, text: &'a str, ranges: &[Range<usize>]) -> Self {
        let mut parsed = 0;
        let mut pieces: Vec<(usize, usize)> = (ranges.iter())
            .map(|range| {
                parsed += range.len();
                (parsed - range.len(), range.start)
            })
            .collect();
        if pieces.is_empty() {
            pieces.push((0, 0));
        }
        Checker {
            file,
            text,
            pieces,
            budget: None,
        }
    }

    /// The offset in the file of an offset in the parsed text.
    fn in_file(&self, offset: usize) -> usize {
        let piece = self.pieces.partition_point(|&(start, _)| start <= offset);
        let (parsed, file) = self.pieces[piece.saturating_sub(1)];
        file + offset - parsed
    }

    /// An error at a span of the parsed text, if it has one.
    pub fn error_at(
        &self,
        span: Option<Range<usize>>,
        path: &str,
        message: impl Into<String>,
    ) -> SceneError {
        let span = span.map(|s| self.in_file(s.start)..self.in_file(s.end));
        SceneError::at(self.file, self.text, span, path, message)
    }

    fn error(&self, span: Range<usize>, path: String, message: impl Into<String>) -> SceneError {
        self.error_at(Some(span), &path, message)
    }
}

impl SceneFile {
    pub(super) fn validate(self, check: &Checker) -> Result<Scene, SceneError> {
        let camera = self.camera.validate(check)?;
        let names: Vec<&String> = self.materials.keys().collect();
        let objects = objects_from_records(&self.objects, 0, &names, check)?;
        let lights = (self.lights.iter().enumerate())
            .map(|(i, light)| light_from_record(light, i, check))
            .collect::<Result<Vec<_>, _>>()?;
        let materials = (self.materials.into_iter())
            .map(|(name, m)| m.into_material(name))
            .collect();
        Ok(Scene {
            camera,
            image: ImageSpec {
                width: self.image.width.0,
                height: self.image.height.0,
                background: self.image.background.0,
                samples: self.image.samples.0,
                seed: None,
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

/// The camera's fields as the TOML file names them.
const CAMERA_WORDS: CameraWords = CameraWords {
    eye: "eye",
    look_at: "look_at",
    up: "up",
    level_up: "[0, 1, 0]",
};

impl CameraFile {
    fn validate(self, check: &Checker) -> Result<CameraSpec, SceneError> {
        let (eye, look_at, up) = (self.eye.0, self.look_at.get_ref().0, self.up.get_ref().0);
        rules::camera(eye, look_at, up, self.vfov.0).map_err(|problem| {
            let (span, field) = match problem {
                rules::CameraProblem::LooksNowhere => (self.look_at.span(), "look_at"),
                rules::CameraProblem::UpAlongView => (self.up.span(), "up"),
            };
            let message = problem.message(&CAMERA_WORDS);
            check.error(span, format!("camera.{field}"), message)
        })
    }
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

    /// Refuses the first field that is set but is not one this kind `takes`.
    fn refuse(&self, set: &[(&str, bool)], kind: &str, takes: &[&str]) -> Result<(), SceneError> {
        let extra = set.iter().find(|(f, is_set)| *is_set && !takes.contains(f));
        match extra {
            Some((field, _)) => Err(self.check.error(
                self.span.clone(),
                format!("{}.{field}", self.path),
                format!(
                    "a {kind} has no `{field}`; a {kind} takes {}",
                    takes.join(", ")
                ),
            )),
            None => Ok(()),
        }
    }
}

/// The objects of `records`, the first of which is `objects[first]` of the file.
pub(super) fn objects_from_records(
    records: &[Spanned<ObjectFile>],
    first: usize,
    materials: &[&String],
    check: &Checker,
) -> Result<Vec<Object>, SceneError> {
    let mut objects = Vec::with_capacity(records.len());
    for (i, record) in records.iter().enumerate() {
        objects.extend(object_from_record(record, first + i, materials, check)?);
    }
    Ok(objects)
}

fn object_from_record(
    record: &Spanned<ObjectFile>,
    index: usize,
    materials: &[&String],
    check: &Checker,
) -> Result<Vec<Object>, SceneError> {
    let r = Record {
        span: record.span(),
        path: format!("objects[{index}]"),
        check,
    };
    let o = record.get_ref();
    let shapes = match o.kind {
        ObjectKind::Sphere => vec![sphere(o, &r)?],
        ObjectKind::Plane => vec![plane(o, &r)?],
        ObjectKind::Triangle => vec![triangle(o, &r)?],
        ObjectKind::Mesh => mesh(o, &r)?,
        ObjectKind::Cone => vec![cone(o, &r)?],
    };
    let material = material_id(&o.material, materials, &r)?;
    let shadows = o.shadows.unwrap_or(true);
    let object = |shape| Object {
        shape,
        material,
        shadows,
    };
    Ok(shapes.into_iter().map(object).collect())
}

fn sphere(o: &ObjectFile, r: &Record) -> Result<Shape, SceneError> {
    let takes = ["center", "radius", "material", "shadows"];
    r.refuse(&o.fields_set(), "sphere", &takes)?;
    Ok(Shape::Sphere {
        center: r.need(o.center.map(|c| c.0), "center", "sphere")?,
        radius: r.need(o.radius.map(|r| r.0), "radius", "sphere")?,
    })
}

/// The plane n·x + d = 0 with n scaled to unit length (and d with it: the same plane).
fn plane(o: &ObjectFile, r: &Record) -> Result<Shape, SceneError> {
    let takes = ["normal", "offset", "material", "shadows"];
    r.refuse(&o.fields_set(), "plane", &takes)?;
    let normal = r.need(o.normal, "normal", "plane")?;
    let offset = r.need(o.offset.map(|d| d.0), "offset", "plane")?;
    Ok(Shape::Plane {
        normal: normal.0,
        offset: offset / normal.1,
    })
}

fn triangle(o: &ObjectFile, r: &Record) -> Result<Shape, SceneError> {
    let takes = ["vertices", "material", "shadows"];
    r.refuse(&o.fields_set(), "triangle", &takes)?;
    Ok(Shape::Triangle {
        vertices: r.need(o.vertices.map(|v| v.0), "vertices", "triangle")?,
    })
}

/// A cone or cylinder without end caps, by the rules NFF's `c` obeys too.
fn cone(o: &ObjectFile, r: &Record) -> Result<Shape, SceneError> {
    let takes = [
        "base",
        "base_radius",
        "apex",
        "apex_radius",
        "material",
        "shadows",
    ];
    r.refuse(&o.fields_set(), "cone", &takes)?;
    let base = r.need(o.base.map(|p| p.0), "base", "cone")?;
    let base_radius = r.need(o.base_radius.map(|x| x.0), "base_radius", "cone")?;
    let apex = r.need(o.apex.map(|p| p.0), "apex", "cone")?;
    let apex_radius = r.need(o.apex_radius.map(|x| x.0), "apex_radius", "cone")?;
    rules::cone(base, base_radius, apex, apex_radius)
        .map_err(|message| r.check.error(r.span.clone(), r.path.clone(), message))?;
    Ok(Shape::Cone {
        base,
        base_radius,
        apex,
        apex_radius,
        inside_out: false,
    })
}

/// The triangles of a mesh's OBJ file, found relative to the scene file.
/// An error in the OBJ file (its file, line and column, what is wrong)
/// becomes the message of an error at the scene's `path`; so do the
/// warnings, which are printed.
fn mesh(o: &ObjectFile, r: &Record) -> Result<Vec<Shape>, SceneError> {
    r.refuse(&o.fields_set(), "mesh", &["path", "material", "shadows"])?;
    let file = r.need(o.path.as_ref(), "path", "mesh")?;
    let scene_dir = std::path::Path::new(r.check.file).parent();
    let obj = scene_dir.map_or_else(|| file.get_ref().into(), |d| d.join(file.get_ref()));
    let at = |message: String| {
        r.check
            .error(file.span(), format!("{}.path", r.path), message)
    };
    let mesh = crate::obj::load(&obj, r.check.budget).map_err(|e| at(e.headline()))?;
    for warning in mesh.warnings {
        eprintln!("warning: {}", at(warning).headline());
    }
    Ok(mesh.shapes)
}

/// The index of the material an object names, or an error listing the known ones.
fn material_id(
    name: &Spanned<String>,
    materials: &[&String],
    r: &Record,
) -> Result<MaterialId, SceneError> {
    let wanted = name.get_ref();
    materials.iter().position(|m| *m == wanted).ok_or_else(|| {
        let known = if materials.is_empty() {
            "none is defined: add a [materials.NAME] table".to_owned()
        } else {
            let list: Vec<&str> = materials.iter().map(|m| m.as_str()).collect();
            format!("known materials: {}", list.join(", "))
        };
        r.check.error(
            name.span(),
            format!("{}.material", r.path),
            format!("unknown material `{wanted}`; {known}"),
        )
    })
}

fn light_from_record(
    record: &Spanned<LightFile>,
    index: usize,
    check: &Checker,
) -> Result<Light, SceneError> {
    let r = Record {
        span: record.span(),
        path: format!("lights[{index}]"),
        check,
    };
    let l = record.get_ref();
    match l.kind {
        LightKind::Ambient => ambient_light(l, &r),
        LightKind::Point => point_light(l, &r),
        LightKind::Spot => spot_light(l, &r),
    }
}

/// A light's colour: white unless it says.
fn color(l: &LightFile) -> Color {
    l.color.map_or(Color::ONE, |c| c.0)
}

/// A light's intensity: 1 unless it says.
fn intensity(l: &LightFile) -> f32 {
    l.intensity.map_or(1.0, |i| i.0)
}

fn ambient_light(l: &LightFile, r: &Record) -> Result<Light, SceneError> {
    r.refuse(&l.fields_set(), "ambient light", &["color"])?;
    Ok(Light::Ambient { color: color(l) })
}

fn point_light(l: &LightFile, r: &Record) -> Result<Light, SceneError> {
    let takes = ["position", "color", "intensity", "shadows", "falloff"];
    r.refuse(&l.fields_set(), "point light", &takes)?;
    Ok(Light::Point {
        position: r.need(l.position.map(|p| p.0), "position", "point light")?,
        color: color(l),
        intensity: intensity(l),
        shadows: l.shadows.unwrap_or(true),
        falloff: l.falloff.unwrap_or_default(),
    })
}

fn spot_light(l: &LightFile, r: &Record) -> Result<Light, SceneError> {
    let inner = r.need(l.inner_angle.map(|a| a.0), "inner_angle", "spot light")?;
    let outer = r.need(l.outer_angle.map(|a| a.0), "outer_angle", "spot light")?;
    if inner > outer {
        return Err(r.check.error(
            r.span.clone(),
            format!("{}.inner_angle", r.path),
            format!(
                "inner_angle ({inner}°) is wider than outer_angle ({outer}°); \
                 the smooth edge runs from inner out to outer, so inner ≤ outer"
            ),
        ));
    }
    Ok(Light::Spot {
        position: r.need(l.position.map(|p| p.0), "position", "spot light")?,
        direction: r.need(l.direction.map(|d| d.0), "direction", "spot light")?,
        color: color(l),
        intensity: intensity(l),
        inner_degrees: inner,
        outer_degrees: outer,
        shadows: l.shadows.unwrap_or(true),
    })
}
