//! Where a ray leaving a surface starts: just off it, on the right side.

use crate::Hit;
use crate::toolkit::Vec3;

/// The origin of a ray that leaves the surface at `hit` in direction
/// `towards`: a point just off the surface, on the side the ray goes to, so
/// that the ray cannot hit its own surface again. Derived in the README,
/// section *Shadow acne*.
///
/// * `hit.point` is the computed hit point, which may lie a little above or
///   below the true surface; `hit.error` is e, the bound on that error
///   (chapter 2). `hit.normal` is the geometric unit normal as the shape
///   defines it: it may face either way, towards the ray or away from it.
/// * `towards` is the direction the new ray will leave in (a shadow ray's
///   l, a mirror or refracted ray's direction). Only the side of the
///   surface it points into matters, not its length. A direction exactly
///   along the surface counts as the side the normal faces.
/// * The point returned lies off `hit.point` by the error bound e,
///   measured along the geometric normal (not along the ray, not along the
///   shading normal), on the side `towards` points into. A fixed epsilon
///   will not do: the distance must grow with e, that is with the size of
///   the coordinates.
/// * It must clear the true surface by at least e/2, near the origin and
///   far from it; `tests/chapter04/offset.rs` checks that on thousands of
///   hits. (Why e is enough, and how pbrt makes it a proof: the README,
///   section *Is e enough? (optional)*.)
pub fn offset_origin(hit: &Hit, towards: Vec3) -> Vec3 {
    // EXERCISE(ch04-offset): the hit point moved off the surface by its error bound, along the geometric normal, to the side that `towards` leaves by
    crate::workbench::exercise::solution_begins("ch04-offset");
    let side = if hit.normal.dot(towards) < 0.0 {
        -1.0
    } else {
        1.0
    };
    hit.point + side * hit.error * hit.normal
    // END EXERCISE
}
