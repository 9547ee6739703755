//! Ray–sphere intersection with a numerically stable quadratic.

use crate::Ray;
use crate::toolkit::Vec3;

/// Both distances at which the ray's line meets the sphere, nearest first,
/// or `None` if it passes by.
///
/// A point x is on the sphere when |x − c|² = r². With x = r0 + t·rd this is
/// the quadratic a·t² + 2b·t + c' = 0 with f = r0 − c, a = rd·rd (1 up to
/// rounding), b = f·rd and c' = f·f − r², so t = (−b ± √(b² − a·c')) / a.
///
/// Computed like that, both halves of the answer are lost to cancellation:
/// * b² − a·c' subtracts two nearly equal large numbers when the sphere is far
///   away and small (b² ≈ c' ≈ distance²). We use the same quantity in a form
///   without that subtraction: b² − a·c' = a·(r² − |f − (b/a)·rd|²), where
///   f − (b/a)·rd is the vector from the centre to the ray's closest point.
/// * −b ± √… subtracts nearly equal numbers for one of the two signs. We
///   compute the other root, t₁ = q/a with q = −b − sign(b)·√…, without
///   cancellation and get the first from the product of the roots:
///   t₀·t₁ = c'/a, so t₀ = c'/q.
///
/// (Haines, Günther and Akenine-Möller, "Precision Improvements for
/// Ray/Sphere Intersection", Ray Tracing Gems, chapter 7.)
///
/// The formula is evaluated in f64, because f32 cannot even hold the
/// differences it starts from: 10⁴ units from the origin f32 steps by about
/// 10⁻³, so r0 − c, b and c' would be off by a tenth of a sphere of radius
/// 0.01, or of a gap of 0.01 between the ray's origin and a huge sphere. In
/// f64 every f32 input and every product of two of them is exact, r0 − c
/// nearly so, and the stable formula keeps that precision to the end.
pub fn sphere_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
    // EXERCISE(ch02-sphere): solve t² + 2bt + c' = 0 with f = r0 - c, b = f·rd, c' = f·f - r²; None if the discriminant is negative; both roots, nearest first
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.direction.as_dvec3();
    let r = radius as f64;
    let (a, b, c) = (d.dot(d), f.dot(d), f.dot(f) - r * r);
    let closest = f - (b / a) * d;
    let discriminant = a * (r * r - closest.dot(closest));
    if discriminant < 0.0 {
        return None;
    }
    let q = -b - discriminant.sqrt().copysign(b);
    let (t0, t1) = ((c / q) as f32, (q / a) as f32);
    Some((t0.min(t1), t0.max(t1)))
    // END EXERCISE
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
