//! The complete tracer's accelerator: chapter 8's BVH made eight wide
//! where the CPU has AVX2, four wide elsewhere.
//!
//! Chapter 8 builds a binary tree and tests one box per step. This module
//! takes that same tree (the same binned-SAH build) and collapses it
//! (`collapse.rs`) to nodes of eight children (about three levels into
//! one) or four (two into one); a step then tests all of a node's boxes in
//! one slab test of eight AVX2 lanes (`eight.rs`) or four SSE lanes
//! (`node.rs`). Why eight: a ray takes fewer steps down the shallower
//! tree, and a step's eight boxes cost one AVX instruction where four cost
//! one SSE instruction: 14 to 22% fewer instructions, 1.10 to 1.23 times less CPU
//! time on five SPD scenes (book/appendix/performance.md, "Eight lanes").
//! The width is chosen once per tree ([`Width::detect`]): eight where
//! `is_x86_feature_detected!("avx2")` says so and `RAYBOOK_NO_AVX2` is
//! unset; four on other CPUs (and on other targets, where the eight-wide
//! code is not compiled). Both give the same bytes, box for box: the slab
//! tests do the same operations in the same order, lane by lane.
//! Subtrees of up to eight primitives (two packets; four, one packet, in
//! the eight-wide tree) become one leaf, so that its packets are full.
//! Beside that:
//! - a leaf's primitives are stored in packets of four spheres, four
//!   triangles or four cones, lane by lane, and tested four at a time (`packet.rs`): only
//!   their geometry, not chapter 8's copy of the whole `Shape`. The scene's
//!   own shape is read only for the one hit that is chosen, with the
//!   barycentric weights its triangle test found (chapter 2's `hit_at`
//!   finds them again);
//! - the per-ray parts of the slab and triangle tests are worked out once
//!   per ray, not once per box or triangle, the triangles' only when the
//!   ray reaches one (`primitive.rs`);
//! - spheres are first tested in f32, which rules out most rays that miss
//!   them; a sphere behind the ray's origin is known to have no root
//!   ahead, and a shadow ray's blocker is often sure from bounds on the
//!   roots, before chapter 2's divisions and square root in f64;
//! - cones are first tested in f32 too, four at a time: rays that pass a
//!   cone's axis farther away than its radius are ruled out (`cone.rs`);
//! - the traversal stack is not filled before use (`traverse.rs`);
//! - a scene of a few objects gets no tree: its packets are tested in turn,
//!   each packet of triangles or cones after its own box.
//!
//! - chapter 2's rule for coincident surfaces is applied in the same walk
//!   that finds the nearest hit (`rule.rs`), not in a second one;
//! - a triangle's t in f64 is worked out only where the watertight test's
//!   own f32 t, with its error bound, cannot rule the triangle out (`packet.rs`).
//!
//! The tests are chapter 2's, to the last bit, and the closest hit is
//! chosen as chapter 2 chooses it, so the pictures equal brute force's.
//! What it buys is measured in chapter 8's text and book/appendix/performance.md.

mod behind;
mod closest;
mod collapse;
mod cone;
#[cfg(target_arch = "x86_64")]
mod eight;
mod node;
mod packet;
mod primitive;
mod rule;
#[cfg(test)]
mod tests;
mod traverse;

use ch08_bvh::Aabb;
use ch08_bvh::build::{self, Item};

use crate::toolkit::scene::{Object, Shape};
use crate::tracer::{Hit, Ray, World, coincident_range, hit_with_weights};
use behind::Planes;
use closest::{Closest, Found, Offer};
use collapse::collapse;
use node::Node;
use packet::Packet;
use primitive::{PreparedRay, Primitive, Weights};

/// A four- or eight-wide bounding volume hierarchy over a scene's objects.
#[derive(Debug, Clone)]
pub struct WideBvh<'a> {
    objects: &'a [Object],
    /// The root is node 0 (if there is any bounded object).
    tree: Tree,
    /// The leaves' primitives, in packets of four of a kind, leaf after
    /// leaf; a leaf's lane in a node gives its first packet and how many.
    packets: Vec<Packet>,
    /// Planes: no box, so every ray tests them, as in chapter 2.
    planes: Vec<usize>,
    /// A small scene: all primitives are tested in turn, with no tree.
    flat: bool,
    /// In a small scene, each packet's box, tested before it (none for
    /// spheres): [`Packet::bounds`].
    flat_boxes: Vec<Option<Aabb>>,
    /// In a small scene, each packet of triangles' planes, tested before
    /// it by shadow rays (none for other packets): `behind.rs`.
    flat_planes: Vec<Option<Planes>>,
}

/// The tree's nodes: four lanes each, or eight.
#[derive(Debug, Clone)]
enum Tree {
    Four(Vec<Node<4>>),
    /// Built only where the CPU has AVX2 (`eight.rs` relies on it).
    #[cfg(target_arch = "x86_64")]
    Eight(Vec<Node<8>>),
}

/// How many children a node of the tree has, so how many boxes a slab test
/// tests at once: four (SSE on every x86-64 CPU, glam's fallback on any
/// other), or eight where the CPU has AVX2 (`eight.rs`). The pictures are
/// the same bytes either way.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Width {
    Four,
    Eight,
}

impl Width {
    /// Eight where this CPU has AVX2 and the variable `RAYBOOK_NO_AVX2` is
    /// unset (CI sets it to check the four-wide path on an AVX2 machine);
    /// else four.
    pub fn detect() -> Width {
        if std::env::var_os("RAYBOOK_NO_AVX2").is_none() && has_avx2() {
            Width::Eight
        } else {
            Width::Four
        }
    }
}

#[cfg(target_arch = "x86_64")]
fn has_avx2() -> bool {
    eight::has_avx2()
}

#[cfg(not(target_arch = "x86_64"))]
fn has_avx2() -> bool {
    false
}

impl<'a> WideBvh<'a> {
    /// Builds chapter 8's binary tree over `objects` and collapses it to
    /// nodes as wide as the CPU allows ([`Width::detect`]).
    pub fn build(objects: &'a [Object]) -> WideBvh<'a> {
        Self::build_with(objects, Width::detect())
    }

    /// [`build`](Self::build) with nodes of `width`, or four where eight
    /// is asked for and the CPU has no AVX2 (`RAYBOOK_NO_AVX2` is not read
    /// here: a test compares both widths whatever it says).
    pub fn build_with(objects: &'a [Object], width: Width) -> WideBvh<'a> {
        let eight = width == Width::Eight && has_avx2();
        let (mut items, planes) = build::items(objects);
        let small = items.len() <= FLAT_MAX;
        let binary = if small {
            flat(&items)
        } else {
            build::build(&mut items)
        };
        let primitives: Vec<_> = items
            .iter()
            .filter_map(|item| {
                let object = &objects[item.index];
                Primitive::of(&object.shape, item.index, object.shadows)
            })
            .collect();
        drop(items);
        let mut packets = Vec::with_capacity(primitives.len() / 2 + 1);
        let tree = if eight && !small {
            Self::eight_wide(&binary, &primitives, &mut packets)
        } else {
            Tree::Four(collapse(&binary, &primitives, &mut packets))
        };
        let (flat_boxes, flat_planes) = if small {
            let boxes = packets.iter().map(|p| p.bounds(objects)).collect();
            let planes = packets
                .iter()
                .map(|p| Planes::of(objects, p.triangle_objects()?));
            (boxes, planes.collect())
        } else {
            (Vec::new(), Vec::new())
        };
        WideBvh {
            objects,
            flat: small,
            flat_boxes,
            flat_planes,
            tree,
            packets,
            planes,
        }
    }

    #[cfg(target_arch = "x86_64")]
    fn eight_wide(
        binary: &[build::Node],
        primitives: &[Primitive],
        packets: &mut Vec<Packet>,
    ) -> Tree {
        Tree::Eight(collapse(binary, primitives, packets))
    }

    #[cfg(not(target_arch = "x86_64"))]
    fn eight_wide(
        binary: &[build::Node],
        primitives: &[Primitive],
        packets: &mut Vec<Packet>,
    ) -> Tree {
        Tree::Four(collapse(binary, primitives, packets))
    }

    /// Number of nodes (four or eight wide).
    pub fn node_count(&self) -> usize {
        match &self.tree {
            Tree::Four(nodes) => nodes.len(),
            #[cfg(target_arch = "x86_64")]
            Tree::Eight(nodes) => nodes.len(),
        }
    }

    /// How many children a node has.
    pub fn width(&self) -> Width {
        match &self.tree {
            Tree::Four(_) => Width::Four,
            #[cfg(target_arch = "x86_64")]
            Tree::Eight(_) => Width::Eight,
        }
    }

    fn shape(&self, object: usize) -> &Shape {
        &self.objects[object].shape
    }
}

/// Up to this many bounded objects go into one leaf, without a tree: a
/// ray tests them all, as brute force does, only a packet of triangles or
/// a cone after its box. For so few, a tree's box tests and bookkeeping
/// cost more than the tests they save (`cargo bench --bench small`: with 6
/// objects, the tree took 1.13 times brute force's time).
const FLAT_MAX: usize = 8;

/// A "tree" of one leaf over all `items`: a root whose box holds them all.
fn flat(items: &[Item]) -> Vec<build::Node> {
    let bounds = items.iter().fold(Aabb::EMPTY, |b, i| b.union(i.bounds));
    let count = items.len() as u32;
    (count > 0)
        .then_some(build::Node {
            bounds,
            start: 0,
            count,
        })
        .into_iter()
        .collect()
}

impl WideBvh<'_> {
    /// The nearest hit, without chapter 2's rule for coincident surfaces
    /// (`closest_hit` applies it): `cargo bench --bench coincident`
    /// measures what the rule costs against this.
    pub fn nearest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        let mut closest = Closest::new(t_max);
        self.walk(&mut PreparedRay::new(ray), t_min, &mut closest);
        Some(self.hit(ray, closest.found?))
    }

    /// Offers `found` every hit of a plane, then of the tree's primitives,
    /// in (t_min, found.limit()).
    fn walk(&self, ray: &mut PreparedRay, t_min: f32, found: &mut impl Offer) {
        for &object in &self.planes {
            let limit = found.limit();
            let t = crate::tracer::intersect(self.shape(object), ray.ray, t_min, limit);
            if let Some(t) = t {
                found.offer((t, Weights::NONE), object as u32);
            }
        }
        self.closest(ray, t_min, found);
    }

    /// The hit record of a found (t, object, weights).
    fn hit(&self, ray: &Ray, (t, object, weights): Found) -> Hit {
        let object = object as usize;
        hit_with_weights(self.shape(object), ray, t, weights.alpha_beta(), object)
    }

    /// The closest hit with chapter 2's rule for coincident surfaces, in
    /// one walk (`rule.rs`): the nearest hit, and the first listed of the
    /// hits kept beside it that lie in its window; or, where the walk may
    /// have missed one, a second walk ([`Self::first_coincident`]).
    ///
    /// The nearest hit's record is made in the answer, read there field by
    /// field, and replaced in the rare case that another hit wins. Made
    /// aside and moved, it was read back in wider pieces than chapter 2's
    /// `hit_with_weights` had just written it (8 bytes over two writes of
    /// 4), and the decision waited for those writes to reach the cache: on
    /// balls-4 about a third of the rule's cost in time (`cargo bench --bench
    /// coincident`; book/appendix/performance.md).
    fn nearest_by_the_rule<const KEEP: usize>(
        &self,
        ray: &Ray,
        t_min: f32,
        t_max: f32,
    ) -> Option<Hit> {
        let mut prepared = PreparedRay::new(ray);
        let origin = ray.origin.abs().max_element();
        let mut found = rule::Candidates::<KEEP>::new(t_max, origin);
        self.walk(&mut prepared, t_min, &mut found);
        let mut answer = None;
        let nearest = answer.insert(self.hit(ray, found.nearest?));
        if nearest.object != 0 && !found.surely_nearest(nearest, ray) {
            *nearest = self.in_the_window(&found, &mut prepared, (t_min, t_max), nearest);
        }
        answer
    }

    /// The rule's answer for a nearest hit `nearest` (not of the first
    /// listed object) whose window may hold another hit: the first listed of
    /// the kept hits in its window, or the second walk's. Out of line: most
    /// rays do not come here.
    #[inline(never)]
    fn in_the_window<const KEEP: usize>(
        &self,
        found: &rule::Candidates<KEEP>,
        ray: &mut PreparedRay,
        (t_min, t_max): (f32, f32),
        nearest: &Hit,
    ) -> Hit {
        let nearest = *nearest;
        let range = coincident_range(&nearest, ray.ray, t_min, t_max);
        match found.first_within(nearest.object as u32, range) {
            Ok(first) => first.map_or(nearest, |first| self.hit(ray.ray, first)),
            Err(()) => self.first_coincident(ray, range, nearest),
        }
    }

    /// Chapter 2's rule for coincident surfaces (`first_coincident`), with
    /// `nearest` the nearest hit and (lower, upper) its window: a second
    /// walk through the boxes that the ray crosses in the window only.
    fn first_coincident(
        &self,
        ray: &mut PreparedRay,
        (lower, upper): (f32, f32),
        nearest: Hit,
    ) -> Hit {
        let mut first = Closest::first_before(nearest.object as u32, upper);
        for &object in self.planes.iter().filter(|&&o| o < nearest.object) {
            let t = crate::tracer::intersect(self.shape(object), ray.ray, lower, upper);
            if let Some(t) = t {
                first.offer((t, Weights::NONE), object as u32);
            }
        }
        self.closest(ray, lower, &mut first);
        first
            .found
            .map_or(nearest, |found| self.hit(ray.ray, found))
    }
}

/// How many hits beside the nearest one walk keeps for the rule: more take
/// a second walk. A ray through k coincident surfaces keeps at most k − 1,
/// and only those listed before the nearest hit of the time. (With room
/// for 8, the rule cost 1.44 times the nearest hit alone on chapter 2's
/// coincident scene, against 1.20 with 2: `cargo bench --bench
/// coincident`, one run each on a loaded machine.)
const KEEP: usize = 2;

impl World for WideBvh<'_> {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        self.nearest_by_the_rule::<KEEP>(ray, t_min, t_max)
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        let on_a_plane = self.planes.iter().any(|&object| {
            self.objects[object].shadows
                && crate::tracer::intersect(self.shape(object), ray, t_min, t_max).is_some()
        });
        on_a_plane || self.any(&mut PreparedRay::new(ray), t_min, t_max)
    }
}
