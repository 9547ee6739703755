//! Ray–sphere intersection: the lecture's quadratic, and its numerically
//! stable form, which the tracer uses.
//!
//! Letters as in the README: the sphere has centre m and radius ρ; the ray
//! has origin r0, unit direction rd and its points r(t); a, b, c are the
//! quadratic's coefficients and nothing else.

use crate::Ray;
use crate::toolkit::{DVec3, Vec3};

/// Both distances at which the ray's line meets the sphere, nearest first,
/// or `None` if the line passes by: the lecture's quadratic in t, solved
/// with the lecture's formula in f32. Derived in the README, section *The
/// lecture's quadratic*.
///
/// * `center` is the centre m and `radius` is ρ > 0. The ray's direction rd
///   has length 1, so the roots are distances along the ray.
/// * `Some((t₀, t₁))` with t₀ ≤ t₁: the two real roots of the quadratic,
///   where the line enters the sphere and where it leaves it. They belong
///   to the whole line, so either or both may be negative (behind the ray's
///   origin): choosing among them is [`intersect_sphere`]'s job, not this
///   function's.
/// * A line that touches the sphere (discriminant exactly 0) has one double
///   root, returned twice, `Some((t, t))`: a tangent ray is a hit.
/// * `None` exactly when the discriminant is negative: the line misses the
///   sphere. Never roots that are not numbers.
///
/// Right on paper, and for a sphere near the eye; [`sphere_roots`] is the
/// form that stays right for a small sphere far away.
pub fn sphere_roots_abc(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    // EXERCISE(ch02-sphere): the lecture's quadratic a·t² + b·t + c = 0 for the ray's line and the sphere; None when the discriminant says the line passes by; both roots, nearest first (a tangent line has one double root)
    crate::workbench::exercise::solution_begins("ch02-sphere");
    let f = ray.origin - center;
    let a = ray.direction.dot(ray.direction);
    let b = 2.0 * f.dot(ray.direction);
    let c = f.dot(f) - radius * radius;
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return None;
    }
    let root = discriminant.sqrt();
    Some(((-b - root) / (2.0 * a), (-b + root) / (2.0 * a)))
    // END EXERCISE
}

/// Both distances at which the ray's line meets the sphere, nearest first,
/// or `None` if it passes by: the same roots as [`sphere_roots_abc`], computed
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

/// Where the ray hits the sphere: the nearest of the two roots of the
/// stable quadratic ([`sphere_roots`]) in (t_min, t_max), chosen by
/// [`nearest_root`]; `None` if the line misses the sphere or neither root
/// is in range.
pub fn intersect_sphere(
    center: Vec3,
    radius: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    nearest_root(sphere_roots(center, radius, ray)?, t_min, t_max)
}

/// The distance at which a ray hits a sphere, from the two roots of its
/// line, `(near, far)` with near ≤ far ([`sphere_roots`] or
/// [`sphere_roots_abc`]): the nearest root that lies strictly between
/// `t_min` and `t_max`. Derived in the README, section *Which root is the
/// hit?*.
///
/// * The roots belong to the whole line: a negative one is behind the
///   ray's origin. From inside the sphere the near root is behind and the
///   hit is the far one (the eye sees the sphere's inside).
/// * Both bounds are strict: a root equal to `t_min` is no hit (a ray that
///   starts on the sphere and leaves it is not hit at t = 0), nor is one
///   equal to `t_max`.
/// * `None` if neither root lies in (t_min, t_max). (A line that misses
///   the sphere has no roots, and its caller asks nothing.)
pub fn nearest_root((near, far): (f32, f32), t_min: f32, t_max: f32) -> Option<f32> {
    // EXERCISE(ch02-nearest): the nearest of the two roots that lies strictly between t_min and t_max, if either does
    crate::workbench::exercise::solution_begins("ch02-nearest");
    [near, far].into_iter().find(|&t| t > t_min && t < t_max)
    // END EXERCISE
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

/// The point of the sphere hit at distance t, put back onto the surface.
///
/// The ray's point r(t) carries the rounding error of t, which grows with
/// the distance travelled; projecting it onto the sphere,
/// m + ρ·(x − m)/|x − m|, leaves only the error of that short computation
/// (pbrt does the same).
pub fn sphere_point(center: Vec3, radius: f32, ray: &Ray, t: f32) -> Vec3 {
    center + radius * (ray.at(t) - center).normalize()
}
