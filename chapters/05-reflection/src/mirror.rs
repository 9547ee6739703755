//! Mirror reflection and the highlight of point lights.

use crate::toolkit::{Color, Vec3};
use crate::{Incoming, Ray, Secondary, SecondaryKind, Surface, offset_origin};

/// The mirror direction d_o of an arriving direction `d` (d_i) at a surface
/// of unit normal `n`: where a perfect mirror sends it. Derived in the
/// README, section *The mirror law*.
///
/// * `d` points along the arriving ray, towards the surface; it need not be
///   a unit vector. `n` has length 1 and may face either way: the answer is
///   the same for n and −n.
/// * d_o leaves on the side d came from, at the same angle to the normal as
///   d arrived, in the plane of d and n, and with the same length as d.
/// * Straight onto the mirror (d along n) it comes straight back, reversed;
///   a d that lies in the surface's plane is returned unchanged.
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    // EXERCISE(ch05-reflect): the mirror direction of d about n: the part of d along n reversed, the part across n kept
    crate::workbench::exercise::solution_begins("ch05-reflect");
    d - 2.0 * d.dot(n) * n
    // END EXERCISE
}

/// The mirror ray that leaves `surface` for the ray `incoming` that hit it,
/// carrying `weight`. Derived in the README, sections *The mirror law* and
/// *The mirror ray*.
///
/// * `surface.normal` is the unit normal turned to face `incoming`;
///   `surface.hit` holds the hit point, its geometric normal and its error
///   bound. `incoming.direction` is the arriving unit direction.
/// * `None` if `weight` is zero in every channel: nothing would come of the
///   ray, and a tracer spawns no ray of weight zero. A weight that is zero
///   in some channels only still spawns one.
/// * Otherwise a [`Secondary`] of kind `SecondaryKind::Reflection` that
///   carries exactly `weight`, whatever it is: this chapter's tracer passes
///   the material's reflectance, chapter 6's adds what glass reflects.
/// * Its direction is the mirror direction ([`reflect`]) of the arriving
///   direction, of length 1 (rounding may leave `reflect`'s result a hair
///   off unit length: make it exact).
/// * It starts just off the surface on the side it leaves to, as a shadow
///   ray does ([`offset_origin`], chapter 4): from the hit point itself it
///   could hit its own surface again.
pub fn mirror_ray(surface: &Surface, incoming: &Ray, weight: Color) -> Option<Secondary> {
    // EXERCISE(ch05-mirror-ray): none for a zero weight; else a reflection carrying `weight`, in the mirror direction of the incoming ray, starting just off the surface on the side it leaves to
    crate::workbench::exercise::solution_begins("ch05-mirror-ray");
    if weight == Color::ZERO {
        return None;
    }
    let direction = reflect(incoming.direction, surface.normal).normalize();
    let origin = offset_origin(&surface.hit, direction);
    Some(Secondary {
        ray: Ray { origin, direction },
        weight,
        kind: SecondaryKind::Reflection,
    })
    // END EXERCISE
}

/// The highlight of one light on a shiny surface (Blinn–Phong): the light
/// that a point light, too small for any mirror ray to hit, sends towards
/// the eye off the surface. Derived in the README, section *Highlights*.
///
/// * n is `surface.normal` (unit, turned to face the eye), v is
///   `surface.to_eye` (unit, from the point back along the ray that hit
///   it), l is `incoming.direction` (unit, towards the light) and I_L is
///   `incoming.irradiance` (per channel, the irradiance of a surface facing
///   the light). From the material: k_s is `specular` (one number, the
///   same for every channel) and s is `shininess` (the exponent, > 0).
/// * The highlight depends on how far the halfway vector h of l and v leans
///   from n: at its peak, h = n, it is exactly k_s · I_L, and it dims as h
///   leans away, the faster the larger s. The README says by how much.
/// * It is never negative: where h leans 90° or more from n it is zero.
///   It is not scaled by cos θ = n·l nor by the albedo: that is Lambert's
///   term, which the tracer adds beside it.
/// * Zero for a matte surface (k_s = 0), and zero where l and v point
///   exactly opposite ways (h has no direction then).
/// * It does not check whether the light is in front of the surface:
///   chapter 3's `direct_light` asks only for lights with n·l > 0.
pub fn highlight(surface: &Surface, incoming: &Incoming) -> Color {
    // EXERCISE(ch05-highlight): Blinn–Phong: the highlight of one light, from how far the halfway vector of the directions to the light and to the eye leans from the normal (README, Highlights)
    crate::workbench::exercise::solution_begins("ch05-highlight");
    let material = surface.material;
    if material.specular == 0.0 {
        return Color::ZERO;
    }
    let halfway = (incoming.direction + surface.to_eye).normalize_or_zero();
    let cos = surface.normal.dot(halfway).max(0.0);
    material.specular * incoming.irradiance * cos.powf(material.shininess)
    // END EXERCISE
}
