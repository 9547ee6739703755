//! Building the hierarchy: top-down, each node split where the surface area
//! heuristic expects the cheapest traversal, chosen among a few bins.

use crate::aabb::{Aabb, bounds};
use crate::toolkit::Vec3;
use crate::toolkit::scene::Object;

/// Candidate split planes per axis: 16 bins give 15 planes, as good as
/// trying every primitive's centre for practical scenes and much cheaper.
const BINS: usize = 16;
/// Cost of visiting a node (testing a box), relative to testing one primitive.
const TRAVERSAL_COST: f32 = 0.5;
/// A leaf never holds more than this many primitives (unless they all have
/// the same centre and cannot be told apart).
const MAX_LEAF: usize = 4;
/// Below this depth splits follow the heuristic; deeper, they halve the
/// primitives, so that no path from the root is longer than
/// [`MAX_DEPTH`](crate::MAX_DEPTH) and traversal's stack suffices.
const SAH_DEPTH: u32 = 40;

/// A primitive while building: its box, the box's centre, and its index.
#[derive(Debug, Clone, Copy)]
pub struct Item {
    pub bounds: Aabb,
    pub center: Vec3,
    pub index: usize,
}

/// A node of the flattened tree. An inner node's first child follows it in
/// the array, the second is at `start`; a leaf holds primitives
/// `start..start + count` of the reordered list.
#[derive(Debug, Clone, Copy)]
pub struct Node {
    pub bounds: Aabb,
    pub start: u32,
    /// 0 for an inner node.
    pub count: u32,
}

/// The items to build over: one for each bounded object, with its box; and
/// the indices of the unbounded ones (planes), which stay outside the tree.
pub fn items(objects: &[Object]) -> (Vec<Item>, Vec<usize>) {
    let mut items = Vec::with_capacity(objects.len());
    let mut unbounded = Vec::new();
    for (index, object) in objects.iter().enumerate() {
        match bounds(&object.shape) {
            Some(b) => items.push(Item {
                bounds: b,
                center: b.center(),
                index,
            }),
            None => unbounded.push(index),
        }
    }
    (items, unbounded)
}

/// Builds the nodes over `items`, reordering them so that every leaf's
/// primitives are contiguous.
pub fn build(items: &mut [Item]) -> Vec<Node> {
    let mut nodes = Vec::with_capacity(2 * items.len());
    if !items.is_empty() {
        build_node(&mut nodes, items, 0, 0);
    }
    nodes
}

/// Appends the subtree over `items` (which start at `offset` in the final
/// order) and returns its root's index.
fn build_node(nodes: &mut Vec<Node>, items: &mut [Item], offset: usize, depth: u32) -> usize {
    let bounds = items.iter().fold(Aabb::EMPTY, |b, i| b.union(i.bounds));
    let index = nodes.len();
    nodes.push(Node {
        bounds,
        start: offset as u32,
        count: items.len() as u32,
    });
    if let Some(mid) = split(items, &bounds, depth) {
        let (left, right) = items.split_at_mut(mid);
        build_node(nodes, left, offset, depth + 1);
        let second = build_node(nodes, right, offset + mid, depth + 1);
        nodes[index].start = second as u32;
        nodes[index].count = 0;
    }
    index
}

/// Where to split `items` (reordered so that the first part comes first),
/// or `None` to make them a leaf.
fn split(items: &mut [Item], bounds: &Aabb, depth: u32) -> Option<usize> {
    if items.len() == 1 {
        return None;
    }
    let centers = items.iter().fold(Aabb::EMPTY, |b, i| b.grow(i.center));
    let extent = centers.max - centers.min;
    let axis = extent.max_position();
    if extent[axis] <= 0.0 {
        return None; // all centres coincide: nothing tells them apart
    }
    if depth >= SAH_DEPTH {
        return Some(halve(items, axis));
    }
    let best = (0..3)
        .filter(|&axis| extent[axis] > 0.0)
        .filter_map(|axis| best_plane(items, &centers, axis))
        .min_by(|a, b| a.cost.total_cmp(&b.cost))?;
    let leaf_cost = items.len() as f32;
    let split_cost = TRAVERSAL_COST + best.cost / bounds.half_area().max(f32::MIN_POSITIVE);
    if items.len() <= MAX_LEAF && leaf_cost <= split_cost {
        return None;
    }
    let mid = partition(items, |item| {
        bin(item.center, &centers, best.axis) < best.bin
    });
    Some(mid)
}

/// A candidate split: primitives in bins below `bin` go left.
#[derive(Debug, Clone, Copy)]
struct Plane {
    axis: usize,
    bin: usize,
    /// A_left·N_left + A_right·N_right: the SAH cost without the constant
    /// factors, which are the same for every plane.
    cost: f32,
}

/// The bin of a centre along `axis`: which of [`BINS`] equal slices of the
/// centres' box it falls in.
fn bin(center: Vec3, centers: &Aabb, axis: usize) -> usize {
    let (low, size) = (centers.min[axis], centers.max[axis] - centers.min[axis]);
    let b = ((center[axis] - low) / size * BINS as f32) as usize;
    b.min(BINS - 1)
}

/// The cheapest of the planes between bins along `axis`, by the surface
/// area heuristic: cost(split) = A_L·N_L + A_R·N_R, the expected number of
/// primitive tests for a ray that crosses the node, times its area. Sweeps
/// the bins from the left and from the right to know each side's box and
/// count at every plane.
fn best_plane(items: &[Item], centers: &Aabb, axis: usize) -> Option<Plane> {
    let mut boxes = [Aabb::EMPTY; BINS];
    let mut counts = [0usize; BINS];
    for item in items {
        let b = bin(item.center, centers, axis);
        boxes[b] = boxes[b].union(item.bounds);
        counts[b] += 1;
    }
    // right[i]: area × count of bins i.. (the right side of plane i).
    let mut right = [0.0f32; BINS];
    let (mut bounds, mut count) = (Aabb::EMPTY, 0);
    for i in (1..BINS).rev() {
        bounds = bounds.union(boxes[i]);
        count += counts[i];
        right[i] = if count == 0 {
            f32::INFINITY // nothing on the right: not a split
        } else {
            bounds.half_area() * count as f32
        };
    }
    let (mut bounds, mut count) = (Aabb::EMPTY, 0);
    let mut best: Option<Plane> = None;
    for i in 1..BINS {
        bounds = bounds.union(boxes[i - 1]);
        count += counts[i - 1];
        if count == 0 || !right[i].is_finite() {
            continue;
        }
        let cost = bounds.half_area() * count as f32 + right[i];
        if best.is_none_or(|b| cost < b.cost) {
            best = Some(Plane { axis, bin: i, cost });
        }
    }
    best
}

/// Splits in the middle of the order along `axis`: two halves of equal count.
fn halve(items: &mut [Item], axis: usize) -> usize {
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |a, b| a.center[axis].total_cmp(&b.center[axis]));
    mid
}

/// Moves the items for which `left` holds to the front; returns how many.
fn partition(items: &mut [Item], left: impl Fn(&Item) -> bool) -> usize {
    let mut mid = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(i, mid);
            mid += 1;
        }
    }
    mid
}
