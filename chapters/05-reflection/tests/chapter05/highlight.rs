//! The highlight: brightest at the light's mirror image, falling off with the
//! halfway angle, none on a matte surface.

use ch05_reflection::toolkit::{Color, Scene, Vec3};
use ch05_reflection::{Incoming, highlight};

use super::{arriving, close, floor, surface};

/// Light arriving from `direction` (towards the light) with irradiance (2, 1, 0.5).
fn light_from(direction: Vec3) -> Incoming {
    Incoming {
        direction: direction.normalize(),
        distance: 3.0,
        irradiance: Color::new(2.0, 1.0, 0.5),
        casts_shadows: false,
    }
}

/// When `found` is `want` × the floor's albedo, channel by channel: what
/// that says. The highlight is the light's colour, as a shiny coat on top
/// of the surface reflects it; the albedo belongs to Lambert's term only.
fn tinted(scene: &Scene, found: Color, want: Color) -> Option<String> {
    let albedo = scene.materials[0].color;
    close(found, want * albedo).then(|| {
        format!(
            ", which is {want} × the floor's albedo {albedo}: the highlight is the light's \
             colour, not tinted by the albedo (only Lambert's term has the albedo; here the \
             specular weight is 0.5 too, so specular applied twice gives the same numbers)"
        )
    })
}

#[test]
pub(crate) fn the_highlight_is_brightest_where_the_lights_mirror_image_is_seen() {
    let scene = floor();
    // specular 0.5 × irradiance (2, 1, 0.5), with h = n: cos = 1.
    let peak = Color::new(1.0, 0.5, 0.25);
    let s = 0.5f32.sqrt();
    for (eye_ray, light, case) in [
        (Vec3::NEG_Y, Vec3::Y, "eye and light straight above"),
        (
            Vec3::new(s, -s, 0.0),
            Vec3::new(s, s, 0.0),
            "eye and light at 45° on either side of the normal",
        ),
    ] {
        let ray = arriving(eye_ray);
        let found = highlight(&surface(&scene, &ray), &light_from(light));
        assert!(
            close(found, peak),
            "{case}: the halfway vector of the directions to the light and to the eye is the \
             normal, so the highlight is specular × irradiance = {peak}; found {found}{}",
            tinted(&scene, found, peak).unwrap_or_default()
        );
    }
}

#[test]
pub(crate) fn the_highlight_falls_off_with_the_halfway_angle_to_the_power_shininess() {
    let scene = floor();
    // Eye straight above, light 60° from the normal: h is 30° from n.
    let ray = arriving(Vec3::NEG_Y);
    let (s, c) = 60f32.to_radians().sin_cos();
    let found = highlight(&surface(&scene, &ray), &light_from(Vec3::new(s, c, 0.0)));
    let expected = 0.5 * Color::new(2.0, 1.0, 0.5) * 30f32.to_radians().cos().powf(8.0);
    assert!(
        close(found, expected),
        "eye above, light 60° off the normal: h lies 30° from n, so the highlight is \
         specular × irradiance × cos(30°)^8 = {expected}; found {found}{}",
        tinted(&scene, found, expected).unwrap_or(" (is h a unit vector?)".to_string())
    );
}

#[test]
pub(crate) fn a_matte_surface_has_no_highlight() {
    let mut scene = floor();
    scene.materials[0].specular = 0.0;
    let ray = arriving(Vec3::NEG_Y);
    let found = highlight(&surface(&scene, &ray), &light_from(Vec3::Y));
    assert_eq!(found, Color::ZERO, "specular 0: no highlight");
}
