//! A pixel's ray tree: every ray a chapter traces for one pixel, what each
//! one hit, how the lights lit it and why its path ended, printed as an
//! indented tree (`--pixel X,Y`) or written as JSON (`--pixel X,Y --json`).
//!
//! The chapters fill in the tree, each in a thin `ray_tree.rs` that lets
//! [`record`] watch its own tracer at work; this module holds the rest: the
//! data model, which is also the JSON schema documented in
//! `book/appendix/ray-tree.md`, the nodes made from a chapter's values
//! (`nodes.rs`), the recorder and the tree built from its record
//! ([`record`]), the text printing (`text.rs`), the folds of the short
//! text tree (`fold.rs`) and the picture of the rays (`svg.rs`). Every vector and
//! colour is an array of three numbers, so that a tracer in any language
//! can write the same JSON and a student can compare the two trees.

use serde::{Deserialize, Serialize};

use ch00_toolkit::Vec3;
use scene_files::{Light, Shape};

mod fold;
mod nodes;
pub mod record;
mod svg;
mod text;
mod words;

pub use fold::{Fold, Folded, count_rays};
pub use nodes::{Arriving, HitFacts, Terms};
pub use svg::{to_svg, to_svg_noted};
pub use words::{num, vec3};

/// The whole tree of one pixel, as `--pixel X,Y --json` writes it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RayTree {
    /// The chapter's folder, such as `06-refraction`.
    pub chapter: String,
    /// The scene file (or the chapter's default scene).
    pub scene: String,
    /// The pixel, (x, y) from the top-left corner, counted from 0.
    pub pixel: [u32; 2],
    /// The picture's width and height.
    pub image: [u32; 2],
    /// The scene's rays per pixel. The tree follows one ray only, through
    /// the pixel's centre, whatever this is.
    pub samples: u32,
    /// What the chapter's tracer does and the limits it uses.
    pub tracer: TracerInfo,
    /// The ray from the eye through the pixel's centre, and all that follows it.
    pub primary: RayNode,
}

/// What a chapter's tracer does, so that a reader knows what is absent
/// from the tree because the chapter does not do it yet.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct TracerInfo {
    /// Does it find hits (chapter 2 on)?
    pub hits: bool,
    /// Does it light hits (chapter 3 on)?
    pub lights: bool,
    /// Does it trace shadow rays (chapter 4 on)?
    pub shadow_rays: bool,
    /// The scene's `max_depth`, if the tracer follows secondary rays (chapter 5 on).
    pub max_depth: Option<u32>,
    /// The weight threshold, if the tracer has one (chapter 7 on).
    pub min_weight: Option<f32>,
}

/// Which kind of ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RayKind {
    Primary,
    Reflection,
    Refraction,
}

/// Why a path ended at this ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum End {
    /// The ray hit nothing: the background is all it sees.
    NoHit,
    /// The ray was not traced: it would bounce more than `max_depth` times.
    MaxDepth,
    /// The ray was not traced: its path's weight is below `min_weight`, by
    /// chapter 7's weight criterion.
    WeightThreshold,
    /// The ray hit a surface that sends no secondary ray on (matte and opaque).
    NoSecondaryRays,
    /// The ray was not traced, and the tracer counted no criterion for it.
    NotTraced,
}

/// One ray and everything that follows from it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RayNode {
    pub kind: RayKind,
    /// Bounces from the eye: 0 for the primary ray.
    pub depth: u32,
    /// r0, where the ray starts.
    pub origin: [f32; 3],
    /// rd, its unit direction.
    pub direction: [f32; 3],
    /// The weight its colour gets in the colour of the hit it leaves (1 for the primary ray).
    pub weight: [f32; 3],
    /// The product of the weights from the eye to this ray, its own included.
    pub path_weight: [f32; 3],
    /// Was it traced? (false: a termination criterion stopped it, see `end`.)
    pub traced: bool,
    /// Why the path ends here, if it does.
    pub end: Option<End>,
    /// What it hit (absent if it hit nothing or was not traced).
    pub hit: Option<HitNode>,
    /// What each light of the scene adds at the hit, in the scene's order.
    pub lights: Vec<LightNode>,
    /// The hit's local light: the sum of what the lights add.
    pub local: Option<[f32; 3]>,
    /// How a transparent surface splits the light (chapter 6 on).
    pub refraction: Option<RefractionNode>,
    /// The rays that leave the hit, in the order the tracer follows them.
    pub secondary: Vec<RayNode>,
    /// The colour the ray brings back (absent if it was not traced).
    pub color: Option<[f32; 3]>,
}

impl RayNode {
    /// A ray that has not been followed yet: no hit, nothing seen.
    pub fn new(kind: RayKind, depth: u32, origin: Vec3, direction: Vec3) -> RayNode {
        RayNode {
            kind,
            depth,
            origin: origin.to_array(),
            direction: direction.to_array(),
            weight: [1.0; 3],
            path_weight: [1.0; 3],
            traced: true,
            end: None,
            hit: None,
            lights: Vec::new(),
            local: None,
            refraction: None,
            secondary: Vec::new(),
            color: None,
        }
    }
}

/// Which side of its surface a ray meets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// Against the surface's normal (d·n < 0): the outside of a sphere.
    Front,
    /// Along it (d·n > 0): the inside of a sphere, the back of a plane.
    Back,
}

/// An object of the scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ObjectRef {
    /// Its index, from 0 in the order of the scene's `[[objects]]`.
    pub object: usize,
    /// `sphere`, `plane`, `triangle`, `smooth_triangle` or `cone`.
    pub shape: String,
}

/// Where a ray hits a surface.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HitNode {
    pub object: usize,
    pub shape: String,
    /// The name of its material.
    pub material: String,
    /// The distance along the ray.
    pub t: f32,
    pub point: [f32; 3],
    /// The surface's unit normal as the shape defines it (outward for a sphere).
    pub normal: [f32; 3],
    /// The shading normal turned to face the ray: the n of n·l.
    pub facing_normal: [f32; 3],
    pub side: Side,
    /// For a sphere: both roots t₀ ≤ t₁ of the ray's quadratic (either may be
    /// negative, behind the ray's origin).
    pub roots: Option<[f32; 2]>,
}

/// What a light does at a hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LightStatus {
    /// Ambient light: albedo × its colour, from no direction, never blocked.
    Ambient,
    /// Outside a spot's cone (or exactly at the point): no light arrives.
    Dark,
    /// Behind the surface: n·l ≤ 0, it adds nothing and no shadow ray is traced.
    Behind,
    /// In front, but what it would add is zero (a black surface): no shadow ray.
    AddsNothing,
    /// Nothing blocks it: it adds its Lambert term (and highlight).
    Free,
    /// A shadow ray found an object between the surface and the light.
    Blocked,
}

/// One light at one hit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LightNode {
    /// Its index, from 0 in the order of the scene's `[[lights]]`.
    pub light: usize,
    /// `ambient`, `point` or `spot`.
    pub kind: String,
    pub status: LightStatus,
    /// l, the unit vector from the point towards the light (not for ambient light).
    pub direction: Option<[f32; 3]>,
    /// The distance to the light.
    pub distance: Option<f32>,
    /// n·l with the facing normal: the cosine of Lambert's law.
    pub n_dot_l: Option<f32>,
    /// Does the light cast shadows (`shadows = false` lights are free without a ray)?
    pub casts_shadows: Option<bool>,
    /// The shadow ray traced towards it, if one was.
    pub shadow_ray: Option<ShadowNode>,
    /// Lambert's term of this light (chapter 3's `lambert`).
    pub lambert: Option<[f32; 3]>,
    /// The Blinn–Phong highlight (chapter 5 on).
    pub highlight: Option<[f32; 3]>,
    /// What the light adds to the hit's local light.
    pub adds: [f32; 3],
}

/// A shadow ray: from just off the surface towards a light.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShadowNode {
    pub origin: [f32; 3],
    pub direction: [f32; 3],
    /// The light is at this t: only hits in (0, t_max) block it.
    pub t_max: f32,
    pub blocked: bool,
    /// The nearest shadow-casting object on the segment, if it is blocked.
    pub blocked_by: Option<ObjectRef>,
    /// Where that object is on the shadow ray.
    pub blocker_t: Option<f32>,
}

/// How a transparent surface shares a ray's light between the mirror ray
/// and the refracted ray (chapter 6).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RefractionNode {
    /// true: the ray goes into the object (d·n < 0 with the outward normal);
    /// false: it leaves it.
    pub entering: bool,
    /// Index of refraction on the side the ray comes from, n₁, and beyond, n₂.
    pub n1: f32,
    pub n2: f32,
    /// η = n₁ / n₂.
    pub eta: f32,
    /// cos θ₁ = −n·d, with the facing normal.
    pub cos_theta1: f32,
    /// sin²θ₂ = η²(1 − cos²θ₁): above 1 there is no refracted ray.
    pub sin2_theta2: f32,
    pub total_internal_reflection: bool,
    /// Schlick's R, if the material asks for the Fresnel term and there is a refracted ray.
    pub fresnel: Option<f32>,
    /// The material's transparency T and reflectance.
    pub transparency: f32,
    pub reflectance: [f32; 3],
    /// The mirror ray's weight: reflectance + T·R (reflectance + T on total internal reflection).
    pub reflected_weight: [f32; 3],
    /// The refracted ray's weight, T·(1 − R) (absent on total internal reflection).
    pub refracted_weight: Option<[f32; 3]>,
}

/// The name of a shape in the tree: `sphere`, `plane`, `triangle`, `smooth_triangle`, `cone`.
pub fn shape_name(shape: &Shape) -> &'static str {
    match shape {
        Shape::Sphere { .. } => "sphere",
        Shape::Plane { .. } => "plane",
        Shape::Triangle { .. } => "triangle",
        Shape::SmoothTriangle { .. } => "smooth_triangle",
        Shape::Cone { .. } => "cone",
    }
}

/// The name of a light's kind: `ambient`, `point`, `spot`.
pub fn light_kind(light: &Light) -> &'static str {
    match light {
        Light::Ambient { .. } => "ambient",
        Light::Point { .. } => "point",
        Light::Spot { .. } => "spot",
    }
}
impl RayTree {
    /// The tree as pretty-printed JSON (its schema: book/appendix/ray-tree.md).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a ray tree is always valid JSON")
    }
}
