//! The complete tracer's accelerator: chapter 8's BVH made four wide.
//!
//! Chapter 8 builds a binary tree and tests one box per step. This module
//! takes that same tree (the same binned-SAH build) and collapses it, two
//! levels into one, to nodes of four children; a step then tests four boxes
//! in one slab test of four lanes (`node.rs`); subtrees of up to eight
//! primitives become one leaf, so that its packets are full. Beside that:
//! - a leaf's primitives are stored in packets of four spheres or four
//!   triangles, lane by lane, and tested four at a time (`packet.rs`): only
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

mod closest;
mod cone;
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
use closest::{Closest, Found, Offer};
use node::{Child, Node4};
use packet::Packet;
use primitive::{PreparedRay, Primitive, Weights};

/// A four-wide bounding volume hierarchy over a scene's objects.
#[derive(Debug, Clone)]
pub struct WideBvh<'a> {
    objects: &'a [Object],
    /// The root is node 0 (if there is any bounded object).
    nodes: Vec<Node4>,
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
}

impl<'a> WideBvh<'a> {
    /// Builds chapter 8's binary tree over `objects` and collapses it.
    pub fn build(objects: &'a [Object]) -> WideBvh<'a> {
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
        let mut nodes = Vec::with_capacity(binary.len() / 2 + 1);
        let mut packets = Vec::with_capacity(primitives.len() / 2 + 1);
        if !binary.is_empty() {
            let mut tree = Collapse {
                spans: spans(&binary),
                lanes_before: lanes_before(&primitives),
                binary: &binary,
                primitives: &primitives,
                nodes: &mut nodes,
                packets: &mut packets,
            };
            tree.node(0);
        }
        let flat_boxes = if small {
            packets.iter().map(|p| p.bounds(objects)).collect()
        } else {
            Vec::new()
        };
        WideBvh {
            objects,
            flat: small,
            flat_boxes,
            nodes,
            packets,
            planes,
        }
    }

    /// Number of four-wide nodes.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
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

/// Chapter 8's binary tree, being collapsed into four-wide nodes and the
/// leaves' packets.
struct Collapse<'t> {
    binary: &'t [build::Node],
    /// Each binary node's primitives: (first, count).
    spans: Vec<(u32, u32)>,
    /// For each i, the packet lanes that primitives[..i] fill on their own:
    /// one for a sphere or a triangle, four for a cone (a packet of its
    /// own).
    lanes_before: Vec<u32>,
    /// In the order of the binary tree's leaves.
    primitives: &'t [Primitive],
    nodes: &'t mut Vec<Node4>,
    packets: &'t mut Vec<Packet>,
}

impl Collapse<'_> {
    /// Appends the four-wide node standing for binary node `index` and the
    /// subtree below it; returns its index.
    ///
    /// Its lanes start as the binary node's two children. While a lane
    /// holds an inner node and a lane is free, the inner child with the
    /// largest box (the one rays most often enter) is replaced by its own
    /// two children. A binary leaf at the root becomes a node with one leaf
    /// lane.
    fn node(&mut self, index: usize) -> u32 {
        let binary = self.binary;
        let at = self.nodes.len();
        self.nodes.push(Node4::EMPTY);
        let mut lanes = if self.is_leaf(index) {
            vec![index]
        } else {
            vec![index + 1, binary[index].start as usize]
        };
        while lanes.len() < 4 {
            let inner = lanes
                .iter()
                .enumerate()
                .filter(|&(_, &n)| !self.is_leaf(n))
                .max_by(|a, b| area(binary, *a.1).total_cmp(&area(binary, *b.1)));
            let Some((lane, &n)) = inner else { break };
            lanes.swap_remove(lane);
            lanes.extend([n + 1, binary[n].start as usize]);
        }
        for (lane, &n) in lanes.iter().enumerate() {
            let child = if self.is_leaf(n) {
                let (start, count) = self.spans[n];
                self.leaf(start, count)
            } else {
                Child::Node(self.node(n))
            };
            self.nodes[at].set(lane, binary[n].bounds, child);
        }
        at as u32
    }

    /// Is binary node `n` a leaf here: a leaf of chapter 8's tree, or a
    /// subtree whose primitives fill at most [`LEAF_MAX`] lanes?
    fn is_leaf(&self, n: usize) -> bool {
        let (first, count) = self.spans[n];
        let (first, end) = (first as usize, (first + count) as usize);
        self.binary[n].count > 0 || self.lanes_before[end] - self.lanes_before[first] <= LEAF_MAX
    }

    /// The packets of the binary leaf of `count` primitives from `start`.
    fn leaf(&mut self, start: u32, count: u32) -> Child {
        let first = self.packets.len();
        let (start, end) = (start as usize, (start + count) as usize);
        packet::pack(&self.primitives[start..end], self.packets);
        Child::Leaf {
            start: first as u32,
            count: (self.packets.len() - first) as u32,
        }
    }
}

/// A subtree of chapter 8's tree whose primitives fill at most this many
/// packet lanes becomes one leaf: two packets at most, if of one kind. A
/// cone fills one lane, as a sphere or a triangle does. (Why 8:
/// book/appendix/performance.md, "Profile and what it bought".)
const LEAF_MAX: u32 = 8;

/// The primitives under each node of chapter 8's tree, (first, count): a
/// subtree's are contiguous, its first child's before its second's.
fn spans(binary: &[build::Node]) -> Vec<(u32, u32)> {
    let mut spans = vec![(0, 0); binary.len()];
    // Children come after their parent: work from the end.
    for n in (0..binary.len()).rev() {
        spans[n] = match binary[n] {
            build::Node {
                count: 0, start, ..
            } => {
                let ((first, left), (second, right)) = (spans[n + 1], spans[start as usize]);
                debug_assert_eq!(
                    first + left,
                    second,
                    "a subtree's primitives are contiguous"
                );
                (first, left + right)
            }
            build::Node { start, count, .. } => (start, count),
        };
    }
    spans
}

/// The prefix sums of the lanes each primitive fills: one each (a sphere,
/// a triangle or a cone).
fn lanes_before(primitives: &[Primitive]) -> Vec<u32> {
    (0..=primitives.len() as u32).collect()
}

fn area(binary: &[build::Node], n: usize) -> f32 {
    binary[n].bounds.half_area()
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
        let nearest = self.hit(ray, found.nearest?);
        if nearest.object == 0 {
            return Some(nearest); // nothing is listed before it
        }
        let range = coincident_range(&nearest, ray, t_min, t_max);
        Some(match found.first_within(nearest.object as u32, range) {
            Ok(first) => first.map_or(nearest, |first| self.hit(ray, first)),
            Err(()) => self.first_coincident(&mut prepared, range, nearest),
        })
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
