//! The stable quadratic of a ray and a sphere: the lecture's roots,
//! computed so that they stay right for a small sphere far away and a huge
//! sphere close by (README, *When the numbers get hard: the stable
//! quadratic*). It is kept apart from `sphere.rs`, where the lecture's
//! quadratic is an exercise: this is what comes after it, with the test
//! that shows why.

use crate::Ray;
use crate::toolkit::{DVec3, Vec3};

/// Both distances at which the ray's line meets the sphere, nearest first,
/// or `None` if it passes by: the same roots as
/// [`sphere_roots_abc`](crate::sphere_roots_abc), computed
/// so that they stay right for a small sphere far away and for a huge sphere
/// close by. The tracer uses this one.
///
/// Both steps of the lecture's formula lose their digits to cancellation
/// in f32 (README, *When the numbers get hard: the stable quadratic*), so
/// this one is computed from the geometric quantities of [`Quadratic`]:
/// * Whether the line meets the sphere: the lecture's discriminant
///   subtracts two nearly equal large numbers when the sphere is far away
///   and small. The same sign comes from ρ² − |h|², where h goes from the
///   centre to the point of the ray's line closest to it: the line meets
///   the sphere when that point is inside. Both are small, so nothing large
///   cancels.
/// * Where: the root of the larger size is computed without cancellation
///   (q / |rd|²), and the other from the product of the two roots
///   (`power` / |rd|²): it is `power` / q.
///
/// (Haines, Günther and Akenine-Möller, "Precision Improvements for
/// Ray/Sphere Intersection", Ray Tracing Gems, chapter 7.)
///
/// The formula is evaluated in f64, because f32 cannot even hold the
/// differences it starts from: 10⁴ units from the origin f32 steps by about
/// 10⁻³, so f, `along` and `power` would be off by a tenth of a sphere of
/// radius 0.01, or of a gap of 0.01 between the ray's origin and a huge sphere. In f64
/// every f32 input and every product of two of them is exact, f nearly so,
/// and the stable formula keeps that precision to the end.
pub fn sphere_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    let Quadratic {
        f,
        rd,
        rho,
        speed2,
        along,
        power,
    } = Quadratic::of(center, radius, ray);
    // h: from the centre to the line's point closest to it.
    let h = f - (along / speed2) * rd;
    // |rd|² times ρ² − |h|², the squared half chord: ≥ 0 when that point
    // is inside, and nothing large cancels.
    let half_chord2 = speed2 * (rho * rho - h.dot(h));
    if half_chord2 < 0.0 {
        return None;
    }
    // For along = 0 and a half chord of 0 (a tangent line from a point on
    // the sphere), q = 0 and power/q is 0/0: min and max drop that NaN and keep the
    // double root 0.
    let q = -(along + half_chord2.sqrt().copysign(along));
    let (t0, t1) = ((power / q) as f32, (q / speed2) as f32);
    Some((t0.min(t1), t0.max(t1)))
}

/// The ray's line and a sphere, in f64, in the quantities [`sphere_roots`]
/// solves from. They are geometric ones, not the lecture's coefficients:
/// working out a, b, c from the line and the sphere is the exercise
/// (README, *The lecture's quadratic*), and how each relates to these is a
/// good check of it.
///
/// * `f` = r0 − m, from the centre to the ray's origin; `rd` the direction
///   and `rho` = ρ, all in f64.
/// * `speed2` = |rd|², the squared length of the direction (1 up to
///   rounding).
/// * `along` = f·rd: negative while the ray still moves towards the
///   centre, positive once it moves away from it.
/// * `power` = |f|² − ρ², the power of the origin with respect to the
///   sphere: negative inside, 0 on the sphere, positive outside. It is
///   |rd|² times the product of the two roots.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadratic {
    pub f: DVec3,
    pub rd: DVec3,
    pub rho: f64,
    pub speed2: f64,
    pub along: f64,
    pub power: f64,
}

impl Quadratic {
    pub fn of(center: Vec3, radius: f32, ray: &Ray) -> Quadratic {
        let f = ray.origin.as_dvec3() - center.as_dvec3();
        let rd = ray.direction.as_dvec3();
        let rho = radius as f64;
        Quadratic {
            f,
            rd,
            rho,
            speed2: rd.dot(rd),
            along: f.dot(rd),
            power: f.dot(f) - rho * rho,
        }
    }
}
