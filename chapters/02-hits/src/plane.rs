//! Ray–plane intersection.

use crate::Ray;
use crate::toolkit::Vec3;

/// The distance t at which the ray meets the plane, if t lies strictly
/// between `t_min` and `t_max`; derived in the README, section *Plane*.
///
/// * The plane is the set of points x with n·x + d = 0: `normal` is n, of
///   length 1, and `offset` is d. Which way n faces does not matter: the
///   plane is hit from either side.
/// * The ray's direction has length 1, so t is a distance along the ray.
/// * `None` for a ray parallel to the plane, whether it lies in the plane
///   or beside it: there is no single hit. A ray so nearly parallel that
///   its t overflows to infinity (or is not a number) is no hit either.
/// * `None` when t is not strictly inside (t_min, t_max). A plane behind
///   the ray has t < 0, and t = t_min is no hit: a ray that starts on the
///   plane and leaves it does not hit it at t = 0. t = t_max is no hit
///   either.
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
/// The ray's point r(t) carries the rounding error of a long sum: far from
/// the eye it can lie a little off the plane, on either side. Moving it
/// along n by its computed distance from the plane, p − (n·p + d)·n, leaves
/// an error of a few units in the last place of p's own coordinates.
/// (Chapter 4 starts shadow rays just off the surface, by an amount that
/// relies on this.)
pub fn plane_point(normal: Vec3, offset: f32, ray: &Ray, t: f32) -> Vec3 {
    let p = ray.at(t);
    p - (normal.dot(p) + offset) * normal
}
