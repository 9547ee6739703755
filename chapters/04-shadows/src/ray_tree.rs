//! Chapter 4's ray tree (`--pixel X,Y`): chapter 3's tree with the shadow
//! ray of each light, free or blocked by which object.
//!
//! The chapter's own `shade` runs unchanged against a [`Recorder`], a
//! [`World`] that answers every question with the scene's objects and
//! writes each question and answer down. `any_hit` only says *whether*
//! something blocks a shadow ray; [`shadow_node`] asks the chapter's
//! intersection again to say *which* object.

use std::sync::Mutex;

pub use ch03_lambert::ray_tree::{hit_node, light_nodes, primary_ray, ray_node, rgb};

use crate::toolkit::scene::Object;
use crate::toolkit::{Scene, Stats};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{
    End, ObjectRef, RayKind, RayNode, ShadowNode, TracerInfo, shape_name,
};
use crate::{Hit, Incoming, Ray, ShadowStart, Surface, World, intersect, lambert, shade, trace};

/// A question a tracer asked its world, with the answer it got.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Query {
    /// `closest_hit(ray, t_min, t_max)`.
    Closest {
        ray: Ray,
        t_min: f32,
        t_max: f32,
        hit: Option<Hit>,
    },
    /// `any_hit(ray, t_min, t_max)`: a shadow ray.
    Any {
        ray: Ray,
        t_min: f32,
        t_max: f32,
        blocked: bool,
    },
}

/// Where a [`Recorder`] writes its queries down.
pub trait Sink: Sync {
    fn record(&self, query: Query);
}

impl Sink for Mutex<Vec<Query>> {
    fn record(&self, query: Query) {
        self.lock().expect("no panic while recording").push(query);
    }
}

/// A world that answers like `world` and writes every question and answer
/// to `sink`, in the order they are asked.
pub struct Recorder<'a, W: World + ?Sized, S: Sink> {
    pub world: &'a W,
    pub sink: &'a S,
}

impl<W: World + ?Sized, S: Sink> World for Recorder<'_, W, S> {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        let hit = self.world.closest_hit(ray, t_min, t_max);
        self.sink.record(Query::Closest {
            ray: *ray,
            t_min,
            t_max,
            hit,
        });
        hit
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        let blocked = self.world.any_hit(ray, t_min, t_max);
        self.sink.record(Query::Any {
            ray: *ray,
            t_min,
            t_max,
            blocked,
        });
        blocked
    }
}

/// The tree's account of a shadow ray that `any_hit` answered with
/// `blocked`: and if it is blocked, the nearest shadow-casting object on
/// the segment (t_min, t_max), by the chapter's `intersect`.
pub fn shadow_node(
    objects: &[Object],
    ray: &Ray,
    t_min: f32,
    t_max: f32,
    blocked: bool,
) -> ShadowNode {
    let nearest = objects
        .iter()
        .enumerate()
        .filter(|(_, object)| object.shadows)
        .filter_map(|(index, object)| Some((intersect(&object.shape, ray, t_min, t_max)?, index)))
        .min_by(|a, b| a.0.total_cmp(&b.0));
    let blocker = nearest.filter(|_| blocked);
    ShadowNode {
        origin: rgb(ray.origin),
        direction: rgb(ray.direction),
        t_max,
        blocked,
        blocked_by: blocker.map(|(_, index)| ObjectRef {
            object: index,
            shape: shape_name(&objects[index].shape).into(),
        }),
        blocker_t: blocker.map(|(t, _)| t),
    }
}

/// The shadow ray among `queries` that went towards `incoming`'s light
/// (along its direction l), as the tree shows it.
pub fn shadow_towards(
    objects: &[Object],
    queries: &[Query],
    incoming: &Incoming,
) -> Option<ShadowNode> {
    queries.iter().find_map(|query| match *query {
        Query::Any {
            ray,
            t_min,
            t_max,
            blocked,
        } if ray.direction.dot(incoming.direction) > 1.0 - 1e-5 => {
            Some(shadow_node(objects, &ray, t_min, t_max, blocked))
        }
        _ => None,
    })
}

/// What this chapter's tracer does.
pub const TRACER: TracerInfo = TracerInfo {
    hits: true,
    lights: true,
    shadow_rays: true,
    max_depth: None,
    min_weight: None,
};

/// Chapter 4's tree: the primary ray, its closest hit, and for each light
/// its shadow ray (as the chapter's `shade` traces them, started as
/// `origin` says) and what it adds.
pub fn explain(scene: &Scene, pixel: Pixel, origin: ShadowStart) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let mut node = ray_node(RayKind::Primary, 0, &ray);
    let mut stats = Stats::default();
    node.color = Some(rgb(trace(scene, &ray, origin, &mut stats)));
    let Some(hit) = scene.objects[..].closest_hit(&ray, 0.0, f32::INFINITY) else {
        node.end = Some(End::NoHit);
        return (TRACER, node);
    };
    let surface = Surface::new(scene, hit, &ray);
    let log = Mutex::new(Vec::new());
    let recorder = Recorder {
        world: &scene.objects[..],
        sink: &log,
    };
    let local = shade(scene, &recorder, &surface, origin, &mut stats, |incoming| {
        lambert(&surface, incoming)
    });
    let queries = log.into_inner().expect("no panic while recording");
    node.hit = Some(hit_node(scene, &hit, &ray));
    node.lights = light_nodes(scene, &surface, &|_| None, &mut |incoming| {
        shadow_towards(&scene.objects, &queries, incoming)
    });
    node.local = Some(rgb(local));
    (TRACER, node)
}
