//! Ray–sphere intersection: the lecture's quadratic, the choice of the
//! root that is the hit, and the point hit. The numerically stable form of
//! the quadratic, which the tracer uses, is in `stable.rs`: read it after
//! writing your own (README, *When the numbers get hard*).
//!
//! Letters as in the README: the sphere has centre m and radius ρ; the ray
//! has origin r0, unit direction rd and its points r(t); a, b, c are the
//! quadratic's coefficients and nothing else.

use crate::Ray;
use crate::stable::sphere_roots;
use crate::toolkit::Vec3;

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
/// [`sphere_roots_abc`]): the first point of the ray, strictly between
/// `t_min` and `t_max`, at which it meets the sphere. Which root that is
/// is the README's question, section *Which root is the hit?*.
///
/// * The roots belong to the whole line: a negative one is behind the
///   ray's origin. A ray that starts inside the sphere hits it too (the eye
///   sees the sphere's inside).
/// * Both bounds are strict: a root equal to `t_min` is no hit (a ray that
///   starts on the sphere and leaves it is not hit at t = 0), nor is one
///   equal to `t_max`.
/// * `None` if neither root lies in (t_min, t_max). (A line that misses
///   the sphere has no roots, and its caller asks nothing.)
pub fn nearest_root((near, far): (f32, f32), t_min: f32, t_max: f32) -> Option<f32> {
    // EXERCISE(ch02-nearest): which root, if either, is where the ray (not its line) first meets the sphere strictly between t_min and t_max
    crate::workbench::exercise::solution_begins("ch02-nearest");
    [near, far].into_iter().find(|&t| t > t_min && t < t_max)
    // END EXERCISE
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
