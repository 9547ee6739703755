//! The records, one per TOML table, as serde reads them: strict (no unknown
//! field passes) and typed with the self-checking values of `values.rs`.
//!
//! Objects and lights are *flat* records (`type` plus every field any kind
//! may have) rather than serde's internally tagged enums, which buffer a
//! table before choosing the variant and so lose the field's path and line.
//! `validate.rs` then names the fields a kind needs and refuses the ones it
//! does not take.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use super::values::{
    Albedo, Corners, Depth, Direction, FieldOfView, Fraction, HalfAngle, NonNegative, Number,
    Positive, Rgb, Samples, Side, Xyz,
};
use crate::Color;
use crate::{Effect, Falloff, TraceSpec};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    pub camera: CameraFile,
    pub image: ImageFile,
    #[serde(default)]
    pub trace: TraceFile,
    #[serde(default)]
    pub materials: BTreeMap<String, MaterialFile>,
    #[serde(default)]
    pub lights: Vec<Spanned<LightFile>>,
    #[serde(default)]
    pub objects: Vec<Spanned<ObjectFile>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CameraFile {
    pub eye: Xyz,
    pub look_at: Spanned<Xyz>,
    pub up: Spanned<Direction>,
    pub vfov: FieldOfView,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ImageFile {
    pub width: Side,
    pub height: Side,
    #[serde(default)]
    pub background: Rgb,
    #[serde(default)]
    pub samples: Samples,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct TraceFile {
    #[serde(default = "default_max_depth")]
    pub max_depth: Depth,
    #[serde(default = "default_min_weight")]
    pub min_weight: Fraction,
    pub effects: Option<Vec<Effect>>,
}

fn default_max_depth() -> Depth {
    Depth(TraceSpec::default().max_depth)
}

fn default_min_weight() -> Fraction {
    Fraction(TraceSpec::default().min_weight)
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
pub(super) struct MaterialFile {
    #[serde(default = "default_albedo")]
    pub color: Albedo,
    #[serde(default)]
    pub reflectance: Albedo,
    #[serde(default)]
    pub specular: Fraction,
    #[serde(default = "default_shininess")]
    pub shininess: Positive,
    #[serde(default)]
    pub transparency: Fraction,
    #[serde(default = "default_ior")]
    pub ior: Positive,
    #[serde(default)]
    pub fresnel: bool,
}

fn default_albedo() -> Albedo {
    Albedo(Color::splat(0.8))
}

fn default_shininess() -> Positive {
    Positive(50.0)
}

fn default_ior() -> Positive {
    Positive(1.0)
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub(super) enum LightKind {
    Ambient,
    Point,
    Spot,
}

/// Every field any light may have; each kind picks its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct LightFile {
    #[serde(rename = "type")]
    pub kind: LightKind,
    pub color: Option<Rgb>,
    pub intensity: Option<NonNegative>,
    pub position: Option<Xyz>,
    pub direction: Option<Direction>,
    pub inner_angle: Option<HalfAngle>,
    pub outer_angle: Option<HalfAngle>,
    pub shadows: Option<bool>,
    pub falloff: Option<Falloff>,
}

impl LightFile {
    /// The optional fields in file order, and whether each is set.
    pub fn fields_set(&self) -> [(&'static str, bool); 8] {
        [
            ("color", self.color.is_some()),
            ("intensity", self.intensity.is_some()),
            ("position", self.position.is_some()),
            ("direction", self.direction.is_some()),
            ("inner_angle", self.inner_angle.is_some()),
            ("outer_angle", self.outer_angle.is_some()),
            ("shadows", self.shadows.is_some()),
            ("falloff", self.falloff.is_some()),
        ]
    }
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub(super) enum ObjectKind {
    Sphere,
    Plane,
    Triangle,
    Mesh,
    Cone,
}

/// Every field any object may have; each kind picks its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ObjectFile {
    #[serde(rename = "type")]
    pub kind: ObjectKind,
    pub center: Option<Xyz>,
    pub radius: Option<Positive>,
    pub normal: Option<Direction>,
    pub offset: Option<Number>,
    pub vertices: Option<Corners>,
    /// A mesh's OBJ file, relative to the scene file.
    pub path: Option<Spanned<String>>,
    /// A cone's ends: the centres of its end circles and their radii.
    pub base: Option<Xyz>,
    pub base_radius: Option<NonNegative>,
    pub apex: Option<Xyz>,
    pub apex_radius: Option<NonNegative>,
    pub material: Spanned<String>,
    pub shadows: Option<bool>,
}

impl ObjectFile {
    /// The optional fields of the shape in file order, and whether each is set.
    pub fn fields_set(&self) -> [(&'static str, bool); 10] {
        [
            ("center", self.center.is_some()),
            ("radius", self.radius.is_some()),
            ("normal", self.normal.is_some()),
            ("offset", self.offset.is_some()),
            ("vertices", self.vertices.is_some()),
            ("path", self.path.is_some()),
            ("base", self.base.is_some()),
            ("base_radius", self.base_radius.is_some()),
            ("apex", self.apex.is_some()),
            ("apex_radius", self.apex_radius.is_some()),
        ]
    }
}
