//! Eight lanes where the CPU has them: a shadow ray's walk that tests the
//! boxes of two nodes (eight children) in one slab test of eight AVX lanes.
//!
//! Why two nodes of the four-wide tree, and only for shadow rays: a shadow
//! ray asks whether *any* primitive blocks it, so the order in which nodes
//! are visited cannot change its answer, and the two nodes on top of the
//! stack can be tested together. (The closest hit visits the nearest box
//! first; testing two nodes at once would change that order, and an
//! eight-wide tree or eight-primitive leaves need a tree built for them.)
//!
//! The slab test is chapter 8's, lane for lane the same operations as
//! [`Node4::enter`] in the same order (max, min, the robust far factor, a
//! `<=` compare), so every lane's answer is the same bit, and a shadow ray
//! the same answer, as on the four-wide path.
//!
//! Chosen at run time with `std::arch`'s `is_x86_feature_detected!` rather
//! than a crate: one feature, one function, and the standard library's
//! check is cached and costs a load; `RAYBOOK_NO_AVX2=1` forces the
//! four-wide path on a CPU that has AVX2.

use std::arch::x86_64::{
    __m256, _CMP_LE_OQ, _mm256_cmp_ps, _mm256_max_ps, _mm256_min_ps, _mm256_movemask_ps,
    _mm256_mul_ps, _mm256_set_m128, _mm256_set1_ps, _mm256_sub_ps,
};

use arrayvec::ArrayVec;
use ch08_bvh::MAX_DEPTH;

use super::WideBvh;
use super::node::{Child, Node4, ROBUST_FAR, Slabs};
use super::primitive::PreparedRay;
use super::traverse::blocks;

/// Is the eight-lane walk to be used? AVX2 on this CPU, and the variable
/// `RAYBOOK_NO_AVX2` unset (CI sets it to check the fallback's bytes).
pub fn available() -> bool {
    std::env::var_os("RAYBOOK_NO_AVX2").is_none() && std::is_x86_feature_detected!("avx2")
}

/// Room for the nodes still to visit: a step pops two and pushes at most
/// eight; a step is taken only while eight fit, else one node is tested.
const STACK: usize = 8 * MAX_DEPTH + 8;

impl WideBvh<'_> {
    /// [`any_in_tree`](WideBvh::any) with two nodes' boxes tested at once.
    ///
    /// # Safety
    /// The CPU must have AVX2 ([`available`]).
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn any_in_tree_eight(
        &self,
        ray: &mut PreparedRay,
        t_min: f32,
        t_max: f32,
    ) -> bool {
        let slabs = Slabs::new(ray);
        let wide = Slabs8::new(&slabs);
        let mut stack = ArrayVec::<u32, STACK>::new();
        stack.push(0);
        while let Some(first) = stack.pop() {
            let a = &self.nodes[first as usize];
            let (b, mut mask) = match stack.last() {
                Some(&second) if stack.remaining_capacity() >= 7 => {
                    stack.pop();
                    let b = &self.nodes[second as usize];
                    (b, enter_pair(a, b, &wide, t_min, t_max))
                }
                _ => (a, a.enter(&slabs, t_min, t_max).1),
            };
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let child = if lane < 4 {
                    a.child(lane)
                } else {
                    b.child(lane - 4)
                };
                match child {
                    Child::Node(child) => stack.push(child),
                    Child::Leaf { start, count } => {
                        let (start, end) = (start as usize, (start + count) as usize);
                        if blocks(&self.packets[start..end], ray, t_min, t_max) {
                            return true;
                        }
                    }
                    Child::Empty => {}
                }
            }
        }
        false
    }
}

/// A ray's origin and 1/rd in all eight lanes.
struct Slabs8 {
    origin: [__m256; 3],
    inverse: [__m256; 3],
    near_face: [usize; 3],
}

impl Slabs8 {
    #[target_feature(enable = "avx2")]
    fn new(slabs: &Slabs) -> Slabs8 {
        let splat = |v: [glam::Vec4; 3]| v.map(|lanes| _mm256_set1_ps(lanes.x));
        Slabs8 {
            origin: splat(slabs.origin),
            inverse: splat(slabs.inverse),
            near_face: slabs.near_face,
        }
    }
}

/// Chapter 8's slab test for the eight boxes of `a` (bits 0 to 3) and `b`
/// (bits 4 to 7): bit i set if the ray meets box i in [t_min, t_max].
#[target_feature(enable = "avx2")]
#[inline]
fn enter_pair(a: &Node4, b: &Node4, ray: &Slabs8, t_min: f32, t_max: f32) -> u32 {
    let bound = |face: usize| _mm256_set_m128(b.bounds[face].into(), a.bounds[face].into());
    let slab = |axis: usize, face: usize| {
        _mm256_mul_ps(
            _mm256_sub_ps(bound(face + axis), ray.origin[axis]),
            ray.inverse[axis],
        )
    };
    let [nx, ny, nz] = ray.near_face;
    let near = _mm256_max_ps(slab(0, nx), slab(1, ny));
    let near = _mm256_max_ps(_mm256_max_ps(near, slab(2, nz)), _mm256_set1_ps(t_min));
    let far = _mm256_min_ps(slab(0, 3 - nx), slab(1, 3 - ny));
    let far = _mm256_mul_ps(
        _mm256_min_ps(far, slab(2, 3 - nz)),
        _mm256_set1_ps(ROBUST_FAR),
    );
    let far = _mm256_min_ps(far, _mm256_set1_ps(t_max));
    _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(near, far)) as u32
}
