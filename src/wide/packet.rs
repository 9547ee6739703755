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

use glam::{BVec4A, Vec4};

use super::closest::Offer;
use super::cone::Cones;
use super::primitive::{Geometry, PreparedRay, Primitive, Weights};
use ch08_bvh::Aabb;

use crate::toolkit::Vec3;
use crate::toolkit::scene::Object;
use crate::tracer::{
    Quadratic, Ray, intersect_cone, intersect_sphere, intersect_triangle, triangle_plane_t,
};

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

/// Four spheres: centres' x, y, z and radii.
#[derive(Debug, Clone, Copy)]
struct Spheres {
    center: [Vec4; 3],
    radius: Vec4,
}

/// Four triangles: each corner's x, y, z.
#[derive(Debug, Clone, Copy)]
struct Triangles {
    corners: [[Vec4; 3]; 3],
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
fn lanes(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let lane = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            lane
        })
    })
}

impl Spheres {
    fn of(spheres: &[&Primitive]) -> Spheres {
        let mut packet = Spheres {
            center: [Vec4::ZERO; 3],
            radius: Vec4::ZERO,
        };
        for (lane, p) in spheres.iter().enumerate() {
            let Geometry::Sphere { center, radius } = p.geometry else {
                unreachable!("only spheres are packed as spheres")
            };
            for axis in 0..3 {
                packet.center[axis][lane] = center[axis];
            }
            packet.radius[lane] = radius;
        }
        packet
    }

    fn get(&self, lane: usize) -> (Vec3, f32) {
        // Lanes are read from arrays: indexing a Vec4 is a jump table.
        let [x, y, z] = self.center.map(|c| c.to_array()[lane]);
        (Vec3::new(x, y, z), self.radius.to_array()[lane])
    }

    /// Lanes whose sphere the ray may meet: all but those it passes farther
    /// from the centre than r, by a margin that covers every rounding.
    ///
    /// With f = r0 − c and rd of length 1 (up to rounding), the ray passes
    /// the centre at distance |h|, h = f − (f·rd)·rd. Computed in f32, h is
    /// off by a few units in the last place of |f| (f32::EPSILON·|f| each);
    /// 64 of them is a wide margin. So if |h| > r + 64·ε·|f|, the exact |h|
    /// exceeds r too, and so does chapter 2's (in f64, far more exact): its
    /// discriminant 4a(r² − h·h) is negative, and it answers None.
    #[inline(always)]
    fn might_hit(&self, ray: &PreparedRay) -> BVec4A {
        let [ox, oy, oz] = ray.origin;
        let [dx, dy, dz] = ray.direction;
        let (fx, fy, fz) = (
            ox - self.center[0],
            oy - self.center[1],
            oz - self.center[2],
        );
        let along = fx * dx + fy * dy + fz * dz;
        let (hx, hy, hz) = (fx - along * dx, fy - along * dy, fz - along * dz);
        let size = fx.abs().max(fy.abs()).max(fz.abs());
        let margin = self.radius + 64.0 * f32::EPSILON * size;
        (hx * hx + hy * hy + hz * hz).cmple(margin * margin)
    }
}

/// Chapter 2's `intersect_sphere`, without its divisions and square root
/// where their answer is known beforehand: for a sphere behind the ray's
/// origin ([`behind_origin`]).
#[inline(always)]
fn intersect_sphere_ahead(
    center: Vec3,
    radius: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    if behind_origin(&Quadratic::of(center, radius, ray), t_min) {
        return None;
    }
    intersect_sphere(center, radius, ray, t_min, t_max)
}

/// Is the sphere of `q` behind the ray's origin, so that chapter 2 finds
/// no root beyond t_min ≥ 0 (every ray the tracer casts)?
///
/// If `along` > 0 (the ray moves away from the centre) and `power` ≥ 0 (the
/// origin is not inside), chapter 2's q = −(along + √(…)) in
/// `sphere_roots` is negative, so both of its roots, power/q and q/|rd|²,
/// are ≤ 0 (rounding keeps their signs): neither lies beyond t_min. The
/// quantities are chapter 2's own ([`Quadratic::of`]), so the answer is its
/// answer. It is the common case of a shadow ray or a mirror ray leaving a
/// sphere, which always meets its own sphere's line.
#[inline(always)]
fn behind_origin(q: &Quadratic, t_min: f32) -> bool {
    t_min >= 0.0 && q.along > 0.0 && q.power >= 0.0
}

/// Does chapter 2's `intersect_sphere(…, t_min = 0, t_max)` find a hit,
/// where that is sure without its divisions and square root? `true` only
/// when chapter 2 answers `Some`; `false` when not sure (the caller then
/// asks chapter 2). A shadow ray needs only this yes or no, and in
/// tinyraytracer's scene nearly every shadow ray that reached chapter 2's
/// sphere test was blocked: from inside the glass ball, or from the board
/// through a ball.
///
/// With chapter 2's quantities (`q`, in f64: f = r0 − m, |f|², ρ², `along`
/// = f·rd, `power` = |f|² − ρ²), and a root t at the distance t·|rd| along
/// the ray:
/// - **From clearly inside** (power < −2⁻²⁰ρ²): the roots have opposite
///   signs, so only the far one, where the ray leaves the sphere, can lie
///   in (0, t_max). That point is at most |f| + ρ away, and (|f| + ρ)² ≤
///   2(|f|² + ρ²). So if |rd|²·t_max² > 2(|f|² + ρ²)(1 + 2⁻¹⁸), it lies
///   before t_max.
/// - **From clearly outside, towards the centre, clearly through**
///   (power > 2⁻²⁰|f|², along < 0, and the line's point closest to the
///   centre clearly inside: along² − |rd|²·power > 2⁻³⁰(along² + |rd|²|f|²),
///   since along² − |rd|²·power = |rd|²(ρ² − |h|²) with h as in
///   `sphere_roots`): both roots are positive, and the near one, where the
///   ray enters, is at most |f| away. So if
///   |rd|²·t_max² > |f|² (1 + 2⁻¹⁸), it lies before t_max.
///
/// The margins are far wider than chapter 2's rounding: its quantities and
/// roots are exact to about 2⁻⁵⁰ of |f|² or ρ² (it works in f64), then
/// rounded once to f32 (2⁻²⁴). "Clearly" inside or outside keeps the roots
/// away from 0, so that their signs, and the discriminant's, are chapter
/// 2's too, and the lower bounds on |f|² and ρ² keep the roots from
/// underflowing in f32.
#[inline(always)]
fn surely_meets(q: &Quadratic, t_max: f32) -> bool {
    const CLEARLY: f64 = 1.0 / (1u64 << 20) as f64;
    const BEYOND: f64 = 1.0 + 1.0 / (1u64 << 18) as f64;
    const THROUGH: f64 = 1.0 / (1u64 << 30) as f64;
    const TINY: f64 = 1e-60;
    let Quadratic {
        f,
        rho,
        speed2,
        along,
        power,
        ..
    } = *q;
    let (ff, rr) = (f.dot(f), rho * rho);
    let reach = speed2 * (t_max as f64 * t_max as f64);
    if ff < TINY || rr < TINY {
        return false;
    }
    if power < -CLEARLY * rr {
        return reach > 2.0 * (ff + rr) * BEYOND;
    }
    let through = along * along - speed2 * power > THROUGH * (along * along + speed2 * ff);
    power > CLEARLY * ff && along < 0.0 && through && reach > ff * BEYOND
}

/// What the four-lane triangle test found.
struct Found {
    /// Bit i: the ray passes through lane i's triangle (not on an edge).
    hit: u32,
    /// Bit i: lane i is on an edge in f32, to be decided in f64.
    on_edge: u32,
    /// The corners' x and y in the ray's space.
    x: [Vec4; 3],
    y: [Vec4; 3],
    /// The edge functions and their sum.
    u: Vec4,
    v: Vec4,
    w: Vec4,
    determinant: Vec4,
}

/// Bounds on each lane's t, as chapter 2 finds it, from the watertight
/// test's own f32 t (`Triangles::t_range`): the exact t lies in [low, high].
struct TRange {
    low: Vec4,
    high: Vec4,
}

impl TRange {
    /// Lanes whose t may lie in (t_min, t_max): all but those surely at or
    /// below t_min or at or above t_max (and a lane whose bounds are not
    /// numbers may).
    #[inline(always)]
    fn may_lie_within(&self, t_min: f32, t_max: f32) -> u32 {
        let below = self.high.cmplt(Vec4::splat(t_min));
        let beyond = self.low.cmpgt(Vec4::splat(t_max));
        !(below | beyond).bitmask() & 0b1111
    }

    /// Lanes whose t surely lies in (t_min, t_max).
    #[inline(always)]
    fn surely_within(&self, t_min: f32, t_max: f32) -> u32 {
        (self.low.cmpgt(Vec4::splat(t_min)) & self.high.cmplt(Vec4::splat(t_max))).bitmask()
    }
}

impl Found {
    fn weights(&self, lane: usize) -> Weights {
        let lane_of = |v: Vec4| v.to_array()[lane];
        Weights::new(lane_of(self.v), lane_of(self.w), lane_of(self.determinant))
    }
}

impl Triangles {
    fn of(triangles: &[&Primitive]) -> Triangles {
        let mut packet = Triangles {
            corners: [[Vec4::ZERO; 3]; 3],
        };
        for (lane, p) in triangles.iter().enumerate() {
            let Geometry::Triangle { vertices } = p.geometry else {
                unreachable!("only triangles are packed as triangles")
            };
            for (corner, vertex) in vertices.iter().enumerate() {
                for axis in 0..3 {
                    packet.corners[corner][axis][lane] = vertex[axis];
                }
            }
        }
        packet
    }

    fn get(&self, lane: usize) -> [Vec3; 3] {
        self.corners
            .map(|c| Vec3::from_array(c.map(|axis| axis.to_array()[lane])))
    }

    /// Lane `lane`'s t, as chapter 2's `intersect_triangle` finds it.
    fn t(&self, lane: usize, ray: &Ray) -> f32 {
        triangle_plane_t(self.get(lane), ray) as f32
    }

    /// Chapter 2's watertight test (`intersect_triangle`) in four lanes, up
    /// to its t ([`Triangles::t`]): the same products and sums, the same
    /// edge functions and determinant.
    #[inline(always)]
    fn intersect(&self, ray: &mut PreparedRay) -> Found {
        let shear = ray.shear();
        let [p0, p1, p2] = &self.corners;
        let (x0, y0) = shear.project4(&ray.origin, p0);
        let (x1, y1) = shear.project4(&ray.origin, p1);
        let (x2, y2) = shear.project4(&ray.origin, p2);
        let u = x2 * y1 - y2 * x1;
        let v = x0 * y2 - y0 * x2;
        let w = x1 * y0 - y1 * x0;
        let zero = Vec4::ZERO;
        let on_edge = u.cmpeq(zero) | v.cmpeq(zero) | w.cmpeq(zero);
        let negative = u.cmplt(zero) | v.cmplt(zero) | w.cmplt(zero);
        let positive = u.cmpgt(zero) | v.cmpgt(zero) | w.cmpgt(zero);
        let determinant = u + v + w;
        let inside = !(negative & positive) & determinant.cmpne(zero);
        Found {
            hit: (inside & !on_edge).bitmask(),
            on_edge: on_edge.bitmask(),
            x: [x0, x1, x2],
            y: [y0, y1, y2],
            u,
            v,
            w,
            determinant,
        }
    }

    /// Bounds on each lane's t, for the lanes the ray passes through: the
    /// watertight test's own t in f32, t = (u·z₀ + v·z₁ + w·z₂) / (u + v + w)
    /// with zᵢ the corners' distances along the ray, plus or minus a bound
    /// on its rounding error. Chapter 2's t (`triangle_plane_t`, in f64) is
    /// exact to its rounding to f32, so it lies within the bounds too.
    ///
    /// The bound is pbrt-v4's (Pharr, Jakob and Humphreys, section 6.8.7,
    /// "Avoiding Intersections behind Ray Origins", its part on triangles), with γₙ = nu/(1 − nu), u = ε/2:
    /// the corners' z are off by δz = γ₃·max|zᵢ|, their x and y by
    /// δx = γ₅(max|xᵢ| + max|p\[kz\]|) (and δy alike), the edge functions by
    /// δe = 2(γ₂·max|xᵢ|·max|yᵢ| + δy·max|xᵢ| + δx·max|yᵢ|), so t by
    ///
    /// ```text
    /// δt = 3(γ₃·max|eᵢ|·max|zᵢ| + δe·max|zᵢ| + δz·max|eᵢ|) / |u + v + w|
    /// ```
    ///
    /// Taken twice, plus γ₄|t| for the division and the sum below it: a
    /// lane's f64 t is needed only where these bounds leave it in doubt.
    #[inline(always)]
    fn t_range(&self, ray: &mut PreparedRay, found: &Found) -> TRange {
        const fn gamma(n: f32) -> f32 {
            let u = f32::EPSILON / 2.0;
            n * u / (1.0 - n * u)
        }
        let shear = ray.shear();
        let [(z0, a0), (z1, a1), (z2, a2)] = self
            .corners
            .each_ref()
            .map(|c| shear.depth4(&ray.origin, c));
        let largest = |[a, b, c]: [Vec4; 3]| a.abs().max(b.abs()).max(c.abs());
        let (max_x, max_y, max_z) = (largest(found.x), largest(found.y), largest([z0, z1, z2]));
        let max_e = largest([found.u, found.v, found.w]);
        let max_pz = a0.max(a1).max(a2);
        let delta_x = gamma(5.0) * (max_x + max_pz);
        let delta_y = gamma(5.0) * (max_y + max_pz);
        let delta_z = gamma(3.0) * max_z;
        let delta_e = 2.0 * (gamma(2.0) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let sum = gamma(3.0) * max_e * max_z + delta_e * max_z + delta_z * max_e;
        let delta_t = 3.0 * sum / found.determinant.abs();
        let t = (found.u * z0 + found.v * z1 + found.w * z2) / found.determinant;
        let bound = 2.0 * delta_t + gamma(4.0) * t.abs();
        TRange {
            low: t - bound,
            high: t + bound,
        }
    }

    /// For the debug assertions: chapter 2's t of each lane in `mask` lies
    /// outside (t_min, t_max), as the bounds said.
    fn rightly_outside(&self, mask: u32, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        lanes(mask).all(|lane| {
            let t = self.t(lane, ray);
            !(t.is_finite() && t > t_min && t < t_max)
        })
    }

    /// For the debug assertions: chapter 2's t of each lane in `mask` lies
    /// in (t_min, t_max), as the bounds said.
    fn rightly_within(&self, mask: u32, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        lanes(mask).all(|lane| {
            let t = self.t(lane, ray);
            t.is_finite() && t > t_min && t < t_max
        })
    }
}
