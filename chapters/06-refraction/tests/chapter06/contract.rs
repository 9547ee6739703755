//! `refract`'s promise beyond the known angles: never a NaN, and a
//! cos θ₁ that rounding leaves a hair above 1 counts as 1.

use ch06_refraction::refract;
use ch06_refraction::toolkit::Vec3;

/// Random unit normals, from a small xorshift generator (the same on every run).
fn random_normals(count: usize) -> Vec<Vec3> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 23) as f32 - 1.0
    };
    let mut normals = Vec::with_capacity(count);
    while normals.len() < count {
        let v = Vec3::new(next(), next(), next());
        if (0.01..=1.0).contains(&v.length_squared()) {
            normals.push(v.normalize());
        }
    }
    normals
}

#[test]
fn head_on_rays_go_straight_through_and_never_give_nan() {
    let normals = random_normals(2000);
    // The premise: for many of these, −N·d with d = −N comes out above 1.
    let above_one = normals.iter().filter(|n| -n.dot(-**n) > 1.0).count();
    assert!(above_one > 100, "only {above_one} normals with −N·d > 1");
    let mut wrong = Vec::new();
    for &n in &normals {
        for eta in [1.0 / 1.5, 1.5] {
            let d = -n;
            let got = refract(d, n, eta);
            if !got.is_some_and(|out| out.is_finite() && (out - d).length() < 1e-3) {
                wrong.push((d, n, eta, got, -n.dot(d)));
            }
        }
    }
    let Some((d, n, eta, got, cos)) = wrong.first() else {
        return;
    };
    panic!(
        "{} of {} head-on rays (d = −N, random unit normals N) did not go straight through: \
         refract({d}, {n}, η = {eta}) gave {got:?}, with cos θ₁ = −N·d = {cos}. Rounding \
         can put cos θ₁ a hair above 1, and then it counts as 1 (refract's contract, so \
         the answer is d again): a sin θ₁ = √(1 − cos²θ₁) of it, or a 1 − cos² below 0, is NaN",
        wrong.len(),
        2 * normals.len()
    );
}
