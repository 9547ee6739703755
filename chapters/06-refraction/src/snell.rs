//! Snell's law, total internal reflection and Schlick's Fresnel term.

use crate::toolkit::Vec3;

/// The direction d' of a ray refracted at a surface, by Snell's law, or
/// `None` for total internal reflection. Derived in the README, sections
/// *Snell's law*, *The refracted direction* and *Total internal
/// reflection*.
///
/// * `d` is the unit direction of the arriving ray. `normal` (N in the
///   README) is the unit normal on the side the ray comes from, so
///   N·d ≤ 0; the caller has turned it that way. `eta` is η = n₁/n₂, the
///   index of refraction on the side the ray comes from over the index on
///   the side it goes into (η < 1 into a denser medium, η > 1 out of it).
/// * `Some(d')`: a unit vector in the plane of d and N that crosses the
///   surface into the far side (N·d' ≤ 0), leaning the same way as d, at
///   the angle θ₂ from −N that Snell's law gives for d's angle θ₁ from −N.
///   Into a denser medium it bends towards the normal, out of it away.
/// * Along the normal (θ₁ = 0) the ray goes on unbent, and with η = 1 it is
///   not bent at all.
/// * `None` when no angle θ₂ satisfies Snell's law (its sine would exceed
///   1): total internal reflection, possible only for η > 1, beyond the
///   critical angle. Exactly at it, the refracted ray grazes the surface.
///   Never a vector of NaNs.
/// * Rounding may leave cos θ₁ a hair above 1 for a ray along the normal:
///   that counts as 1.
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

/// The share R of light reflected at a surface between the indices of
/// refraction `n1` and `n2`: Schlick's approximation of Fresnel's
/// equations. Derived in the README, section *Fresnel and Schlick's
/// approximation*.
///
/// * `cos_theta` is cos θ, where θ is the angle to the normal on the side
///   of the smaller index: the larger of the two angles. Choosing it is the
///   caller's job ([`split`](crate::split)); the README says why.
/// * R₀, the share reflected head-on, depends only on the two indices, and
///   not on which of them comes first: 4% between air (1) and glass (1.5),
///   0 between equal indices.
/// * R = R₀ head-on (cos θ = 1), R = 1 at grazing incidence (cos θ = 0),
///   and in between it rises from R₀ to 1 as Schlick's formula says: slowly
///   at first, steeply near grazing.
/// * A cosine outside [0, 1] (rounding can put one there) counts as the
///   nearest end: R stays between R₀ and 1.
pub fn schlick(cos_theta: f32, n1: f32, n2: f32) -> f32 {
    // EXERCISE(ch06-schlick): Schlick's approximation of the share reflected: R₀ head-on (from the two indices), rising to 1 at grazing incidence; a cosine outside [0, 1] counts as the nearest end
    crate::workbench::exercise::solution_begins("ch06-schlick");
    let r0 = ((n1 - n2) / (n1 + n2)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_theta.clamp(0.0, 1.0)).powi(5)
    // END EXERCISE
}
