//! The tree's nodes made from what a chapter computed: each constructor
//! takes the chapter's own values and computes nothing of the lesson.

use ch00_toolkit::scene::{Light, Object};
use ch00_toolkit::{Color, Scene, Vec3};

use super::{HitNode, LightNode, LightStatus, ObjectRef, Side, TracerInfo, light_kind, shape_name};

impl TracerInfo {
    /// A tracer that finds the closest hit and shows it (chapter 2).
    pub const HITS: TracerInfo = TracerInfo {
        hits: true,
        lights: false,
        shadow_rays: false,
        max_depth: None,
        min_weight: None,
    };

    /// A tracer that lights its hits (chapter 3).
    pub const LIGHTS: TracerInfo = TracerInfo {
        lights: true,
        ..TracerInfo::HITS
    };

    /// A tracer that asks shadow rays (chapter 4).
    pub const SHADOW_RAYS: TracerInfo = TracerInfo {
        shadow_rays: true,
        ..TracerInfo::LIGHTS
    };

    /// A recursive tracer, with its criteria (chapter 5 on).
    pub fn recursive(max_depth: u32, min_weight: Option<f32>) -> TracerInfo {
        TracerInfo {
            max_depth: Some(max_depth),
            min_weight,
            ..TracerInfo::SHADOW_RAYS
        }
    }
}

/// Where a chapter's ray met a surface, as the chapter found it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HitFacts {
    pub object: usize,
    pub t: f32,
    pub point: Vec3,
    /// The surface's normal as the shape defines it.
    pub normal: Vec3,
    /// The normal shading uses (a smooth triangle's interpolated one).
    pub shading_normal: Vec3,
    /// For a sphere: the two roots of the ray's quadratic, nearest first.
    pub roots: Option<(f32, f32)>,
}

impl HitFacts {
    /// The facts of a hit on `object` at `t`; `roots` for a sphere.
    pub fn new(
        object: usize,
        t: f32,
        point: Vec3,
        normals: (Vec3, Vec3),
        roots: Option<(f32, f32)>,
    ) -> Self {
        let (normal, shading_normal) = normals;
        HitFacts {
            object,
            t,
            point,
            normal,
            shading_normal,
            roots,
        }
    }
}

impl HitNode {
    /// The node of a hit along a ray of direction `direction`: the side is
    /// the one the geometric normal faces, and the facing normal is the
    /// shading normal turned to that side, as chapter 3's `Surface` turns it.
    pub fn new(scene: &Scene, hit: HitFacts, direction: Vec3) -> HitNode {
        let object = &scene.objects[hit.object];
        let back = hit.normal.dot(direction) > 0.0;
        let facing = if back {
            -hit.shading_normal
        } else {
            hit.shading_normal
        };
        HitNode {
            object: hit.object,
            shape: shape_name(&object.shape).into(),
            material: scene.material(object).name.clone(),
            t: hit.t,
            point: hit.point.to_array(),
            normal: hit.normal.to_array(),
            facing_normal: facing.to_array(),
            side: if back { Side::Back } else { Side::Front },
            roots: hit.roots.map(|(a, b)| [a, b]),
        }
    }
}

impl ObjectRef {
    /// Object `index` of `objects`.
    pub fn new(objects: &[Object], index: usize) -> ObjectRef {
        ObjectRef {
            object: index,
            shape: shape_name(&objects[index].shape).into(),
        }
    }
}

/// A point or spot light that reaches a hit, as the chapter's `arrival` says.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arriving {
    /// l, the unit vector towards the light.
    pub direction: Vec3,
    pub distance: f32,
    pub casts_shadows: bool,
}

impl Arriving {
    pub fn new(direction: Vec3, distance: f32, casts_shadows: bool) -> Arriving {
        Arriving {
            direction,
            distance,
            casts_shadows,
        }
    }
}

/// What the chapter's shading computed for a light in front of the surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Terms {
    /// The chapter's `lambert`.
    pub lambert: Color,
    /// The chapter's highlight, from chapter 5 on.
    pub highlight: Option<Color>,
}

impl Terms {
    pub fn new(lambert: Color, highlight: Option<Color>) -> Terms {
        Terms { lambert, highlight }
    }
}

impl LightNode {
    /// Light `index` of the scene, before the tree knows what it does: dark
    /// (outside a spot's cone), as [`LightNode::ambient`] and
    /// [`LightNode::arriving`] tell otherwise.
    pub fn new(index: usize, light: &Light) -> LightNode {
        LightNode {
            light: index,
            kind: light_kind(light).into(),
            status: LightStatus::Dark,
            direction: None,
            distance: None,
            n_dot_l: None,
            casts_shadows: None,
            shadow_ray: None,
            lambert: None,
            highlight: None,
            adds: [0.0; 3],
        }
    }

    /// An ambient light that adds `adds` (albedo × its colour).
    pub fn ambient(mut self, adds: Color) -> LightNode {
        self.status = LightStatus::Ambient;
        self.adds = adds.to_array();
        self
    }

    /// A light that reaches a surface of facing normal `normal`. The tree
    /// says what the chapter's light loop does with it: nothing if it is
    /// behind the surface (n·l ≤ 0) or if its `terms` add nothing; else
    /// it adds them, unless the chapter's shadow ray found it blocked.
    /// `terms` and `shadow` are asked only where the light loop asks them.
    pub fn arriving(
        mut self,
        normal: Vec3,
        light: Arriving,
        terms: impl FnOnce() -> Terms,
        shadow: impl FnOnce() -> Option<super::ShadowNode>,
    ) -> LightNode {
        let n_dot_l = normal.dot(light.direction);
        self.direction = Some(light.direction.to_array());
        self.distance = Some(light.distance);
        self.n_dot_l = Some(n_dot_l);
        self.casts_shadows = Some(light.casts_shadows);
        if n_dot_l <= 0.0 {
            self.status = LightStatus::Behind;
            return self;
        }
        let terms = terms();
        self.lambert = Some(terms.lambert.to_array());
        self.highlight = terms.highlight.map(|h| h.to_array());
        let total = terms.lambert + terms.highlight.unwrap_or(Color::ZERO);
        if total == Color::ZERO {
            self.status = LightStatus::AddsNothing;
            return self;
        }
        self.shadow_ray = if light.casts_shadows { shadow() } else { None };
        let blocked = self.shadow_ray.as_ref().is_some_and(|s| s.blocked);
        self.status = if blocked {
            LightStatus::Blocked
        } else {
            LightStatus::Free
        };
        self.adds = if blocked { [0.0; 3] } else { total.to_array() };
        self
    }
}
