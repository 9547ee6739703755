//! Recording a chapter's tracer at work on one pixel, and the tree made
//! from the record.
//!
//! A tracer asks its world for closest hits and shadow rays (chapter 4's
//! `World`) and, from chapter 5 on, asks its Whitted tracer for the local
//! light, the secondary rays and whether a ray may go on. A [`Recorder`]
//! stands in for the world or the tracer: it passes each question on to
//! the chapter's own, and writes the question and the answer in a [`Log`].
//! The chapters implement their traits for it (each in a few lines of its
//! `ray_tree.rs`), so the tree shows what the chapter's own code computed.
//! [`build`] turns the log, which the tracer writes depth first, into the
//! tree.

use std::sync::Mutex;

use ch00_toolkit::scene::{Object, Shape};
use ch00_toolkit::{Color, Stats, Vec3};

use super::{End, HitNode, LightNode, RayKind, RayNode, RefractionNode, ShadowNode};

/// One thing a chapter's tracer did for the pixel. `H` is the chapter's
/// hit, `S` its secondary ray.
#[derive(Debug, Clone, PartialEq)]
pub enum Event<H, S> {
    /// `closest_hit` along a ray, and what it found.
    Closest { hit: Option<H> },
    /// `any_hit` along a shadow ray, and whether something blocked it.
    Shadow(ShadowQuery),
    /// The local light of the latest hit.
    Local(Color),
    /// The rays that leave the latest hit.
    Secondary([Option<S>; 2]),
    /// May a secondary ray at `depth` on a path of `weight` go on? `end`
    /// says which criterion ended it if not.
    MayTrace {
        depth: u32,
        weight: Color,
        end: Option<End>,
    },
}

/// A shadow ray as the chapter asked `any_hit` about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShadowQuery {
    pub origin: Vec3,
    pub direction: Vec3,
    pub t_min: f32,
    pub t_max: f32,
    pub blocked: bool,
}

impl ShadowQuery {
    /// A shadow ray asked between `t_min` and `t_max`, and the answer.
    pub fn new(origin: Vec3, direction: Vec3, (t_min, t_max): (f32, f32), blocked: bool) -> Self {
        ShadowQuery {
            origin,
            direction,
            t_min,
            t_max,
            blocked,
        }
    }

    /// The shadow ray among `shadows` that went along `direction` (towards
    /// a light at the hit they were traced from).
    pub fn towards(shadows: &[ShadowQuery], direction: Vec3) -> Option<&ShadowQuery> {
        shadows
            .iter()
            .find(|s| s.direction.dot(direction) > 1.0 - 1e-5)
    }

    /// The tree's node of this shadow ray, naming (if it is blocked) the
    /// nearest shadow-casting object of `objects` on it, as the chapter's
    /// `intersect(shape, t_min, t_max)` along this ray finds it.
    pub fn node_among(
        &self,
        objects: &[Object],
        intersect: impl Fn(&Shape, f32, f32) -> Option<f32>,
    ) -> ShadowNode {
        let nearest = (objects.iter().enumerate())
            .filter(|(_, object)| object.shadows)
            .filter_map(|(i, object)| Some((intersect(&object.shape, self.t_min, self.t_max)?, i)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        self.node(nearest.map(|(t, i)| (super::ObjectRef::new(objects, i), t)))
    }

    /// The tree's node of this shadow ray; `blocker` is the nearest
    /// shadow-casting object on it and where, if it is blocked.
    fn node(&self, blocker: Option<(super::ObjectRef, f32)>) -> ShadowNode {
        let blocker = blocker.filter(|_| self.blocked);
        ShadowNode {
            origin: self.origin.to_array(),
            direction: self.direction.to_array(),
            t_max: self.t_max,
            blocked: self.blocked,
            blocker_t: blocker.as_ref().map(|(_, t)| *t),
            blocked_by: blocker.map(|(object, _)| object),
        }
    }
}

/// Where recorders write, in the order the tracer asks.
#[derive(Debug)]
pub struct Log<H, S>(Mutex<Vec<Event<H, S>>>);

impl<H, S> Default for Log<H, S> {
    fn default() -> Self {
        Log(Mutex::new(Vec::new()))
    }
}

impl<H, S> Log<H, S> {
    pub fn push(&self, event: Event<H, S>) {
        self.0.lock().expect("no panic while recording").push(event);
    }

    pub fn into_events(self) -> Vec<Event<H, S>> {
        self.0.into_inner().expect("no panic while recording")
    }

    /// The shadow rays written down, in the order they were asked.
    pub fn into_shadow_rays(self) -> Vec<ShadowQuery> {
        let shadow = |event| match event {
            Event::Shadow(query) => Some(query),
            _ => None,
        };
        self.into_events().into_iter().filter_map(shadow).collect()
    }

    /// A recorder that stands in for `inner` and writes here.
    pub fn recorder<'a, T: ?Sized>(&'a self, inner: &'a T) -> Recorder<'a, T, H, S> {
        Recorder { inner, log: self }
    }
}

/// Stands in for `inner`, a chapter's world or tracer: the chapter's trait
/// implementation for it asks `inner` and hands each answer to one of
/// these methods, which write it down and return it.
pub struct Recorder<'a, T: ?Sized, H, S> {
    pub inner: &'a T,
    pub log: &'a Log<H, S>,
}

impl<T: ?Sized, H: Copy, S: Copy> Recorder<'_, T, H, S> {
    pub fn record_closest(&self, hit: Option<H>) -> Option<H> {
        self.log.push(Event::Closest { hit });
        hit
    }

    pub fn record_shadow(&self, query: ShadowQuery) -> bool {
        self.log.push(Event::Shadow(query));
        query.blocked
    }

    pub fn record_local(&self, color: Color) -> Color {
        self.log.push(Event::Local(color));
        color
    }

    pub fn record_secondary(&self, rays: [Option<S>; 2]) -> [Option<S>; 2] {
        self.log.push(Event::Secondary(rays));
        rays
    }

    /// `allowed`, the tracer's answer; `before` and `after` its statistics
    /// around the question, which say which criterion ended the path.
    pub fn record_may_trace(
        &self,
        (depth, weight): (u32, Color),
        allowed: bool,
        before: &Stats,
        after: &Stats,
    ) -> bool {
        let end = match () {
            _ if allowed => None,
            _ if after.ended_max_depth > before.ended_max_depth => Some(End::MaxDepth),
            _ if after.ended_threshold > before.ended_threshold => Some(End::WeightThreshold),
            _ => Some(End::NotTraced),
        };
        self.log.push(Event::MayTrace { depth, weight, end });
        allowed
    }
}

/// A chapter's ray, as the tree needs it (chapter 1 implements it).
pub trait TreeRay: Copy {
    fn origin(&self) -> Vec3;
    fn direction(&self) -> Vec3;
}

/// What [`build`] asks of a chapter: its own answers, in the tree's terms.
pub trait Explain {
    type Ray: TreeRay;
    type Hit: Copy;
    type Secondary: Copy;

    /// The colour the chapter's tracer sees along `ray` at `depth` on a
    /// path of `weight` (traced again, unrecorded).
    fn color(&self, ray: &Self::Ray, depth: u32, weight: Color) -> Color;
    /// The node of a hit.
    fn hit(&self, hit: &Self::Hit, ray: &Self::Ray) -> HitNode;
    /// What each light does at the hit, given the shadow rays traced there.
    fn lights(&self, hit: &Self::Hit, ray: &Self::Ray, shadows: &[ShadowQuery]) -> Vec<LightNode>;
    /// How glass splits the light at the hit (chapter 6 on).
    fn refraction(&self, hit: &Self::Hit, ray: &Self::Ray) -> Option<RefractionNode>;
    /// A secondary ray's kind, ray and weight.
    fn secondary(&self, secondary: &Self::Secondary) -> (RayKind, Self::Ray, Color);
}

/// A node for `ray`, not yet followed.
pub fn ray_node(kind: RayKind, depth: u32, ray: &impl TreeRay) -> RayNode {
    RayNode::new(kind, depth, ray.origin(), ray.direction())
}

/// The node of a primary ray that was not recorded: it saw `color`, and
/// met `hit` (the node of the chapter's closest hit) or nothing.
pub fn primary_node(ray: &impl TreeRay, hit: Option<HitNode>, color: Color) -> RayNode {
    let mut node = ray_node(RayKind::Primary, 0, ray);
    node.end = hit.is_none().then_some(End::NoHit);
    node.hit = hit;
    node.color = Some(color.to_array());
    node
}

/// The tree of the primary ray `ray` from the events its tracing wrote
/// down, depth first; `color` is what the chapter's tracer returned for it.
pub fn build<E: Explain>(
    chapter: &E,
    events: Vec<Event<E::Hit, E::Secondary>>,
    ray: &E::Ray,
    color: Color,
) -> RayNode {
    let mut builder = Builder {
        chapter,
        events: events.into_iter(),
    };
    let mut node = builder.ray(RayKind::Primary, ray, (0, Color::ONE), Color::ONE);
    node.color = Some(color.to_array());
    node
}

struct Builder<'a, E: Explain> {
    chapter: &'a E,
    events: std::vec::IntoIter<Event<E::Hit, E::Secondary>>,
}

impl<E: Explain> Builder<'_, E> {
    /// A traced ray at (depth, path weight), of weight `weight`, and all
    /// that follows it.
    fn ray(&mut self, kind: RayKind, ray: &E::Ray, path: (u32, Color), weight: Color) -> RayNode {
        let (depth, path_weight) = path;
        let mut node = ray_node(kind, depth, ray);
        node.weight = weight.to_array();
        node.path_weight = path_weight.to_array();
        node.color = Some(self.chapter.color(ray, depth, path_weight).to_array());
        let Some(Event::Closest { hit }) = self.events.next() else {
            return node;
        };
        let Some(hit) = hit else {
            node.end = Some(End::NoHit);
            return node;
        };
        node.hit = Some(self.chapter.hit(&hit, ray));
        let Some(shadows) = self.shadow_rays(&mut node) else {
            return node;
        };
        node.lights = self.chapter.lights(&hit, ray, &shadows);
        node.refraction = self.chapter.refraction(&hit, ray);
        self.secondary_rays(&mut node, path);
        node
    }

    /// The shadow rays up to the hit's local light, which goes in `node`.
    fn shadow_rays(&mut self, node: &mut RayNode) -> Option<Vec<ShadowQuery>> {
        let mut shadows = Vec::new();
        loop {
            match self.events.next()? {
                Event::Shadow(query) => shadows.push(query),
                Event::Local(color) => {
                    node.local = Some(color.to_array());
                    return Some(shadows);
                }
                _ => return None,
            }
        }
    }

    /// The rays that leave the hit, each followed (or ended) in turn.
    fn secondary_rays(&mut self, node: &mut RayNode, path: (u32, Color)) {
        let Some(Event::Secondary(rays)) = self.events.next() else {
            return;
        };
        if rays.iter().all(Option::is_none) {
            node.end = Some(End::NoSecondaryRays);
            return;
        }
        for secondary in rays.into_iter().flatten() {
            let child = self.secondary(&secondary, path);
            node.secondary.push(child);
        }
    }

    /// A secondary ray: followed if the tracer let it go on, else ended by
    /// the criterion that ended it.
    fn secondary(&mut self, secondary: &E::Secondary, path: (u32, Color)) -> RayNode {
        let (kind, ray, weight) = self.chapter.secondary(secondary);
        let Some(Event::MayTrace {
            depth,
            weight: path_weight,
            end,
        }) = self.events.next()
        else {
            return ray_node(kind, path.0 + 1, &ray);
        };
        if end.is_none() {
            return self.ray(kind, &ray, (depth, path_weight), weight);
        }
        let mut node = ray_node(kind, depth, &ray);
        node.weight = weight.to_array();
        node.path_weight = path_weight.to_array();
        node.traced = false;
        node.end = end;
        node
    }
}
