//! The pictures: ambient light alone, colours clamped when written, the snapshot.

use ch03_lambert::toolkit::Vec3;
use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::workbench::snapshot::assert_image;
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
        "linear values may exceed 1 while shading"
    );
    assert_eq!(image.to_rgb8().get_pixel(20, 20).0, [255, 255, 255]);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image("03-lambert", "default", &render(&scene));
}
