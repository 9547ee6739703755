//! The pictures: ambient light alone, colours clamped when written, the snapshot.

use ch03_lambert::toolkit::Vec3;
use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::workbench::snapshot::{Precise, assert_image_beside};
use ch03_lambert::{CHAPTER, Camera, closest_hit};

use super::{render, sphere_lit_at};

#[test]
fn ambient_only_is_exactly_albedo_times_ambient() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    let ambient = Vec3::new(0.3, 0.2, 0.1);
    scene.lights = vec![Light::Ambient { color: ambient }];
    let image = render(&scene);
    let camera = Camera::new(&scene.camera, 80, 60);
    for y in 0..60 {
        for x in 0..80 {
            let hit = closest_hit(
                &scene.objects,
                &camera.primary_ray(x, y),
                0.0,
                f32::INFINITY,
            );
            let expected = match hit {
                Some(hit) => scene.material(&scene.objects[hit.object]).color * ambient,
                None => scene.image.background,
            };
            assert_eq!(image.get(x, y), expected, "pixel ({x}, {y})");
        }
    }
}

#[test]
fn colours_are_clamped_when_written() {
    let mut scene = sphere_lit_at(0.0);
    scene.lights[0] = match scene.lights[0].clone() {
        Light::Point {
            position,
            color,
            shadows,
            falloff,
            ..
        } => Light::Point {
            position,
            color,
            intensity: 1e4,
            shadows,
            falloff,
        },
        other => other,
    };
    let image = render(&scene);
    assert!(
        image.get(20, 20).x > 1.0,
        "pixel (20, 20), lit by a light of intensity 10⁴, is {} in the picture's linear \
         light: its red should be far above 1. Linear values may exceed 1 while shading: \
         lambert and direct_light return what they compute, unclamped, and only writing the \
         pixel to 8 bits (Image::to_rgb8) clamps it to [0, 1]",
        image.get(20, 20)
    );
    assert_eq!(
        image.to_rgb8().get_pixel(20, 20).0,
        [255, 255, 255],
        "pixel (20, 20), {} in linear light, is clamped to 1 when written: white",
        image.get(20, 20)
    );
}

/// The tests whose messages say more than a picture's count of pixels: a
/// snapshot that differs names those of them that fail beside it.
const PRECISE: &[Precise] = &[
    (
        "spot_factor_is_one_inside_zero_outside_and_smooth_between",
        super::spot::spot_factor_is_one_inside_zero_outside_and_smooth_between,
    ),
    (
        "cosine_law_head_on_versus_sixty_degrees",
        super::lambert::cosine_law_head_on_versus_sixty_degrees,
    ),
    (
        "a_light_behind_the_surface_adds_nothing",
        super::lambert::a_light_behind_the_surface_adds_nothing,
    ),
    (
        "ambient_light_adds_albedo_times_its_colour_once",
        super::direct_light::ambient_light_adds_albedo_times_its_colour_once,
    ),
    (
        "the_lights_add_up_channel_by_channel",
        super::direct_light::the_lights_add_up_channel_by_channel,
    ),
    (
        "a_light_that_is_not_visible_adds_nothing",
        super::direct_light::a_light_that_is_not_visible_adds_nothing,
    ),
    (
        "a_light_behind_the_surface_is_skipped_whatever_reflect_says",
        super::direct_light::a_light_behind_the_surface_is_skipped_whatever_reflect_says,
    ),
    (
        "visible_is_asked_only_about_lights_that_could_add_something",
        super::direct_light::visible_is_asked_only_about_lights_that_could_add_something,
    ),
];

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image_beside("03-lambert", "default", &render(&scene), PRECISE);
}
