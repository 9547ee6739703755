//! Mirror reflection and the highlight of point lights.

use crate::toolkit::{Color, Vec3};
use crate::{Incoming, Ray, Secondary, SecondaryKind, Surface, offset_origin};

/// The mirror direction of `d` about the unit normal `n`:
/// d_o = d_i − 2(d_i·n)n.
///
/// The component of d along n flips sign and the rest is kept, so the angle
/// out equals the angle in, and |d_o| = |d_i|.
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    // EXERCISE(ch05-reflect): the mirror direction of d about n: the part of d along n reversed, the part across n kept
    crate::workbench::exercise::solution_begins("ch05-reflect");
    d - 2.0 * d.dot(n) * n
    // END EXERCISE
}

/// The mirror ray leaving `surface` for a ray that arrived along `incoming`,
/// carrying `weight` of its colour; none if the weight is zero (nothing
/// would come of it, and a tracer spawns no ray of weight zero).
///
/// Its direction is the mirror direction of the incoming one, [`reflect`]
/// (normalised: rounding may leave it a little off unit length). It starts
/// off the surface like a shadow ray, by `offset_origin` towards the side it
/// leaves to; from the hit point itself it could hit its own surface again.
/// The weight is whatever the caller gives: this chapter's tracer passes the
/// material's reflectance, chapter 6's adds what glass reflects.
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

/// The highlight of a light on a shiny surface (Blinn–Phong):
/// specular × irradiance × max(0, n·h)^shininess, where h is the unit vector
/// halfway between the directions to the light and to the eye.
///
/// A mirror ray is a single direction and never hits a point light, which
/// has no size; the highlight puts the light's reflection back in.
pub fn highlight(surface: &Surface, incoming: &Incoming) -> Color {
    // EXERCISE(ch05-highlight): Blinn–Phong: the specular weight times the light's irradiance times the cosine between the normal and the unit halfway vector of the directions to the light and to the eye, raised to the shininess
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
