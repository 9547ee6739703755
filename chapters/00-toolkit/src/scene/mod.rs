//! The scene: what a scene file describes, checked and ready to render.
//!
//! The `scene-files` crate (`crates/scene-files`) reads TOML scene files,
//! the SPD scenes' NFF and OBJ meshes into this [`Scene`]. A chapter that
//! cannot simulate something yet still reads it; it simply does not use
//! it. Everything here has been validated: finite numbers, unit normals,
//! positive radii, triangles with area, known material names.

mod effects;

use crate::Vec3;
pub use effects::Effects;

use crate::Color;

/// A complete, validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub camera: CameraSpec,
    pub image: ImageSpec,
    pub trace: TraceSpec,
    /// Materials in the order of their names; objects refer to them by index.
    pub materials: Vec<Material>,
    pub lights: Vec<Light>,
    pub objects: Vec<Object>,
}

/// Where the eye is and where it looks (chapter 1's pinhole camera).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraSpec {
    pub eye: Vec3,
    pub look_at: Vec3,
    /// Unit vector, not parallel to `look_at - eye`.
    pub up: Vec3,
    /// Vertical field of view in degrees, in (0, 180).
    pub vfov_degrees: f32,
}

/// The picture to make.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImageSpec {
    pub width: u32,
    pub height: u32,
    /// The colour of a ray that hits nothing.
    pub background: Color,
    /// Rays per pixel (anti-aliasing, chapter 1): a square number.
    pub samples: u32,
    /// Where the random positions of the rays in a pixel come from
    /// (`--seed`, chapter 1's `render`). `None`, as a scene file gives:
    /// from the pixel's index alone, and one ray goes through the centre.
    /// `Some(seed)`: from the seed and the index, every ray at a random
    /// point of its cell, one ray too; another seed gives other positions.
    pub seed: Option<u64>,
}

/// Chapter 7's termination criteria and the effects switched on.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceSpec {
    /// A path ends after this many bounces.
    pub max_depth: u32,
    /// A path ends when the product of its weights falls below this.
    pub min_weight: f32,
    /// `None`: every effect the scene calls for; `Some`: only these.
    pub effects: Option<Vec<Effect>>,
}

impl Default for TraceSpec {
    /// What a scene gets that does not say: 5 bounces, weights down to
    /// 0.001, every effect it calls for.
    fn default() -> Self {
        TraceSpec {
            max_depth: 5,
            min_weight: 0.001,
            effects: None,
        }
    }
}

/// The effects a tracer can simulate, each introduced by one chapter.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Deserialize, clap::ValueEnum,
)]
#[serde(rename_all = "lowercase")]
pub enum Effect {
    Lambert,
    Spot,
    Shadows,
    Reflection,
    Refraction,
}

// ANCHOR: material
/// How a surface answers light.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    pub name: String,
    /// Diffuse albedo per channel, in [0, 1] (chapter 3).
    pub color: Color,
    /// Mirror weight per channel, in [0, 1] (chapter 5).
    pub reflectance: Color,
    /// Weight of the highlight of point lights, in [0, 1] (chapter 5).
    pub specular: f32,
    /// Exponent of the highlight: larger is sharper (chapter 5).
    pub shininess: f32,
    /// Weight of the transmitted ray, in [0, 1] (chapter 6).
    pub transparency: f32,
    /// Index of refraction, > 0 (chapter 6).
    pub ior: f32,
    /// Use Schlick's Fresnel term to split reflection and refraction (chapter 6).
    pub fresnel: bool,
}
// ANCHOR_END: material

/// Index into [`Scene::materials`].
pub type MaterialId = usize;

/// A light source (chapter 3).
#[derive(Debug, Clone, PartialEq)]
pub enum Light {
    /// Constant light, equal everywhere, never blocked.
    Ambient { color: Color },
    /// Light from a point, falling off with 1/r² (or not at all: see [`Falloff`]).
    Point {
        position: Vec3,
        color: Color,
        intensity: f32,
        /// Does this light cast shadows (chapter 4)?
        shadows: bool,
        falloff: Falloff,
    },
    /// A point light limited to a cone around `direction`, with a smooth
    /// edge between the inner and the outer half-angle.
    Spot {
        position: Vec3,
        /// Unit vector: the axis of the cone.
        direction: Vec3,
        color: Color,
        intensity: f32,
        inner_degrees: f32,
        outer_degrees: f32,
        shadows: bool,
    },
}

/// How a point light's light weakens with the distance r from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Falloff {
    /// 1/r², as light from a point does: its power spreads over a sphere
    /// whose area grows with r².
    #[default]
    InverseSquare,
    /// Not at all: as bright at any distance. Not physical, but it is how
    /// the Neutral File Format (NFF) defines its lights, and what POV-Ray's
    /// lights do unless they say `fade_power`.
    None,
}

/// A shape with its material.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    pub shape: Shape,
    pub material: MaterialId,
    /// Does this object block shadow rays (chapter 4)?
    pub shadows: bool,
}

/// The geometric primitives of chapter 2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: f32,
    },
    /// The points x with n·x + d = 0; `normal` is a unit vector.
    Plane {
        normal: Vec3,
        offset: f32,
    },
    /// Three corners, counter-clockwise seen from the front; never degenerate.
    Triangle {
        vertices: [Vec3; 3],
    },
    /// A triangle of a smooth mesh (NFF `pp` patches, OBJ files with vertex
    /// normals): the surface is flat, but shading interpolates these unit
    /// normals at the corners, so that a mesh of flat facets looks curved.
    SmoothTriangle {
        vertices: [Vec3; 3],
        normals: [Vec3; 3],
    },
    /// The side of a truncated cone around the axis from `base` to `apex`
    /// (distinct points), without end caps: its radius goes linearly from
    /// `base_radius` to `apex_radius` (both ≥ 0, one > 0); a cylinder when
    /// they are equal, a pointed cone when one is 0. The SPD scenes' NFF `c`.
    /// Its normal points away from the axis, or towards it if `inside_out`
    /// (NFF's negative radii: only the inside is meant to be seen).
    Cone {
        base: Vec3,
        base_radius: f32,
        apex: Vec3,
        apex_radius: f32,
        inside_out: bool,
    },
}

impl Scene {
    /// The material of an object.
    pub fn material(&self, object: &Object) -> &Material {
        &self.materials[object.material]
    }

    /// The same scene moved by `offset`: camera, lights and objects.
    pub fn translated(mut self, offset: Vec3) -> Scene {
        self.camera.eye += offset;
        self.camera.look_at += offset;
        for light in &mut self.lights {
            match light {
                Light::Ambient { .. } => {}
                Light::Point { position, .. } | Light::Spot { position, .. } => *position += offset,
            }
        }
        for object in &mut self.objects {
            match &mut object.shape {
                Shape::Sphere { center, .. } => *center += offset,
                // n·(x − o) + d = 0, so the new offset is d − n·o.
                Shape::Plane { normal, offset: d } => *d -= normal.dot(offset),
                Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
                    vertices.iter_mut().for_each(|v| *v += offset)
                }
                Shape::Cone { base, apex, .. } => {
                    *base += offset;
                    *apex += offset;
                }
            }
        }
        self
    }

    /// The same scene at another image size (tests render small).
    pub fn with_size(mut self, width: u32, height: u32) -> Scene {
        self.image.width = width;
        self.image.height = height;
        self
    }
}
