//! Snell's law, total internal reflection and Schlick's Fresnel term.

use crate::toolkit::Vec3;

/// The direction of a ray refracted at a surface, by Snell's law
/// n₁ sin θ₁ = n₂ sin θ₂, or `None` for total internal reflection.
///
/// `d` is the unit direction of the arriving ray, `n` the unit normal on the
/// side it comes from (n·d ≤ 0) and `eta` = n₁ / n₂, the ratio of the
/// indices of refraction before and after the surface. With cos θ₁ = −n·d,
/// sin²θ₂ = η² (1 − cos²θ₁). If that exceeds 1 there is no refracted ray:
/// going from a denser medium at a steep enough angle, all light is
/// reflected. Otherwise d' = η d + (η cos θ₁ − cos θ₂) n.
pub fn refract(d: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    // EXERCISE(ch06-refract): cos θ1 = -n·d, sin²θ2 = η²(1 - cos²θ1); None if > 1, else η d + (η cos θ1 - cos θ2) n, normalised
    let cos_in = (-n.dot(d)).min(1.0);
    let sin2_out = eta * eta * (1.0 - cos_in * cos_in);
    if sin2_out > 1.0 {
        return None;
    }
    let cos_out = (1.0 - sin2_out).sqrt();
    Some((eta * d + (eta * cos_in - cos_out) * n).normalize())
    // END EXERCISE
}

/// The share of light reflected at a surface between indices `n1` and `n2`
/// (Schlick's approximation of Fresnel's equations):
/// R = R₀ + (1 − R₀)(1 − cos θ)⁵ with R₀ = ((n₁ − n₂) / (n₁ + n₂))².
///
/// `cos_theta` is the cosine of the angle on the side of the smaller index
/// (the angle of the arriving ray when entering glass, of the refracted ray
/// when leaving it). At normal incidence R = R₀ (4% for glass); at grazing
/// incidence R = 1: every surface is a mirror seen edge-on.
pub fn schlick(cos_theta: f32, n1: f32, n2: f32) -> f32 {
    // EXERCISE(ch06-schlick): R0 = ((n1 - n2)/(n1 + n2))², R = R0 + (1 - R0)(1 - cos θ)⁵, with cos θ clamped to [0, 1]
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_theta.clamp(0.0, 1.0)).powi(5)
    // END EXERCISE
}
