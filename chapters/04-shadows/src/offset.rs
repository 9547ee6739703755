//! Where a ray leaving a surface starts: just off it, on the right side.

use crate::toolkit::Vec3;

/// Below this magnitude a coordinate is moved by a fixed step instead.
const NEAR_ORIGIN: f32 = 1.0 / 32.0;
/// The fixed step near the origin.
const FIXED_STEP: f32 = 1.0 / 65536.0;
/// How many units in the last place a unit normal moves a coordinate.
const ULPS: f32 = 256.0;

/// The origin of a ray that leaves the surface point `p` (geometric unit
/// normal `normal`) in direction `towards`: `p` moved off the surface, along
/// the normal, to the side the ray goes.
///
/// Why: `p` was computed in floating point, so it lies a little above or a
/// little below the true surface, at random. A ray started exactly there
/// towards a light may hit its own surface at a tiny t and report a shadow
/// that is not there: the speckle called *shadow acne*. A fixed epsilon does
/// not cure it: the rounding error of a coordinate grows with its magnitude
/// (at 10 000 one f32 step is 0.001), so any fixed distance is too small far
/// from the origin and needlessly large near it.
///
/// How: move each coordinate by a number of *units in the last place*
/// proportional to the normal's component, which is a distance that scales
/// with the coordinate itself; near zero, where units in the last place
/// become tiny, move by a small fixed step. (Wächter and Binder, "A Fast and
/// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, chapter 6;
/// the constants are theirs.)
pub fn offset_origin(p: Vec3, normal: Vec3, towards: Vec3) -> Vec3 {
    let n = if normal.dot(towards) < 0.0 {
        -normal
    } else {
        normal
    };
    Vec3::new(
        offset_coordinate(p.x, n.x),
        offset_coordinate(p.y, n.y),
        offset_coordinate(p.z, n.z),
    )
}

/// One coordinate `p` moved in the direction of `n` (a normal's component).
fn offset_coordinate(p: f32, n: f32) -> f32 {
    if p.abs() < NEAR_ORIGIN {
        return p + FIXED_STEP * n;
    }
    // For floats of one sign, the bit patterns count up with the magnitude, so
    // adding k to the bits moves k representable numbers away from zero.
    let steps = (ULPS * n) as i32;
    let away_from_zero = if p < 0.0 { -steps } else { steps };
    f32::from_bits((p.to_bits() as i32).wrapping_add(away_from_zero) as u32)
}
