//! The exercises that later ones build on, checked first: the mirror ray's
//! test checks `reflect`, and the pictures check `reflect`, `mirror_ray`
//! and `highlight`, so that a mistake there is named there and not blamed
//! on the mirror ray or the recursion.

use ch05_reflection::toolkit::{Color, Vec3};
use ch05_reflection::workbench::exercise::builds_on;
use ch05_reflection::{Incoming, highlight, mirror_ray, reflect};

use super::{arriving, floor, surface};

/// `ch05-reflect`: 45° down onto a floor leaves 45° up, whichever way the
/// normal points; straight down comes straight back.
pub(crate) fn reflect_first() {
    let s = 0.5f32.sqrt();
    for (d, n, want) in [
        (Vec3::new(s, -s, 0.0), Vec3::Y, Vec3::new(s, s, 0.0)),
        (Vec3::new(s, -s, 0.0), Vec3::NEG_Y, Vec3::new(s, s, 0.0)),
        (Vec3::NEG_Y, Vec3::Y, Vec3::Y),
    ] {
        let got = reflect(d, n);
        builds_on(
            "ch05-reflect",
            (got - want).length() < 1e-6,
            format_args!(
                "reflect({d}, n = {n}) gave {got}, the mirror law {want} (the tests in \
                 `mirror` say more)"
            ),
        );
    }
}

/// `ch05-mirror-ray` (after `ch05-reflect`): at 45° onto the mirror floor,
/// the mirror direction, from just above the surface, with the weight given.
pub(crate) fn mirror_ray_first() {
    reflect_first();
    let scene = floor();
    let s = 0.5f32.sqrt();
    let incoming = arriving(Vec3::new(s, -s, 0.0));
    let surface = surface(&scene, &incoming);
    let weight = Color::new(0.1, 0.2, 0.4);
    let got = mirror_ray(&surface, &incoming, weight);
    let right = got.as_ref().is_some_and(|m| {
        (m.ray.direction - Vec3::new(s, s, 0.0)).length() < 1e-6
            && m.ray.origin.y > surface.hit.point.y
            && m.weight == weight
    }) && mirror_ray(&surface, &incoming, Color::ZERO).is_none();
    builds_on(
        "ch05-mirror-ray",
        right,
        format_args!(
            "at 45° onto a mirror floor with weight {weight}, mirror_ray gave {got:?} (the \
             tests the_mirror_ray_… and a_zero_weight_… say more)"
        ),
    );
}

/// `ch05-highlight`: at its peak (h = n) specular × irradiance, none for a
/// matte surface.
pub(crate) fn highlight_first() {
    let mut scene = floor();
    let incoming = arriving(Vec3::new(0.0, -1.0, 0.0));
    let light = Incoming {
        direction: Vec3::Y,
        distance: 1.0,
        irradiance: Color::new(1.0, 0.5, 0.25),
        casts_shadows: true,
    };
    let peak = highlight(&surface(&scene, &incoming), &light);
    let want = 0.5 * light.irradiance;
    scene.materials[0].specular = 0.0;
    let matte = highlight(&surface(&scene, &incoming), &light);
    builds_on(
        "ch05-highlight",
        (peak - want).abs().max_element() < 1e-5 && matte == Color::ZERO,
        format_args!(
            "with the light and the eye straight above a floor of specular 0.5, highlight \
             gave {peak} (want {want}), and {matte} for a matte floor (want 0; the tests in \
             `highlight` say more)"
        ),
    );
}

/// Everything the pictures build on but the recursion.
pub(crate) fn the_local_parts_first() {
    mirror_ray_first();
    highlight_first();
}
