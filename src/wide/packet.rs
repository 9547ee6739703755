//! A leaf's primitives in packets of four of one kind, stored lane by lane
//! ("structure of arrays"), so that one test in four lanes (SSE on x86-64,
//! through glam's `Vec4`) tests four spheres, triangles or cones at once.
//!
//! The four-lane tests do the scalar tests' operations in the same order in
//! each lane, so each lane's answer is the scalar test's to the last bit:
//! - four triangles go through chapter 2's watertight test together, up to
//!   the barycentric weights; a lane the ray passes through gets its t from
//!   chapter 2's `triangle_plane_t` (in f64, one lane at a time), unless the
//!   test's own f32 t, with its error bound, puts it surely outside the
//!   range looked in (or, for a shadow ray, surely inside), and a lane
//!   on an edge in f32 (an edge function exactly 0, which chapter 2 decides
//!   again in f64) goes alone through chapter 2's `intersect_triangle`;
//! - four spheres go through the f32 test that rules out rays that pass
//!   too far from the centre ([`might_hit`](Spheres::might_hit)); of the
//!   few lanes left, a sphere behind the ray's origin has no root ahead
//!   ([`intersect_sphere_ahead`]), a shadow ray's blocker is often sure
//!   without solving ([`surely_meets`]), and the others go one by one
//!   through chapter 2's f64 test;
//! - four cones go through the f32 test that rules out rays that pass
//!   their axes too far away ([`might_hit`](Cones::might_hit), `cone.rs`),
//!   and the lanes left one by one through chapter 2's f64 test.

mod spheres;
mod triangles;

use super::closest::Offer;
use super::cone::Cones;
use super::primitive::{Geometry, PreparedRay, Primitive, Weights};
use ch08_bvh::Aabb;
use spheres::{Spheres, behind_origin, intersect_sphere_ahead, surely_meets};
use triangles::Triangles;

use crate::toolkit::scene::Object;
use crate::tracer::{Quadratic, intersect_cone, intersect_sphere, intersect_triangle};

/// Up to four primitives of one kind, and which scene objects they are.
#[derive(Debug, Clone, Copy)]
pub struct Packet {
    shapes: Shapes,
    /// Each lane's index in the scene's objects.
    object: [u32; 4],
    /// Bit i: lane i holds a primitive.
    used: u32,
    /// Bit i: lane i's primitive blocks shadow rays.
    shadows: u32,
}

// Three cache lines, as the table of bytes per object in book/appendix/performance.md gives: 48
// bytes an object in a full packet.
const _: () = assert!(std::mem::size_of::<Packet>() == 192);

/// A packet's geometry, lane by lane.
#[derive(Debug, Clone, Copy)]
enum Shapes {
    Spheres(Spheres),
    Triangles(Triangles),
    Cones(Cones),
}

/// Appends the packets of a leaf's `primitives` to `packets`: spheres four
/// at a time, then triangles four at a time, then cones. (The order
/// within a leaf changes no answer: the closest hit is chosen by t, then by
/// object index.)
pub fn pack(primitives: &[Primitive], packets: &mut Vec<Packet>) {
    let is_sphere = |p: &&Primitive| matches!(p.geometry, Geometry::Sphere { .. });
    let is_triangle = |p: &&Primitive| matches!(p.geometry, Geometry::Triangle { .. });
    let is_cone = |p: &&Primitive| matches!(p.geometry, Geometry::Cone { .. });
    let spheres: Vec<_> = primitives.iter().filter(is_sphere).collect();
    let triangles: Vec<_> = primitives.iter().filter(is_triangle).collect();
    let cones: Vec<_> = primitives.iter().filter(is_cone).collect();
    for four in spheres.chunks(4) {
        packets.push(Packet::of(four, Shapes::Spheres(Spheres::of(four))));
    }
    for four in triangles.chunks(4) {
        packets.push(Packet::of(four, Shapes::Triangles(Triangles::of(four))));
    }
    for four in cones.chunks(4) {
        packets.push(Packet::of(four, Shapes::Cones(Cones::of(four))));
    }
}

impl Packet {
    /// The box around the packet's primitives (chapter 8's boxes, padded),
    /// to test before it in a small scene's one leaf; `None` for spheres,
    /// whose f32 test costs no more than a box's (with a box too,
    /// tinyraytracer's scene took 1.05 times longer).
    pub fn bounds(&self, objects: &[Object]) -> Option<Aabb> {
        if let Shapes::Spheres(_) = self.shapes {
            return None;
        }
        let shape = |lane: usize| &objects[self.object[lane] as usize].shape;
        let boxes = lanes(self.used).filter_map(|lane| ch08_bvh::bounds(shape(lane)));
        Some(boxes.fold(Aabb::EMPTY, Aabb::union))
    }

    /// The scene objects of a packet of triangles, lane by lane; `None`
    /// for other kinds (`behind.rs` tests their planes).
    pub fn triangle_objects(&self) -> Option<impl Iterator<Item = u32> + '_> {
        let Shapes::Triangles(_) = self.shapes else {
            return None;
        };
        Some(lanes(self.used).map(|lane| self.object[lane]))
    }

    fn of(primitives: &[&Primitive], shapes: Shapes) -> Packet {
        let mut packet = Packet {
            shapes,
            object: [0; 4],
            used: 0,
            shadows: 0,
        };
        for (lane, p) in primitives.iter().enumerate() {
            packet.object[lane] = p.object;
            packet.used |= 1 << lane;
            packet.shadows |= u32::from(p.shadows) << lane;
        }
        packet
    }

    /// Offers `closest` each primitive the ray meets in (t_min,
    /// closest.limit()), the limit asked again before each offer: chapter
    /// 2's answers, lane by lane.
    #[inline(always)]
    pub fn offer_hits(&self, ray: &mut PreparedRay, t_min: f32, closest: &mut impl Offer) {
        match &self.shapes {
            Shapes::Spheres(spheres) => {
                for lane in lanes(spheres.might_hit(ray).bitmask() & self.used) {
                    let (center, radius) = spheres.get(lane);
                    if let Some(t) =
                        intersect_sphere_ahead(center, radius, ray.ray, t_min, closest.limit())
                    {
                        closest.offer((t, Weights::NONE), self.object[lane]);
                    }
                }
            }
            Shapes::Triangles(triangles) => {
                let found = triangles.intersect(ray);
                let through = found.hit & self.used;
                if through != 0 {
                    let range = triangles.t_range(ray, &found);
                    let maybe = range.may_lie_within(t_min, closest.limit()) & through;
                    debug_assert!(triangles.rightly_outside(
                        through & !maybe,
                        ray.ray,
                        t_min,
                        closest.limit()
                    ));
                    for lane in lanes(maybe) {
                        let t = triangles.t(lane, ray.ray);
                        if t.is_finite() && t > t_min && t < closest.limit() {
                            closest.offer((t, found.weights(lane)), self.object[lane]);
                        }
                    }
                }
                for lane in lanes(found.on_edge & self.used) {
                    let corners = triangles.get(lane);
                    if let Some((t, alpha, beta)) =
                        intersect_triangle(corners, ray.ray, t_min, closest.limit())
                    {
                        closest.offer((t, Weights::new(alpha, beta, 1.0)), self.object[lane]);
                    }
                }
            }
            Shapes::Cones(cones) => {
                for lane in lanes(cones.might_hit(ray).bitmask() & self.used) {
                    let (base, base_radius, apex, apex_radius) = cones.get(lane);
                    let limit = closest.limit();
                    if let Some(t) =
                        intersect_cone(base, base_radius, apex, apex_radius, ray.ray, t_min, limit)
                    {
                        closest.offer((t, Weights::NONE), self.object[lane]);
                    }
                }
            }
        }
    }

    /// Does one of the packet's shadow-casting primitives meet the ray in
    /// (t_min, t_max)?
    #[inline(always)]
    pub fn blocks(&self, ray: &mut PreparedRay, t_min: f32, t_max: f32) -> bool {
        let casting = self.used & self.shadows;
        if casting == 0 {
            return false;
        }
        match &self.shapes {
            Shapes::Spheres(spheres) => {
                // A loop, not `any`: that compiled to a call per shadow ray.
                for lane in lanes(spheres.might_hit(ray).bitmask() & casting) {
                    let (center, radius) = spheres.get(lane);
                    let quadratic = Quadratic::of(center, radius, ray.ray);
                    // Behind first: a shadow ray leaving its own sphere
                    // (where `surely_meets` could only answer no).
                    if behind_origin(&quadratic, t_min) {
                        continue;
                    }
                    if (t_min == 0.0 && surely_meets(&quadratic, t_max))
                        || intersect_sphere(center, radius, ray.ray, t_min, t_max).is_some()
                    {
                        return true;
                    }
                }
                false
            }
            Shapes::Triangles(triangles) => {
                let found = triangles.intersect(ray);
                let through = found.hit & casting;
                if through != 0 {
                    let range = triangles.t_range(ray, &found);
                    let surely = range.surely_within(t_min, t_max) & through;
                    debug_assert!(triangles.rightly_within(surely, ray.ray, t_min, t_max));
                    let maybe = range.may_lie_within(t_min, t_max) & through;
                    debug_assert!(triangles.rightly_outside(
                        through & !maybe,
                        ray.ray,
                        t_min,
                        t_max
                    ));
                    let within = |t: f32| t.is_finite() && t > t_min && t < t_max;
                    if surely != 0 || lanes(maybe).any(|lane| within(triangles.t(lane, ray.ray))) {
                        return true;
                    }
                }
                lanes(found.on_edge & casting).any(|lane| {
                    intersect_triangle(triangles.get(lane), ray.ray, t_min, t_max).is_some()
                })
            }
            Shapes::Cones(cones) => lanes(cones.might_hit(ray).bitmask() & casting).any(|lane| {
                let (base, base_radius, apex, apex_radius) = cones.get(lane);
                intersect_cone(base, base_radius, apex, apex_radius, ray.ray, t_min, t_max)
                    .is_some()
            }),
        }
    }
}

/// The lanes whose bits are set in `mask`, lowest first.
#[inline(always)]
pub(super) fn lanes(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let lane = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            lane
        })
    })
}
