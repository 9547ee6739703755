//! Walking the wide tree: nearest boxes first for the closest hit, any
//! order for a shadow ray's blocker. The walks are written once for nodes
//! of any width `W`; the four-wide tree's are here, the eight-wide tree's
//! (the same walks, compiled for AVX2) in `eight.rs`.

use arrayvec::ArrayVec;
use ch08_bvh::MAX_DEPTH;

use super::closest::Offer;
use super::node::{Child, Node, Node4, SlabTest, Slabs};
use super::packet::Packet;
use super::primitive::PreparedRay;
use super::{Tree, WideBvh};

/// Room for the lanes still to visit in a tree of `W` lanes: each level
/// down pops one entry and pushes at most `W`, and no path is longer than
/// chapter 8's tree's.
pub(super) const fn stack_room(w: usize) -> usize {
    (w - 1) * MAX_DEPTH + w
}

impl WideBvh<'_> {
    /// Offers `closest` every primitive hit in the boxes the ray enters
    /// before the closest hit found so far, nearer boxes first.
    pub(super) fn closest(&self, ray: &mut PreparedRay, t_min: f32, closest: &mut impl Offer) {
        if self.flat {
            return self.offer_flat(ray, t_min, closest);
        }
        match &self.tree {
            Tree::Four(nodes) if !nodes.is_empty() => {
                closest_in_tree4(nodes, &self.packets, ray, t_min, closest);
            }
            #[cfg(target_arch = "x86_64")]
            Tree::Eight(nodes) if !nodes.is_empty() => {
                super::eight::closest_in_tree8(nodes, &self.packets, ray, t_min, closest);
            }
            _ => {}
        }
    }

    /// Is there a shadow-casting primitive on the ray in (t_min, t_max)?
    /// The first one found ends the search.
    pub(super) fn any(&self, ray: &mut PreparedRay, t_min: f32, t_max: f32) -> bool {
        if self.flat {
            return self.blocks_flat(ray, t_min, t_max);
        }
        match &self.tree {
            Tree::Four(nodes) if !nodes.is_empty() => {
                any_in_tree4(nodes, &self.packets, ray, t_min, t_max)
            }
            #[cfg(target_arch = "x86_64")]
            Tree::Eight(nodes) if !nodes.is_empty() => {
                super::eight::any_in_tree8(nodes, &self.packets, ray, t_min, t_max)
            }
            _ => false,
        }
    }

    /// A small scene's [`closest`](Self::closest): every packet in turn,
    /// spheres first (so that their hits shorten the ray), the others only
    /// if the ray enters their box before the closest hit so far.
    fn offer_flat(&self, ray: &mut PreparedRay, t_min: f32, closest: &mut impl Offer) {
        let (origin, inverse) = (ray.ray.origin, ray.ray.direction.recip());
        for (packet, bounds) in self.packets.iter().zip(&self.flat_boxes) {
            if bounds.is_none_or(|b| b.entry(origin, inverse, t_min, closest.limit()).is_some()) {
                packet.offer_hits(ray, t_min, closest);
            }
        }
    }

    /// A small scene's [`any`](Self::any): every packet whose box (if it
    /// has one) the ray enters, and of which, if triangles, one plane at
    /// least is ahead of the ray (`behind.rs`: a shadow ray leaving a
    /// triangle skips its packet so).
    fn blocks_flat(&self, ray: &mut PreparedRay, t_min: f32, t_max: f32) -> bool {
        let (origin, inverse) = (ray.ray.origin, ray.ray.direction.recip());
        let flat = self.flat_boxes.iter().zip(&self.flat_planes);
        for (packet, (bounds, planes)) in self.packets.iter().zip(flat) {
            if bounds.is_none_or(|b| b.entry(origin, inverse, t_min, t_max).is_some())
                && !planes
                    .as_ref()
                    .is_some_and(|p| p.all_behind(ray.ray, t_min))
                && packet.blocks(ray, t_min, t_max)
            {
                return true;
            }
        }
        false
    }
}

/// [`closest_in_tree`] over the four-wide tree. Not inlined: its stack
/// would make every caller's frame several kilobytes, a small scene's too.
#[inline(never)]
fn closest_in_tree4(
    nodes: &[Node4],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    closest: &mut impl Offer,
) {
    let slabs = Slabs::new(ray);
    closest_in_tree::<4, { stack_room(4) }>(nodes, packets, &slabs, ray, t_min, closest);
}

/// [`any_in_tree`] over the four-wide tree; not inlined, as
/// [`closest_in_tree4`].
#[inline(never)]
fn any_in_tree4(
    nodes: &[Node4],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    t_max: f32,
) -> bool {
    let slabs = Slabs::new(ray);
    any_in_tree::<4, { stack_room(4) }>(nodes, packets, &slabs, ray, t_min, t_max)
}

/// [`WideBvh::closest`] walking a tree of `W` lanes from its root, node 0,
/// with room for `STACK` lanes still to visit ([`stack_room`]).
///
/// Always inlined into the walk of a given width, so that it is compiled
/// with that walk's instruction set (AVX2 for eight lanes).
#[inline(always)]
pub(super) fn closest_in_tree<const W: usize, const STACK: usize>(
    nodes: &[Node<W>],
    packets: &[Packet],
    slabs: &impl SlabTest<W>,
    ray: &mut PreparedRay,
    t_min: f32,
    closest: &mut impl Offer,
) {
    let mut stack = ArrayVec::<(Child, f32), STACK>::new();
    stack.push((Child::Node(0), t_min));
    while let Some((child, t_entry)) = stack.pop() {
        if t_entry > closest.limit() {
            continue; // a hit nearer than this box was found meanwhile
        }
        match child {
            Child::Node(index) => {
                let node = &nodes[index as usize];
                push_nearest_last(node, slabs, t_min, closest.limit(), &mut stack);
            }
            Child::Leaf { start, count } => {
                let (start, end) = (start as usize, (start + count) as usize);
                offer_leaf(&packets[start..end], ray, t_min, closest);
            }
            Child::Empty => {}
        }
    }
}

/// [`WideBvh::any`] walking a tree of `W` lanes; inlined as
/// [`closest_in_tree`].
#[inline(always)]
pub(super) fn any_in_tree<const W: usize, const STACK: usize>(
    nodes: &[Node<W>],
    packets: &[Packet],
    slabs: &impl SlabTest<W>,
    ray: &mut PreparedRay,
    t_min: f32,
    t_max: f32,
) -> bool {
    let mut stack = ArrayVec::<u32, STACK>::new();
    stack.push(0);
    while let Some(index) = stack.pop() {
        let node = &nodes[index as usize];
        let (_, mut mask) = slabs.enter(node, t_min, t_max);
        while mask != 0 {
            let lane = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            match node.child(lane) {
                Child::Node(child) => stack.push(child),
                Child::Leaf { start, count } => {
                    let (start, end) = (start as usize, (start + count) as usize);
                    if blocks(&packets[start..end], ray, t_min, t_max) {
                        return true;
                    }
                }
                Child::Empty => {}
            }
        }
    }
    false
}

/// Offers `closest` the hits of a leaf's packets. Always inlined, as the
/// walks are (left to itself, the compiler keeps it out of line in them).
#[inline(always)]
fn offer_leaf(packets: &[Packet], ray: &mut PreparedRay, t_min: f32, closest: &mut impl Offer) {
    for packet in packets {
        packet.offer_hits(ray, t_min, closest);
    }
}

/// Does a primitive of `packets` cast a shadow on the ray in (t_min, t_max)?
/// Always inlined, as [`offer_leaf`].
#[inline(always)]
fn blocks(packets: &[Packet], ray: &mut PreparedRay, t_min: f32, t_max: f32) -> bool {
    // A loop, not `Iterator::any`, which stayed a call of its own.
    for packet in packets {
        if packet.blocks(ray, t_min, t_max) {
            return true;
        }
    }
    false
}

/// Pushes the lanes of `node` that the ray enters in [t_min, limit], the
/// farthest first, so that the nearest is visited next and its hits can
/// rule out the others.
///
/// The lanes go onto the stack as they come, then the (at most `W`) new
/// entries are put in order where they are, by insertion sort.
///
/// Always inlined into the walk: left to itself, the compiler keeps it out
/// of line since the walk offers the rule's hits (`rule.rs`), and the call
/// was a fifth of the closest hit's time (book/appendix/performance.md).
#[inline(always)]
fn push_nearest_last<const W: usize, const STACK: usize>(
    node: &Node<W>,
    ray: &impl SlabTest<W>,
    t_min: f32,
    limit: f32,
    stack: &mut ArrayVec<(Child, f32), STACK>,
) {
    let (near, mut mask) = ray.enter(node, t_min, limit);
    let first = stack.len();
    while mask != 0 {
        let lane = mask.trailing_zeros() as usize;
        mask &= mask - 1;
        stack.push((node.child(lane), near[lane]));
    }
    let entered = &mut stack[first..];
    for i in 1..entered.len() {
        let mut j = i;
        while j > 0 && entered[j - 1].1 < entered[j].1 {
            entered.swap(j - 1, j);
            j -= 1;
        }
    }
}
