//! A node of the wide BVH: its children's boxes side by side, lane by lane,
//! so that one slab test tests them all at once. Four lanes on every CPU
//! (SSE on x86-64, through glam's `Vec4`); eight where the CPU has AVX2
//! (`eight.rs`).

use glam::{Vec3A, Vec4};

use ch08_bvh::Aabb;

use super::primitive::PreparedRay;

/// Chapter 8's factor that makes the slab test's far distance an upper
/// bound of the exact one despite rounding (1 + 2γ₃).
pub(super) const ROBUST_FAR: f32 =
    1.0 + 2.0 * (3.0 * f32::EPSILON / 2.0) / (1.0 - 3.0 * f32::EPSILON / 2.0);

/// `W` children: their boxes as six rows of `W` lanes (min x, y, z, then
/// max x, y, z), and where each child is. Aligned to 32 bytes, so that a
/// row of eight is one aligned AVX load: four lanes take 128 bytes (two
/// cache lines), eight 256 (four).
#[derive(Debug, Clone, Copy)]
#[repr(C, align(32))]
pub struct Node<const W: usize> {
    pub(super) bounds: [[f32; W]; 6],
    /// A node's index, or a leaf's first primitive.
    index: [u32; W],
    /// A leaf's number of primitives; 0 for a node, [`EMPTY_LANE`] for none.
    count: [u32; W],
}

/// The four-wide node, tested with SSE.
pub type Node4 = Node<4>;

const EMPTY_LANE: u32 = u32::MAX;

// Two cache lines and four, as the docs say.
const _: () = assert!(std::mem::size_of::<Node<4>>() == 128);
const _: () = assert!(std::mem::size_of::<Node<8>>() == 256);

/// A child of a node: another node, a leaf (a run of primitives), or an
/// unused lane (whose box no ray enters).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Child {
    Node(u32),
    Leaf { start: u32, count: u32 },
    Empty,
}

impl<const W: usize> Node<W> {
    /// A node whose lanes are all empty. Chapter 8's empty box (min +∞,
    /// max −∞) is entered by no ray: whatever rd's signs, each near face is
    /// at t = +∞ and each far face at t = −∞.
    pub const EMPTY: Node<W> = Node {
        bounds: [
            [f32::INFINITY; W],
            [f32::INFINITY; W],
            [f32::INFINITY; W],
            [f32::NEG_INFINITY; W],
            [f32::NEG_INFINITY; W],
            [f32::NEG_INFINITY; W],
        ],
        index: [0; W],
        count: [EMPTY_LANE; W],
    };

    /// Puts `child`, with box `b`, in lane `lane`.
    pub fn set(&mut self, lane: usize, b: Aabb, child: Child) {
        for axis in 0..3 {
            self.bounds[axis][lane] = b.min[axis];
            self.bounds[3 + axis][lane] = b.max[axis];
        }
        (self.index[lane], self.count[lane]) = match child {
            Child::Node(index) => (index, 0),
            Child::Leaf { start, count } => (start, count),
            Child::Empty => (0, EMPTY_LANE),
        };
    }

    /// The child in lane `lane`.
    #[inline]
    pub fn child(&self, lane: usize) -> Child {
        match self.count[lane] {
            0 => Child::Node(self.index[lane]),
            EMPTY_LANE => Child::Empty,
            count => Child::Leaf {
                start: self.index[lane],
                count,
            },
        }
    }
}

/// Chapter 8's slab test for all `W` boxes of a node at once, with what it
/// needs of the ray worked out once per walk: [`Slabs`] for four lanes,
/// `eight::Slabs8` for eight.
pub trait SlabTest<const W: usize> {
    /// The t at which the ray enters each box, and a bit mask of the boxes
    /// it meets in [t_min, t_max] (bit i for lane i).
    fn enter(&self, node: &Node<W>, t_min: f32, t_max: f32) -> ([f32; W], u32);
}

/// What the slab test needs of a ray, worked out once for all the nodes it
/// visits, each coordinate in all four lanes.
#[derive(Debug, Clone, Copy)]
pub struct Slabs {
    origin: [Vec4; 3],
    /// 1/rd per coordinate (±∞ where rd has a zero).
    inverse: [Vec4; 3],
    /// For each axis, 0 if rd points up that axis (the box's min face is
    /// met first), 3 if down (the max face is): where the near planes are
    /// among a node's six bound rows.
    pub(super) near_face: [usize; 3],
}

impl Slabs {
    #[inline]
    pub fn new(ray: &PreparedRay) -> Slabs {
        let inverse = ray.ray.direction.recip();
        Slabs {
            origin: ray.origin,
            inverse: inverse.to_array().map(Vec4::splat),
            near_face: near_faces(inverse),
        }
    }
}

/// [`Slabs::near_face`] for a ray whose 1/rd is `inverse`.
#[inline]
pub(super) fn near_faces(inverse: Vec3A) -> [usize; 3] {
    let face = |i: f32| if i.is_sign_negative() { 3 } else { 0 };
    inverse.to_array().map(face)
}

impl SlabTest<4> for Slabs {
    /// Chapter 8's slab test, for the four boxes at once.
    ///
    /// The ray's direction tells which face of each slab comes first
    /// ([`Slabs::near_face`]), so the near and far distances need no
    /// min/max per slab, only across the three. Always inlined into the
    /// walks, as in one function with them before they were generic.
    #[inline(always)]
    fn enter(&self, node: &Node<4>, t_min: f32, t_max: f32) -> ([f32; 4], u32) {
        let slab = |axis: usize, face: usize| {
            (Vec4::from_array(node.bounds[face + axis]) - self.origin[axis]) * self.inverse[axis]
        };
        let [nx, ny, nz] = self.near_face;
        let near = slab(0, nx)
            .max(slab(1, ny))
            .max(slab(2, nz))
            .max(Vec4::splat(t_min));
        let far = slab(0, 3 - nx).min(slab(1, 3 - ny)).min(slab(2, 3 - nz)) * ROBUST_FAR;
        let far = far.min(Vec4::splat(t_max));
        // An array, since indexing a Vec4 is a jump table.
        (near.to_array(), near.cmple(far).bitmask())
    }
}
