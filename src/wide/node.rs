//! A node of the wide BVH: four children's boxes side by side, so that one
//! slab test of four lanes (SSE on x86-64, through glam's `Vec4`) tests all
//! four at once.

use glam::Vec4;

use ch08_bvh::Aabb;

use super::primitive::PreparedRay;

/// Chapter 8's factor that makes the slab test's far distance an upper
/// bound of the exact one despite rounding (1 + 2γ₃).
const ROBUST_FAR: f32 = 1.0 + 2.0 * (3.0 * f32::EPSILON / 2.0) / (1.0 - 3.0 * f32::EPSILON / 2.0);

/// Four children: their boxes as six vectors of four lanes (min x, y, z,
/// then max x, y, z), and where each child is. 128 bytes, two cache lines.
#[derive(Debug, Clone, Copy)]
pub struct Node4 {
    bounds: [Vec4; 6],
    /// A node's index, or a leaf's first primitive.
    index: [u32; 4],
    /// A leaf's number of primitives; 0 for a node, [`EMPTY_LANE`] for none.
    count: [u32; 4],
}

const EMPTY_LANE: u32 = u32::MAX;

// Two cache lines, as the docs say.
const _: () = assert!(std::mem::size_of::<Node4>() == 128);

/// A child of a node: another node, a leaf (a run of primitives), or an
/// unused lane (whose box no ray enters).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Child {
    Node(u32),
    Leaf { start: u32, count: u32 },
    Empty,
}

impl Node4 {
    /// A node whose four lanes are empty. Chapter 8's empty box (min +∞,
    /// max −∞) is entered by no ray: whatever rd's signs, each near face is
    /// at t = +∞ and each far face at t = −∞.
    pub const EMPTY: Node4 = Node4 {
        bounds: [
            Vec4::INFINITY,
            Vec4::INFINITY,
            Vec4::INFINITY,
            Vec4::NEG_INFINITY,
            Vec4::NEG_INFINITY,
            Vec4::NEG_INFINITY,
        ],
        index: [0; 4],
        count: [EMPTY_LANE; 4],
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

    /// Chapter 8's slab test, for the four boxes at once: the t at which the
    /// ray enters each box, and a bit mask of the boxes it meets in
    /// [t_min, t_max] (bit i for lane i).
    ///
    /// The ray's direction tells which face of each slab comes first
    /// ([`Slabs::near_face`]), so the near and far distances need no
    /// min/max per slab, only across the three.
    #[inline]
    pub fn enter(&self, ray: &Slabs, t_min: f32, t_max: f32) -> (Vec4, u32) {
        let slab = |axis: usize, face: usize| {
            (self.bounds[face + axis] - ray.origin[axis]) * ray.inverse[axis]
        };
        let [nx, ny, nz] = ray.near_face;
        let near = slab(0, nx)
            .max(slab(1, ny))
            .max(slab(2, nz))
            .max(Vec4::splat(t_min));
        let far = slab(0, 3 - nx).min(slab(1, 3 - ny)).min(slab(2, 3 - nz)) * ROBUST_FAR;
        let far = far.min(Vec4::splat(t_max));
        (near, near.cmple(far).bitmask())
    }
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
    /// among a node's six bound vectors.
    near_face: [usize; 3],
}

impl Slabs {
    #[inline]
    pub fn new(ray: &PreparedRay) -> Slabs {
        let inverse = ray.ray.direction.recip();
        let face = |i: f32| if i.is_sign_negative() { 3 } else { 0 };
        Slabs {
            origin: ray.origin,
            inverse: inverse.to_array().map(Vec4::splat),
            near_face: inverse.to_array().map(face),
        }
    }
}
