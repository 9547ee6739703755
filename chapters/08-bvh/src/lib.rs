#![doc = include_str!("../README.md")]

mod aabb;
pub mod build;

pub mod ray_tree;

pub use aabb::{Aabb, bounds};
pub use ch02_hits::{coincident_range, hit_at, intersect};
pub use ch07_termination::{
    Camera, Hit, Ray, Termination, Tracer, World, closest_hit, render, render_whitted, scene_files,
    toolkit, workbench,
};

use build::Node;
use toolkit::scene::{Object, Shape};
use toolkit::{Image, Scene, Stats};

/// The longest path from the root to a leaf (the build guarantees it), and
/// so the size of traversal's stack.
pub const MAX_DEPTH: usize = 96;

/// A bounding volume hierarchy over a scene's objects: a binary tree of
/// boxes, each holding the boxes of its children, with the primitives in
/// the leaves. A ray skips every subtree whose box it misses.
#[derive(Debug, Clone)]
pub struct Bvh {
    /// The tree, flattened in depth-first order (root first).
    nodes: Vec<Node>,
    /// The bounded objects, in the order of the leaves.
    primitives: Vec<Primitive>,
    /// Planes: they have no box, so every ray tests them, as in chapter 2.
    unbounded: Vec<Primitive>,
}

/// An object's shape, copied next to its neighbours in the tree for fast
/// access, with what a hit needs to know of the object.
#[derive(Debug, Clone, Copy)]
struct Primitive {
    shape: Shape,
    /// Index in the scene's objects.
    object: usize,
    /// Does it block shadow rays?
    shadows: bool,
}

impl Primitive {
    fn of(objects: &[Object], index: usize) -> Primitive {
        Primitive {
            shape: objects[index].shape,
            object: index,
            shadows: objects[index].shadows,
        }
    }
}

/// The shape of a built hierarchy, for reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Summary {
    pub primitives: usize,
    pub unbounded: usize,
    pub nodes: usize,
    pub leaves: usize,
    pub depth: usize,
}

impl std::fmt::Display for Summary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "BVH: {} primitives in {} nodes ({} leaves, depth {}), {} planes outside",
            self.primitives, self.nodes, self.leaves, self.depth, self.unbounded
        )
    }
}

impl Bvh {
    /// Builds the hierarchy over `objects` (binned SAH, see `build.rs`).
    pub fn build(objects: &[Object]) -> Bvh {
        let (mut items, unbounded) = build::items(objects);
        let unbounded = unbounded
            .into_iter()
            .map(|index| Primitive::of(objects, index))
            .collect();
        let nodes = build::build(&mut items);
        let primitives = items
            .iter()
            .map(|item| Primitive::of(objects, item.index))
            .collect();
        Bvh {
            nodes,
            primitives,
            unbounded,
        }
    }

    /// How big and how deep the tree is.
    pub fn summary(&self) -> Summary {
        Summary {
            primitives: self.primitives.len(),
            unbounded: self.unbounded.len(),
            nodes: self.nodes.len(),
            leaves: self.nodes.iter().filter(|n| n.count > 0).count(),
            depth: self.depth(0),
        }
    }

    fn depth(&self, node: usize) -> usize {
        match self.nodes.get(node) {
            None => 0,
            Some(n) if n.count > 0 => 1,
            Some(n) => 1 + self.depth(node + 1).max(self.depth(n.start as usize)),
        }
    }

    /// Hands `search` the leaves whose boxes the ray enters for t in
    /// [t_min, `search.limit()`], nearer child first, until it is done.
    ///
    /// The limit is asked again at every step: once the closest-hit search
    /// has found a hit at t, boxes entered beyond t cannot hold a closer one
    /// and are skipped, even if they were queued before.
    fn traverse<'a>(&'a self, ray: &Ray, t_min: f32, search: &mut impl Search<'a>) {
        let inverse = ray.direction.recip();
        let entry = |node: usize, limit: f32| {
            self.nodes[node]
                .bounds
                .entry(ray.origin, inverse, t_min, limit)
        };
        // Subtrees still to visit, with the t at which the ray enters them.
        let mut stack = [(0usize, 0.0f32); MAX_DEPTH + 1];
        let mut top = 0;
        if self.nodes.is_empty() {
            return;
        }
        if let Some(t) = entry(0, search.limit()) {
            stack[0] = (0, t);
            top = 1;
        }
        while top > 0 {
            top -= 1;
            let (index, t_entry) = stack[top];
            if t_entry > search.limit() {
                continue; // a hit nearer than this box was found meanwhile
            }
            let node = self.nodes[index];
            if node.count > 0 {
                let start = node.start as usize;
                if search.leaf(&self.primitives[start..start + node.count as usize]) {
                    return;
                }
                continue;
            }
            let limit = search.limit();
            let (a, b) = (index + 1, node.start as usize);
            let mut children = [(a, entry(a, limit)), (b, entry(b, limit))];
            // The farther child goes on the stack first, so the nearer is
            // visited first and its hits shrink the limit for the other.
            if children[0].1 < children[1].1 {
                children.swap(0, 1);
            }
            for (child, t) in children {
                if let Some(t) = t {
                    stack[top] = (child, t);
                    top += 1;
                }
            }
        }
    }
}

/// What a traversal looks for.
trait Search<'a> {
    /// Only boxes entered at or before this t are visited.
    fn limit(&self) -> f32;
    /// Tests a leaf's primitives; true ends the traversal.
    fn leaf(&mut self, primitives: &'a [Primitive]) -> bool;
}

/// The closest hit so far, chosen exactly as chapter 2's loop chooses: the
/// smallest t, and of equal t's the object that comes first in the scene, so
/// that both give the same picture to the last bit.
struct Closest<'a, 'r> {
    ray: &'r Ray,
    t_min: f32,
    t_max: f32,
    found: Option<(f32, &'a Primitive)>,
}

impl<'a> Closest<'a, '_> {
    fn offer(&mut self, primitive: &'a Primitive) {
        let (ray, t_min) = (self.ray, self.t_min);
        if let Some(t) = intersect(&primitive.shape, ray, t_min, self.limit()) {
            let better = self
                .found
                .is_none_or(|(best, p)| t < best || primitive.object < p.object);
            if better {
                self.found = Some((t, primitive));
            }
        }
    }
}

impl<'a> Search<'a> for Closest<'a, '_> {
    /// Hits are looked for below t_max, or, once one is found, up to and
    /// including its t (a tie may still win by its index).
    fn limit(&self) -> f32 {
        self.found.map_or(self.t_max, |(t, _)| t.next_up())
    }

    fn leaf(&mut self, primitives: &'a [Primitive]) -> bool {
        primitives.iter().for_each(|p| self.offer(p));
        false
    }
}

/// The second look that chapter 2's rule for coincident surfaces takes
/// (`first_coincident`): of the primitives listed before the nearest hit's
/// object, the first that the ray meets in (lower, upper).
struct First<'a, 'r> {
    ray: &'r Ray,
    lower: f32,
    upper: f32,
    /// Only objects listed before this one can still win.
    before: usize,
    found: Option<(f32, &'a Primitive)>,
}

impl<'a> First<'a, '_> {
    fn offer(&mut self, primitive: &'a Primitive) {
        if primitive.object < self.before
            && let Some(t) = intersect(&primitive.shape, self.ray, self.lower, self.upper)
        {
            self.before = primitive.object;
            self.found = Some((t, primitive));
        }
    }
}

impl<'a> Search<'a> for First<'a, '_> {
    /// The window's end: it does not move, whatever is found.
    fn limit(&self) -> f32 {
        self.upper
    }

    fn leaf(&mut self, primitives: &'a [Primitive]) -> bool {
        primitives.iter().for_each(|p| self.offer(p));
        false
    }
}

impl Bvh {
    /// Chapter 2's rule for coincident surfaces, with `nearest` the
    /// nearest hit: a second walk of the tree, through the boxes that the
    /// ray crosses in the window around it only.
    fn first_coincident(&self, ray: &Ray, (t_min, t_max): (f32, f32), nearest: Hit) -> Hit {
        if nearest.object == 0 {
            return nearest; // nothing is listed before it
        }
        let (lower, upper) = coincident_range(&nearest, ray, t_min, t_max);
        let mut first = First {
            ray,
            lower,
            upper,
            before: nearest.object,
            found: None,
        };
        self.unbounded.iter().for_each(|p| first.offer(p));
        self.traverse(ray, lower, &mut first);
        match first.found {
            Some((t, p)) => hit_at(&p.shape, ray, t, p.object),
            None => nearest,
        }
    }
}

/// Is there any shadow-casting primitive on the ray in (t_min, t_max)?
struct Blocker<'r> {
    ray: &'r Ray,
    t_min: f32,
    t_max: f32,
    blocked: bool,
}

impl Blocker<'_> {
    fn blocks(&self, p: &Primitive) -> bool {
        p.shadows && intersect(&p.shape, self.ray, self.t_min, self.t_max).is_some()
    }
}

impl Search<'_> for Blocker<'_> {
    fn limit(&self) -> f32 {
        self.t_max
    }

    /// The first blocker ends the search: which one does not matter.
    fn leaf(&mut self, primitives: &[Primitive]) -> bool {
        self.blocked = primitives.iter().any(|p| self.blocks(p));
        self.blocked
    }
}

impl Bvh {
    /// The nearest hit, as chapter 2's loop finds it, without its rule for
    /// coincident surfaces (`closest_hit` applies it).
    pub fn nearest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        let mut closest = Closest {
            ray,
            t_min,
            t_max,
            found: None,
        };
        self.unbounded.iter().for_each(|p| closest.offer(p));
        self.traverse(ray, t_min, &mut closest);
        let (t, primitive) = closest.found?;
        Some(hit_at(&primitive.shape, ray, t, primitive.object))
    }
}

impl World for Bvh {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        let nearest = self.nearest_hit(ray, t_min, t_max)?;
        Some(self.first_coincident(ray, (t_min, t_max), nearest))
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        let mut blocker = Blocker {
            ray,
            t_min,
            t_max,
            blocked: false,
        };
        if !blocker.leaf(&self.unbounded) {
            self.traverse(ray, t_min, &mut blocker);
        }
        blocker.blocked
    }
}

/// Chapter 8's picture: chapter 7's tracer, with the rays traced against a
/// BVH of the scene instead of every object in turn.
pub fn render_bvh(
    scene: &Scene,
    termination: Termination,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    let bvh = Bvh::build(&scene.objects);
    render_whitted(&Tracer { termination }, scene, &bvh, on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
