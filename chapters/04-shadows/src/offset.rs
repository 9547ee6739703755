//! Where a ray leaving a surface starts: just off it, on the right side.

use crate::Hit;
use crate::toolkit::Vec3;

/// The origin of a ray that leaves the surface at `hit` in direction
/// `towards`: the hit point moved off the surface, along the geometric
/// normal, to the side the ray goes, by the hit's error bound.
///
/// Why: the hit point was computed in floating point, so it lies a little
/// above or a little below the true surface, at random. A ray started exactly
/// there towards a light may hit its own surface at a tiny t and report a
/// shadow that is not there: the speckle called *shadow acne*. A fixed
/// epsilon does not cure it: rounding errors grow with the size of the
/// coordinates (at 10 000 one f32 step is 0.001), so any fixed distance is
/// too small far from the origin and needlessly large near it.
///
/// How: chapter 2 puts every hit point back onto its surface and bounds how
/// far each of its coordinates can still be off: a few units in the last
/// place of the largest coordinate involved (`hit.error`, e). Moving the
/// origin by e along the normal, to the side the ray goes, clears the
/// surface with the margin chosen, not by proof: the bound alone allows a
/// point √3·e off a surface whose normal is diagonal. But e is several times
/// the real error, and `tests/offset.rs` checks, in f64 on thousands of hits
/// near the origin and at 10⁴, that every origin lies at least e/2 beyond
/// the true surface. (The chapter text says how pbrt turns this into a
/// proof.)
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
