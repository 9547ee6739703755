//! Ray–sphere intersection with a numerically stable quadratic.

use crate::Ray;
use crate::toolkit::Vec3;

/// Both distances at which the ray's line meets the sphere, nearest first,
/// or `None` if it passes by.
///
/// A point x is on the sphere when |x − c|² = r². With x = r0 + t·rd and
/// |rd| = 1 this is the quadratic t² + 2bt + c' = 0 with f = r0 − c,
/// b = f·rd and c' = f·f − r², so t = −b ± √(b² − c').
///
/// Computed like that, f32 loses both halves of the answer to cancellation:
/// * b² − c' subtracts two nearly equal large numbers when the sphere is far
///   away and small (b² ≈ c' ≈ distance²). We use the same quantity in a form
///   without that subtraction: b² − c' = r² − |f − b·rd|², where f − b·rd is
///   the vector from the centre to the ray's closest point.
/// * −b ± √… subtracts nearly equal numbers for one of the two signs. We
///   compute the other root, q = −b − sign(b)·√…, without cancellation and
///   get the first from the product of the roots: t₀·t₁ = c', so t₀ = c'/q.
///
/// (Haines, Günther and Akenine-Möller, "Precision Improvements for
/// Ray/Sphere Intersection", Ray Tracing Gems, chapter 7.)
pub fn sphere_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    let f = ray.origin - center;
    let b = f.dot(ray.direction);
    let c = f.dot(f) - radius * radius;
    let closest = f - b * ray.direction;
    let discriminant = radius * radius - closest.dot(closest);
    if discriminant < 0.0 {
        return None;
    }
    let q = -b - discriminant.sqrt().copysign(b);
    let (t0, t1) = (c / q, q);
    Some((t0.min(t1), t0.max(t1)))
}

/// The nearest distance in (t_min, t_max) at which the ray hits the sphere.
pub fn intersect_sphere(
    center: Vec3,
    radius: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    let (near, far) = sphere_roots(center, radius, ray)?;
    [near, far].into_iter().find(|&t| t > t_min && t < t_max)
}

/// The point of the sphere hit at distance t, put back onto the surface.
///
/// r0 + t·rd carries the rounding error of t, which grows with the distance
/// travelled; projecting it onto the sphere, c + r·(p − c)/|p − c|, leaves
/// only the error of that short computation (pbrt does the same).
pub fn sphere_point(center: Vec3, radius: f32, ray: &Ray, t: f32) -> Vec3 {
    center + radius * (ray.at(t) - center).normalize()
}
