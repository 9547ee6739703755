//! Chapter 5's ray tree (`--pixel X,Y`): every ray of the pixel's path,
//! mirror rays included, with weights, depths and why each path ended.
//!
//! The chapter's own [`trace`] runs unchanged, once, for the pixel's ray,
//! with two recorders in place of the tracer and the world: [`Recording`]
//! (a [`Whitted`] tracer that asks the chapter's tracer and writes each
//! answer down) and chapter 4's `Recorder` (a [`World`] that does the same
//! for each closest hit and shadow ray). The tree is then rebuilt from that
//! log, which `trace` writes depth first, in the order it recurses.
//! Chapters 6 to 8 explain their tracers with [`explain_with`].

use std::sync::Mutex;

pub use ch04_shadows::ray_tree::{
    Query, Recorder, Sink, hit_node, light_nodes, primary_ray, ray_node, rgb, shadow_towards,
};

use crate::toolkit::{Color, Scene, Stats};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{End, RayKind, RayNode, RefractionNode, TracerInfo};
use crate::{
    Mirrors, Path, Ray, Secondary, SecondaryKind, Surface, Whitted, World, highlight, trace,
};

/// One step of a trace, as the recorders saw it.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    /// A question to the world: a closest hit or a shadow ray.
    World(Query),
    /// The local light of a hit.
    Local(Color),
    /// The secondary rays of a hit, and how a transparent surface split the light.
    Secondary {
        rays: [Option<Secondary>; 2],
        refraction: Option<RefractionNode>,
    },
    /// Whether a secondary ray at `depth` on a path of `weight` may be
    /// traced, and if not, the criterion that ended its path.
    MayTrace {
        depth: u32,
        weight: Color,
        end: Option<End>,
    },
}

/// The events of one trace, in order.
#[derive(Debug, Default)]
pub struct Log(Mutex<Vec<Event>>);

impl Log {
    fn push(&self, event: Event) {
        self.0.lock().expect("no panic while recording").push(event);
    }

    fn into_events(self) -> Vec<Event> {
        self.0.into_inner().expect("no panic while recording")
    }
}

impl Sink for Log {
    fn record(&self, query: Query) {
        self.push(Event::World(query));
    }
}

/// What a chapter adds to the tree at a transparent surface (chapter 6's
/// split); chapter 5 has none.
pub type ExplainSplit = fn(&Surface, &Ray) -> Option<RefractionNode>;

/// A Whitted tracer that answers as `tracer` does and logs each answer.
pub struct Recording<'a, T: Whitted> {
    pub tracer: &'a T,
    pub log: &'a Log,
    pub split: ExplainSplit,
}

impl<T: Whitted> Whitted for Recording<'_, T> {
    fn local(
        &self,
        scene: &Scene,
        world: &(impl World + ?Sized),
        surface: &Surface,
        stats: &mut Stats,
    ) -> Color {
        let color = self.tracer.local(scene, world, surface, stats);
        self.log.push(Event::Local(color));
        color
    }

    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        let rays = self.tracer.secondary_rays(surface, incoming);
        let refraction = (self.split)(surface, incoming);
        self.log.push(Event::Secondary { rays, refraction });
        rays
    }

    /// The tracer's decision; the criterion that ended a path is the one
    /// whose count in `stats` it raised.
    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool {
        let before = *stats;
        let allowed = self.tracer.may_trace(depth, weight, stats);
        let end = match () {
            _ if allowed => None,
            _ if stats.ended_max_depth > before.ended_max_depth => Some(End::MaxDepth),
            _ if stats.ended_threshold > before.ended_threshold => Some(End::WeightThreshold),
            _ => Some(End::NotTraced),
        };
        self.log.push(Event::MayTrace { depth, weight, end });
        allowed
    }
}

/// The tree of the pixel's ray as `tracer` traces it against `world`:
/// what `info` says the tracer does, and the primary ray's node.
pub fn explain_with<T: Whitted, W: World + ?Sized>(
    tracer: &T,
    scene: &Scene,
    world: &W,
    pixel: Pixel,
    info: TracerInfo,
    split: ExplainSplit,
) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let log = Log::default();
    let recorder = Recorder { world, sink: &log };
    let recording = Recording {
        tracer,
        log: &log,
        split,
    };
    let mut stats = Stats::default();
    let color = trace(&recording, scene, &recorder, &ray, Path::START, &mut stats);
    let events = log.into_events();
    let mut builder = Builder {
        scene,
        tracer,
        world,
        events: events.into_iter(),
    };
    let mut node = builder.ray(RayKind::Primary, &ray, Path::START, Color::ONE);
    node.color = Some(rgb(color));
    (info, node)
}

/// Chapter 5's tree: its mirrors, to the scene's `max_depth`.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let tracer = Mirrors {
        max_depth: scene.trace.max_depth,
    };
    let info = TracerInfo {
        hits: true,
        lights: true,
        shadow_rays: true,
        max_depth: Some(tracer.max_depth),
        min_weight: None,
    };
    explain_with(&tracer, scene, &scene.objects[..], pixel, info, |_, _| None)
}

/// Rebuilds the tree from a trace's events, ray by ray, depth first.
struct Builder<'a, T, W: ?Sized> {
    scene: &'a Scene,
    tracer: &'a T,
    world: &'a W,
    events: std::vec::IntoIter<Event>,
}

impl<T: Whitted, W: World + ?Sized> Builder<'_, T, W> {
    /// The node of a traced ray at `path`, carrying `weight`: its hit, the
    /// lights there, and its secondary rays. The colour it brings back is
    /// the chapter's `trace` of the same ray, asked again.
    fn ray(&mut self, kind: RayKind, ray: &Ray, path: Path, weight: Color) -> RayNode {
        let mut node = ray_node(kind, path.depth, ray);
        node.weight = rgb(weight);
        node.path_weight = rgb(path.weight);
        let mut stats = Stats::default();
        let seen = trace(self.tracer, self.scene, self.world, ray, path, &mut stats);
        node.color = Some(rgb(seen));
        let Some(Event::World(Query::Closest { hit, .. })) = self.events.next() else {
            return node;
        };
        let Some(hit) = hit else {
            node.end = Some(End::NoHit);
            return node;
        };
        node.hit = Some(hit_node(self.scene, &hit, ray));
        let surface = Surface::new(self.scene, hit, ray);
        let Some(shadows) = self.shadow_rays(&mut node) else {
            return node;
        };
        node.lights = light_nodes(
            self.scene,
            &surface,
            &|incoming| Some(highlight(&surface, incoming)),
            &mut |incoming| shadow_towards(&self.scene.objects, &shadows, incoming),
        );
        self.secondary_rays(&mut node);
        node
    }

    /// The shadow rays of a hit, up to its local light (stored in `node`);
    /// `None` if the log goes another way.
    fn shadow_rays(&mut self, node: &mut RayNode) -> Option<Vec<Query>> {
        let mut shadows = Vec::new();
        loop {
            match self.events.next()? {
                Event::World(query @ Query::Any { .. }) => shadows.push(query),
                Event::Local(color) => {
                    node.local = Some(rgb(color));
                    return Some(shadows);
                }
                _ => return None,
            }
        }
    }

    /// The hit's secondary rays, each traced or ended.
    fn secondary_rays(&mut self, node: &mut RayNode) {
        let Some(Event::Secondary { rays, refraction }) = self.events.next() else {
            return;
        };
        node.refraction = refraction;
        if rays == [None, None] {
            node.end = Some(End::NoSecondaryRays);
            return;
        }
        for secondary in rays.into_iter().flatten() {
            let child = self.secondary(&secondary);
            node.secondary.push(child);
        }
    }

    /// One secondary ray: traced one bounce deeper, or ended by the
    /// criterion that `may_trace` counted.
    fn secondary(&mut self, secondary: &Secondary) -> RayNode {
        let kind = match secondary.kind {
            SecondaryKind::Reflection => RayKind::Reflection,
            SecondaryKind::Refraction => RayKind::Refraction,
        };
        let Some(Event::MayTrace { depth, weight, end }) = self.events.next() else {
            return ray_node(kind, 0, &secondary.ray);
        };
        let next = Path { depth, weight };
        if end.is_none() {
            return self.ray(kind, &secondary.ray, next, secondary.weight);
        }
        let mut node = ray_node(kind, depth, &secondary.ray);
        node.weight = rgb(secondary.weight);
        node.path_weight = rgb(weight);
        node.traced = false;
        node.end = end;
        node
    }
}
