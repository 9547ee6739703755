//! Four spheres in a packet, lane by lane: the f32 test that rules out
//! rays passing too far from their centres, and what a ray's f32 numbers
//! tell before chapter 2's f64 roots (behind the origin, a sure blocker).

use glam::{BVec4A, Vec4};

use super::super::primitive::{Geometry, PreparedRay, Primitive};
use crate::toolkit::Vec3;
use crate::tracer::{Quadratic, Ray, intersect_sphere};

/// Four spheres: centres' x, y, z and radii.
#[derive(Debug, Clone, Copy)]
pub(super) struct Spheres {
    center: [Vec4; 3],
    radius: Vec4,
}

impl Spheres {
    pub(super) fn of(spheres: &[&Primitive]) -> Spheres {
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

    pub(super) fn get(&self, lane: usize) -> (Vec3, f32) {
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
    pub(super) fn might_hit(&self, ray: &PreparedRay) -> BVec4A {
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
pub(super) fn intersect_sphere_ahead(
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
pub(super) fn behind_origin(q: &Quadratic, t_min: f32) -> bool {
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
pub(super) fn surely_meets(q: &Quadratic, t_max: f32) -> bool {
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
