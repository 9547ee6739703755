//! Drawing inputs from the seed: numbers off the short decimals tests
//! write, unit vectors, points; and the values' JSON.

use ch01_rays::toolkit::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
use serde_json::{Value, json};

/// The random numbers of one probe.
pub type Rng = Pcg64Mcg;

/// The random numbers for `what` (an exercise id, a scene) under `seed`:
/// each exercise draws the same inputs whichever others are probed.
pub fn rng_for(seed: u64, what: &str) -> Rng {
    // FNV-1a of the name, mixed into the seed.
    let hash = what.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    });
    Pcg64Mcg::seed_from_u64(seed ^ hash)
}

/// A number in [lo, hi), never a short decimal ([`crate::is_short_decimal`]):
/// so never a number a test writes.
pub fn number(rng: &mut Rng, lo: f32, hi: f32) -> f32 {
    loop {
        let x = lo + (hi - lo) * rng.random::<f32>();
        if !crate::is_short_decimal(x as f64) && x < hi {
            return x;
        }
    }
}

/// A point in the cube [−r, r]³.
pub fn point(rng: &mut Rng, r: f32) -> Vec3 {
    Vec3::new(number(rng, -r, r), number(rng, -r, r), number(rng, -r, r))
}

/// A unit vector, uniform over the sphere's directions.
pub fn unit(rng: &mut Rng) -> Vec3 {
    loop {
        let v = point(rng, 1.0);
        let length = v.length();
        if length > 0.1 && length <= 1.0 {
            return v / length;
        }
    }
}

/// A yes/no with probability `p` of yes.
pub fn chance(rng: &mut Rng, p: f32) -> bool {
    rng.random::<f32>() < p
}

/// A whole number in [lo, hi].
pub fn whole(rng: &mut Rng, lo: u32, hi: u32) -> u32 {
    rng.random_range(lo..=hi)
}

/// An exact number for an edge case: k/64 for an odd k, |k/64| ≤ r. It
/// is a float exactly, and so are the sums and products of the few such
/// numbers that the exercises' formulas take: at an input built of them,
/// every correct formula computes the same value, and an edge (a root
/// exactly at t_max, a point exactly on a triangle's edge, a light exactly
/// in the surface's plane) is decided by the exercise's rule, not by
/// rounding. It has six decimals, so it is never a short decimal either.
pub fn exact(rng: &mut Rng, r: f32) -> f32 {
    let most = (32.0 * r) as i32;
    (2 * rng.random_range(-most..most) + 1) as f32 / 64.0
}

/// A point of exact coordinates in the cube [−r, r]³.
pub fn exact_point(rng: &mut Rng, r: f32) -> Vec3 {
    Vec3::new(exact(rng, r), exact(rng, r), exact(rng, r))
}

/// One of the six axis directions ±x, ±y, ±z.
pub fn axis(rng: &mut Rng) -> Vec3 {
    let v = [Vec3::X, Vec3::Y, Vec3::Z][whole(rng, 0, 2) as usize];
    if chance(rng, 0.5) { -v } else { v }
}

/// A number as JSON. JSON has no infinity or NaN (serde writes them as
/// `null`, which is `None`'s value): they are written as text, so that a
/// hit at t = ∞ never agrees with no hit.
pub fn num(x: f32) -> Value {
    match x.is_finite() {
        true => json!(x),
        false => json!(x.to_string()),
    }
}

/// A vector as JSON (see [`num`]).
pub fn v3(v: Vec3) -> Value {
    json!([num(v.x), num(v.y), num(v.z)])
}

/// A vector as the report shows an input: exact (Rust's shortest form).
pub fn show(v: Vec3) -> String {
    format!("({:?}, {:?}, {:?})", v.x, v.y, v.z)
}
