//! The exercises that `split` builds on, checked first: a test of the split
//! at a glass surface (or of a whole picture) calls these before its own
//! checks, so that a mistake in `refract` or `schlick` is named there and
//! not blamed on the split's choice of normal, indices or weights.

use ch06_refraction::toolkit::Vec3;
use ch06_refraction::workbench::exercise::builds_on;
use ch06_refraction::{refract, schlick};

use super::{angle_out, arriving_at};

/// `ch06-refract`, on the chapter's known angles with the normal +y: head
/// on, 30° into glass (19.47°), 30° out of it (48.59°, bending away) and
/// 60° out of it (total internal reflection).
pub(crate) fn refract_first() {
    let cases: [(f32, f32, Option<f32>); 4] = [
        (0.0, 1.0 / 1.5, Some(0.0)),
        (30.0, 1.0 / 1.5, Some(19.47)),
        (30.0, 1.5, Some(48.59)),
        (60.0, 1.5, None),
    ];
    for (degrees, eta, want) in cases {
        let got = refract(arriving_at(degrees), Vec3::Y, eta);
        let right = match (got, want) {
            (None, None) => true,
            (Some(d), Some(angle)) => {
                d.y < 0.0
                    && d.x >= 0.0
                    && (d.length() - 1.0).abs() < 1e-5
                    && (angle_out(d) - angle).abs() < 0.01
            }
            _ => false,
        };
        let want = match want {
            Some(angle) => format!("a unit vector going on down, {angle}° from −y"),
            None => "None (total internal reflection)".to_owned(),
        };
        builds_on(
            "ch06-refract",
            right,
            format_args!(
                "refract(d at {degrees}° from the normal +y, going down; N = +y; η = {eta}) \
                 gave {got:?}, where Snell's law gives {want} (the refract tests say more)"
            ),
        );
    }
}

/// `ch06-schlick`: R₀ = 0.04 head-on between air and glass, either way
/// round, 1 at grazing incidence, and R₀ + (1 − R₀)·2⁻⁵ at 60°.
pub(crate) fn schlick_first() {
    let cases = [
        (1.0, 1.0, 1.5, 0.04),
        (1.0, 1.5, 1.0, 0.04),
        (0.0, 1.0, 1.5, 1.0),
        (0.5, 1.0, 1.5, 0.07),
    ];
    for (cos, n1, n2, want) in cases {
        let got = schlick(cos, n1, n2);
        builds_on(
            "ch06-schlick",
            (got - want).abs() < 1e-6,
            format_args!(
                "schlick(cos θ = {cos}, n₁ = {n1}, n₂ = {n2}) gave {got}, Schlick's \
                 approximation {want} (the schlick test says more)"
            ),
        );
    }
}

/// Both, for a test of the split or of a picture.
pub(crate) fn refract_and_schlick_first() {
    refract_first();
    schlick_first();
}
