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
/// With the lecture's f, a, b, c and Δ (README, *The lecture's quadratic*),
/// both steps of the lecture's formula lose their digits to cancellation in
/// f32 (README, *When the numbers get hard: the stable quadratic*):
/// * The discriminant subtracts two nearly equal large numbers when the
///   sphere is far away and small (both close to 4·distance²). The same
///   number, without that subtraction: Δ = 4a·(ρ² − |h|²), where
///   h = f − (b / 2a)·rd goes from the centre to the point of the ray's line
///   closest to it.
/// * For one of the two signs, the roots' numerator subtracts nearly equal
///   numbers. We compute the root without cancellation, t₁ = q/a with
///   q = −(b + sign(b)·√Δ) / 2, and get the other from the product of the
///   roots, t₀·t₁ = c/a: t₀ = c/q.
///
/// (Haines, Günther and Akenine-Möller, "Precision Improvements for
/// Ray/Sphere Intersection", Ray Tracing Gems, chapter 7.)
///
/// The formula is evaluated in f64, because f32 cannot even hold the
/// differences it starts from: 10⁴ units from the origin f32 steps by about
/// 10⁻³, so f, b and c would be off by a tenth of a sphere of radius 0.01,
/// or of a gap of 0.01 between the ray's origin and a huge sphere. In f64
/// every f32 input and every product of two of them is exact, f nearly so,
/// and the stable formula keeps that precision to the end.
pub fn sphere_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    let Quadratic {
        f,
        rd,
        rho,
        a,
        b,
        c,
    } = Quadratic::of(center, radius, ray);
    let h = f - (b / (2.0 * a)) * rd;
    let discriminant = 4.0 * a * (rho * rho - h.dot(h));
    if discriminant < 0.0 {
        return None;
    }
    // For b = 0 and Δ = 0 (a tangent line from a point on the sphere), q = 0
    // and c/q is 0/0: min and max drop that NaN and keep the double root 0.
    let q = -(b + discriminant.sqrt().copysign(b)) / 2.0;
    let (t0, t1) = ((c / q) as f32, (q / a) as f32);
    Some((t0.min(t1), t0.max(t1)))
}

/// The quadratic a·t² + b·t + c = 0 of a ray's line and a sphere, in f64,
/// as [`sphere_roots`] solves it: the lecture's f, rd, ρ and coefficients
/// a, b, c (README, *The lecture's quadratic*).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadratic {
    pub f: DVec3,
    pub rd: DVec3,
    pub rho: f64,
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl Quadratic {
    pub fn of(center: Vec3, radius: f32, ray: &Ray) -> Quadratic {
        let f = ray.origin.as_dvec3() - center.as_dvec3();
        let rd = ray.direction.as_dvec3();
        let rho = radius as f64;
        let (a, b, c) = (rd.dot(rd), 2.0 * f.dot(rd), f.dot(f) - rho * rho);
        Quadratic {
            f,
            rd,
            rho,
            a,
            b,
            c,
        }
    }
}
