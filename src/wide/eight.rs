//! The eight-wide tree's slab test and walks, for CPUs with AVX2.
//!
//! A node of eight children keeps each bound of its eight boxes in a row of
//! eight f32 (`Node<8>`, 32-byte aligned), so one slab plane of all eight
//! boxes is one AVX load; collapsed to eight lanes, about three levels of
//! chapter 8's tree make one node (two in the four-wide tree), so a ray
//! takes fewer steps, each testing twice the boxes in as many instructions.
//!
//! The slab test does [`Slabs`](super::node::Slabs)'s operations, lane for lane and in the same
//! order (sub, mul, the max and min chains, the robust far factor, `<=`),
//! so each box's "entered" and near t are the same bits as in four lanes.
//! Not fused (no FMA): a fused multiply-add rounds once, not twice.
//!
//! The walks are [`traverse`](super::traverse)'s, compiled for AVX2 by
//! `#[target_feature]`; they run only where `is_x86_feature_detected!`
//! found AVX2 (`Width::detect`), through `std::arch`: one feature and one
//! check per tree, for which a dispatch crate would add a dependency and
//! nothing else.

use std::arch::x86_64::{
    __m256, _CMP_LE_OQ, _mm256_cmp_ps, _mm256_load_ps, _mm256_max_ps, _mm256_min_ps,
    _mm256_movemask_ps, _mm256_mul_ps, _mm256_set1_ps, _mm256_storeu_ps, _mm256_sub_ps,
};

use super::closest::Offer;
use super::node::{Node, ROBUST_FAR, SlabTest, near_faces};
use super::packet::Packet;
use super::primitive::PreparedRay;
use super::traverse::{any_in_tree, closest_in_tree, stack_room};

/// Does this CPU have AVX2?
pub fn has_avx2() -> bool {
    std::is_x86_feature_detected!("avx2")
}

/// [`closest_in_tree`] over the eight-wide tree.
///
/// Safe to call only where [`has_avx2`] (the tree is built eight wide only
/// there): the `unsafe` below relies on it.
#[inline(never)]
pub(super) fn closest_in_tree8(
    nodes: &[Node<8>],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    closest: &mut impl Offer,
) {
    debug_assert!(has_avx2());
    // SAFETY: an eight-wide tree is built only where the CPU has AVX2.
    unsafe { closest_avx2(nodes, packets, ray, t_min, closest) }
}

/// [`any_in_tree`] over the eight-wide tree; as [`closest_in_tree8`].
#[inline(never)]
pub(super) fn any_in_tree8(
    nodes: &[Node<8>],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    t_max: f32,
) -> bool {
    debug_assert!(has_avx2());
    // SAFETY: as in closest_in_tree8.
    unsafe { any_avx2(nodes, packets, ray, t_min, t_max) }
}

#[target_feature(enable = "avx2")]
fn closest_avx2(
    nodes: &[Node<8>],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    closest: &mut impl Offer,
) {
    let slabs = Slabs8::new(ray);
    closest_in_tree::<8, { stack_room(8) }>(nodes, packets, &slabs, ray, t_min, closest);
}

#[target_feature(enable = "avx2")]
fn any_avx2(
    nodes: &[Node<8>],
    packets: &[Packet],
    ray: &mut PreparedRay,
    t_min: f32,
    t_max: f32,
) -> bool {
    let slabs = Slabs8::new(ray);
    any_in_tree::<8, { stack_room(8) }>(nodes, packets, &slabs, ray, t_min, t_max)
}

/// What the slab test needs of a ray, as [`Slabs`](super::node::Slabs)
/// but in eight lanes. Made only in a function compiled for AVX2, so that
/// one exists only where the CPU has it.
#[derive(Debug, Clone, Copy)]
pub struct Slabs8 {
    origin: [__m256; 3],
    inverse: [__m256; 3],
    near_face: [usize; 3],
}

impl Slabs8 {
    #[target_feature(enable = "avx2")]
    fn new(ray: &PreparedRay) -> Slabs8 {
        let inverse = ray.ray.direction.recip();
        Slabs8 {
            origin: ray.ray.origin.to_array().map(|o| _mm256_set1_ps(o)),
            inverse: inverse.to_array().map(|i| _mm256_set1_ps(i)),
            near_face: near_faces(inverse),
        }
    }

    /// Chapter 8's slab test for a node's eight boxes (see the module's
    /// docs for why its bits are the four-lane test's).
    #[target_feature(enable = "avx2")]
    #[inline]
    fn enter_avx2(&self, node: &Node<8>, t_min: f32, t_max: f32) -> ([f32; 8], u32) {
        let slab = |axis: usize, face: usize| {
            // SAFETY: a row is 32 bytes at a 32-byte boundary (Node's repr).
            let plane = unsafe { _mm256_load_ps(node.bounds[face + axis].as_ptr()) };
            _mm256_mul_ps(_mm256_sub_ps(plane, self.origin[axis]), self.inverse[axis])
        };
        let [nx, ny, nz] = self.near_face;
        let near = _mm256_max_ps(slab(0, nx), slab(1, ny));
        let near = _mm256_max_ps(near, slab(2, nz));
        let near = _mm256_max_ps(near, _mm256_set1_ps(t_min));
        let far = _mm256_min_ps(slab(0, 3 - nx), slab(1, 3 - ny));
        let far = _mm256_min_ps(far, slab(2, 3 - nz));
        let far = _mm256_mul_ps(far, _mm256_set1_ps(ROBUST_FAR));
        let far = _mm256_min_ps(far, _mm256_set1_ps(t_max));
        let mask = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LE_OQ>(near, far)) as u32;
        let mut lanes = [0.0; 8];
        // SAFETY: `lanes` has room for eight f32.
        unsafe { _mm256_storeu_ps(lanes.as_mut_ptr(), near) };
        (lanes, mask)
    }
}

impl SlabTest<8> for Slabs8 {
    /// [`Slabs8::enter_avx2`]; inlined into the walks compiled for AVX2.
    #[inline(always)]
    fn enter(&self, node: &Node<8>, t_min: f32, t_max: f32) -> ([f32; 8], u32) {
        // SAFETY: a Slabs8 is made only where the CPU has AVX2.
        unsafe { self.enter_avx2(node, t_min, t_max) }
    }
}
