//! Ray–plane intersection.

use crate::Ray;
use crate::toolkit::Vec3;

/// Where the ray meets the plane n·x + d = 0 (n a unit normal), if at a t in
/// (t_min, t_max).
///
/// Put r(t) = r0 + t·rd into the plane equation: n·r0 + t (n·rd) + d = 0, so
/// t = −(n·r0 + d) / (n·rd). When n·rd = 0 the ray runs parallel to the plane
/// and there is no single hit; when n·rd is tiny, t may overflow to infinity,
/// which is no hit either.
pub fn intersect_plane(
    normal: Vec3,
    offset: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    // EXERCISE(ch02-plane): the distance t at which r(t) satisfies the plane's equation; None for a ray parallel to the plane or a t that is not finite or not strictly between t_min and t_max
    crate::workbench::exercise::solution_begins("ch02-plane");
    let denominator = normal.dot(ray.direction);
    if denominator == 0.0 {
        return None;
    }
    let t = -(normal.dot(ray.origin) + offset) / denominator;
    (t.is_finite() && t > t_min && t < t_max).then_some(t)
    // END EXERCISE
}

/// The point of the plane n·x + d = 0 hit at distance t, put back onto the
/// plane.
///
/// r0 + t·rd carries the rounding error of a long sum: far from the eye it
/// can lie a little off the plane, on either side. Moving it along n by its
/// computed distance from the plane, p − (n·p + d)·n, leaves an error of a
/// few units in the last place of p's own coordinates. (Chapter 4 starts
/// shadow rays just off the surface, by an amount that relies on this.)
pub fn plane_point(normal: Vec3, offset: f32, ray: &Ray, t: f32) -> Vec3 {
    let p = ray.at(t);
    p - (normal.dot(p) + offset) * normal
}
