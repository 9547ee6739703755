//! Snell's law, total internal reflection and Schlick's Fresnel term.

use crate::toolkit::Vec3;

/// The direction of a ray refracted at a surface, by Snell's law
/// n₁ sin θ₁ = n₂ sin θ₂, or `None` for total internal reflection.
///
/// `d` is the unit direction of the arriving ray, `normal` (N in the
/// chapter's text) the unit normal on the side it comes from (N·d ≤ 0), and
/// `eta` = η = n₁ / n₂, the ratio of the indices of refraction before and
/// after the surface.
///
/// Split d into its part along N, −cos θ₁ N with cos θ₁ = −N·d, and its part
/// across N, d + cos θ₁ N, of length sin θ₁. Snell's law scales the part
/// across by η (sin θ₂ = η sin θ₁, same direction); the part along N follows
/// from d' being a unit vector: −cos θ₂ N, cos θ₂ = √(1 − sin²θ₂). If
/// sin²θ₂ = η² (1 − cos²θ₁) exceeds 1 there is no refracted ray: going from
/// a denser medium at a steep enough angle, all light is reflected.
/// Otherwise d' = η (d + cos θ₁ N) − cos θ₂ N = η d + (η cos θ₁ − cos θ₂) N.
pub fn refract(d: Vec3, normal: Vec3, eta: f32) -> Option<Vec3> {
    // EXERCISE(ch06-refract): Snell's law in vector form: the refracted unit direction, or None on total internal reflection
    crate::workbench::exercise::solution_begins("ch06-refract");
    let cos_in = (-normal.dot(d)).min(1.0);
    let sin2_out = eta * eta * (1.0 - cos_in * cos_in);
    if sin2_out > 1.0 {
        return None;
    }
    let cos_out = (1.0 - sin2_out).sqrt();
    Some((eta * d + (eta * cos_in - cos_out) * normal).normalize())
    // END EXERCISE
}

/// The share of light reflected at a surface between indices `n1` and `n2`
/// (Schlick's approximation of Fresnel's equations):
/// R = R₀ + (1 − R₀)(1 − cos θ)⁵ with R₀ = ((n₁ − n₂) / (n₁ + n₂))².
///
/// `cos_theta` is the cosine of the angle on the side of the smaller index,
/// the larger of the two angles: of the arriving ray when entering glass,
/// of the refracted ray when leaving it. (Fresnel's reflectance is the same
/// for light going either way along a path; written in the angle on the
/// less dense side it rises from R₀ to 1 at 90°, the shape of this formula.
/// Taken so, R rises to 1 as a ray leaving glass nears the critical angle,
/// where total internal reflection takes over.) At normal incidence R = R₀
/// (4% for glass); at grazing incidence R = 1: every surface is a mirror
/// seen edge-on.
pub fn schlick(cos_theta: f32, n1: f32, n2: f32) -> f32 {
    // EXERCISE(ch06-schlick): Schlick's approximation of the share reflected: R₀ head-on (from the two indices), rising to 1 at grazing incidence; a cosine outside [0, 1] counts as the nearest end
    crate::workbench::exercise::solution_begins("ch06-schlick");
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_theta.clamp(0.0, 1.0)).powi(5)
    // END EXERCISE
}
