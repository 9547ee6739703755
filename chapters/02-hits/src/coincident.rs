//! Coincident surfaces: two objects that occupy the same place (two
//! triangles of a mesh drawn twice, a decal on a wall, a floor written as a
//! plane and as triangles) are decided by one rule, not by rounding.

use crate::toolkit::scene::Object;
use crate::{Hit, Ray, hit_at, intersect};

/// How far beyond the nearest hit `hit` another surface's hit along `ray`
/// still counts as the same place: τ = (2e + 8ε·(|r0|∞ + t)) / |n·rd|.
///
/// Two surfaces whose hits lie within their error bounds of each other
/// cannot be told apart by the numbers: which t comes out smaller is
/// rounding, and changes from pixel to pixel. Each coordinate of the hit
/// point is off by up to e (chapter 2's `Hit::error`), about e along the
/// normal n (√3·e at most), which is e/|n·rd| along the ray; the other
/// surface's point as much again (2e, both from the nearest hit's e: the
/// other's is not known before it is hit), and t itself carries the
/// rounding of the ray's numbers, a few ε of |r0| + t, divided by |n·rd|
/// for the same reason. A margin of the rounding's size, not a proof.
/// README, section *Coincident surfaces*.
pub fn coincidence_window(hit: &Hit, ray: &Ray) -> f32 {
    let rounding = 8.0 * f32::EPSILON * (ray.origin.abs().max_element() + hit.t);
    let cosine = hit.normal.dot(ray.direction).abs().max(f32::MIN_POSITIVE);
    (2.0 * hit.error + rounding) / cosine
}

/// The rule for coincident surfaces: of the objects whose hits lie within
/// [`coincidence_window`] of the nearest hit, the one listed first in the
/// scene wins. `nearest` must be the nearest hit in (t_min, t_max), as
/// chapter 2's closest hit finds it; the hit returned is the first listed
/// object's, or `nearest` itself.
///
/// Which objects count depends on the nearest t alone, so the winner does
/// not depend on the order in which the hits were found: a list, chapter
/// 8's BVH and the complete tracer's wide BVH agree. Only the objects
/// listed before the nearest one can win, and only if the ray meets them
/// within the window: this is the second look it costs (README, section
/// *Coincident surfaces*, measures it).
pub fn first_coincident(
    objects: &[Object],
    ray: &Ray,
    (t_min, t_max): (f32, f32),
    nearest: Hit,
) -> Hit {
    let (lower, upper) = coincident_range(&nearest, ray, t_min, t_max);
    objects[..nearest.object]
        .iter()
        .enumerate()
        .find_map(|(index, object)| {
            let t = intersect(&object.shape, ray, lower, upper)?;
            Some(hit_at(&object.shape, ray, t, index))
        })
        .unwrap_or(nearest)
}

/// The range (lower, upper) of t in which another object's hit coincides
/// with `nearest`, the nearest hit in (t_min, t_max): its t plus or minus
/// the window, within (t_min, t_max). (No object is hit in (t_min,
/// nearest.t), so the lower end only spares a traversal the boxes before it.)
pub fn coincident_range(nearest: &Hit, ray: &Ray, t_min: f32, t_max: f32) -> (f32, f32) {
    let window = coincidence_window(nearest, ray);
    (
        (nearest.t - window).max(t_min),
        (nearest.t + window).min(t_max),
    )
}
