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

/// A vector as JSON.
pub fn v3(v: Vec3) -> Value {
    json!([v.x, v.y, v.z])
}

/// A vector as the report shows an input: exact (Rust's shortest form).
pub fn show(v: Vec3) -> String {
    format!("({:?}, {:?}, {:?})", v.x, v.y, v.z)
}
