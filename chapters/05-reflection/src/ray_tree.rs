//! Chapter 5's ray tree (`--pixel X,Y`): every ray of the pixel's path,
//! mirror rays included, with weights, depths and why each path ended.
//!
//! The chapter's own [`trace`] runs once for the pixel's ray, with
//! recorders standing in for its tracer and its world; the workbench builds
//! the tree from what they wrote down, asking [`Lesson`] for this chapter's
//! answers. Chapters 6 to 8 explain their tracers with [`explain_with`].

pub use ch04_shadows::ray_tree::{hit_node, light_nodes, primary_ray, shadow_towards};

use crate::toolkit::{Color, Scene, Stats};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::{Explain, Log, Recorder, ShadowQuery, build};
use crate::workbench::ray_tree::{
    HitNode, LightNode, RayKind, RayNode, RefractionNode, TracerInfo,
};
use crate::{Hit, Mirrors, Path, Ray, Secondary, SecondaryKind, Surface, Whitted, World};
use crate::{highlight, trace};

/// The recorder answers as the tracer it stands in for, and writes it down.
impl<T: Whitted + ?Sized> Whitted for Recorder<'_, T, Hit, Secondary> {
    fn local(
        &self,
        scene: &Scene,
        world: &(impl World + ?Sized),
        surface: &Surface,
        stats: &mut Stats,
    ) -> Color {
        self.record_local(self.inner.local(scene, world, surface, stats))
    }

    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        self.record_secondary(self.inner.secondary_rays(surface, incoming))
    }

    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool {
        let before = *stats;
        let allowed = self.inner.may_trace(depth, weight, stats);
        self.record_may_trace((depth, weight), allowed, &before, stats)
    }
}

/// How a chapter's tree shows a hit's split at glass (none before chapter 6).
pub type ExplainSplit = fn(&Surface, &Ray) -> Option<RefractionNode>;

/// A chapter's tracer and world, answering the tree's questions.
pub struct Lesson<'a, T, W: ?Sized> {
    pub scene: &'a Scene,
    pub tracer: &'a T,
    pub world: &'a W,
    pub split: ExplainSplit,
}

impl<T: Whitted, W: World + ?Sized> Explain for Lesson<'_, T, W> {
    type Ray = Ray;
    type Hit = Hit;
    type Secondary = Secondary;

    fn color(&self, ray: &Ray, depth: u32, weight: Color) -> Color {
        let (path, stats) = (Path { depth, weight }, &mut Stats::default());
        trace(self.tracer, self.scene, self.world, ray, path, stats)
    }

    fn hit(&self, hit: &Hit, ray: &Ray) -> HitNode {
        hit_node(self.scene, hit, ray)
    }

    fn lights(&self, hit: &Hit, ray: &Ray, shadows: &[ShadowQuery]) -> Vec<LightNode> {
        let surface = Surface::new(self.scene, *hit, ray);
        let shine = |incoming: &_| Some(highlight(&surface, incoming));
        let shadow = |incoming: &_| shadow_towards(&self.scene.objects, shadows, incoming);
        light_nodes(self.scene, &surface, &shine, &shadow)
    }

    fn refraction(&self, hit: &Hit, ray: &Ray) -> Option<RefractionNode> {
        (self.split)(&Surface::new(self.scene, *hit, ray), ray)
    }

    fn secondary(&self, secondary: &Secondary) -> (RayKind, Ray, Color) {
        let kind = match secondary.kind {
            SecondaryKind::Reflection => RayKind::Reflection,
            SecondaryKind::Refraction => RayKind::Refraction,
        };
        (kind, secondary.ray, secondary.weight)
    }
}

/// The tree of `lesson`'s tracer for the ray through `pixel`.
pub fn explain_with<T: Whitted, W: World + ?Sized>(lesson: &Lesson<T, W>, pixel: Pixel) -> RayNode {
    let ray = primary_ray(lesson.scene, pixel);
    let log = Log::default();
    let (tracer, world) = (log.recorder(lesson.tracer), log.recorder(lesson.world));
    let (scene, stats) = (lesson.scene, &mut Stats::default());
    let color = trace(&tracer, scene, &world, &ray, Path::START, stats);
    build(lesson, log.into_events(), &ray, color)
}

/// Chapter 5's tree: the mirror rays up to the scene's `max_depth`.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let max_depth = scene.trace.max_depth;
    let (tracer, world) = (&Mirrors { max_depth }, &scene.objects[..]);
    let lesson = Lesson {
        scene,
        tracer,
        world,
        split: |_, _| None,
    };
    let info = TracerInfo::recursive(max_depth, None);
    (info, explain_with(&lesson, pixel))
}
