//! Chapter 3: the cosine law, the spot cone, ambient light, and the picture.

use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::toolkit::snapshot::assert_image;
use ch03_lambert::toolkit::{Image, Scene, Vec3};
use ch03_lambert::{CHAPTER, Camera, Ray, closest_hit, render_lambert, spot_factor};

fn render(scene: &Scene) -> Image {
    render_lambert(scene, || {}).0
}

/// A unit sphere at the origin seen from +z, lit by one point light placed
/// `degrees` away from the normal of the sphere's front point (0, 0, 1), at
/// distance 10 from that point.
fn sphere_lit_at(degrees: f32) -> Scene {
    let (s, c) = degrees.to_radians().sin_cos();
    let light = Vec3::new(0.0, 0.0, 1.0) + 10.0 * Vec3::new(s, 0.0, c);
    let text = format!(
        r#"
        [camera]
        eye = [0, 0, 5]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 41
        height = 41
        [materials.white]
        color = [0.9, 0.9, 0.9]
        [[lights]]
        type = "point"
        position = [{}, {}, {}]
        intensity = 50
        [[objects]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "white"
        "#,
        light.x, light.y, light.z
    );
    Scene::parse(&text, "cosine.toml").unwrap()
}

#[test]
fn cosine_law_head_on_versus_sixty_degrees() {
    // The centre pixel sees the point (0, 0, 1) whose normal is +z.
    let head_on = render(&sphere_lit_at(0.0)).get(20, 20);
    let at_sixty = render(&sphere_lit_at(60.0)).get(20, 20);
    // Head on: 0.9 × 50 / 10² = 0.45, below 1, so nothing is clamped.
    assert!((head_on.x - 0.45).abs() < 1e-3, "{head_on}");
    let ratio = at_sixty.x / head_on.x;
    assert!(
        (ratio - 0.5).abs() < 0.005,
        "cos 60° = 0.5, measured {ratio}"
    );
}

#[test]
fn a_light_behind_the_surface_adds_nothing() {
    let behind = render(&sphere_lit_at(120.0)).get(20, 20);
    assert_eq!(behind, Vec3::ZERO);
}

#[test]
fn spot_factor_is_one_inside_zero_outside_and_smooth_between() {
    let axis = Vec3::new(0.0, -1.0, 0.0);
    let at = |deg: f32| {
        let r = deg.to_radians();
        spot_factor(axis, 10.0, 20.0, Vec3::new(r.sin(), -r.cos(), 0.0))
    };
    assert_eq!(at(0.0), 1.0);
    assert_eq!(at(9.9), 1.0);
    assert_eq!(at(20.1), 0.0);
    assert_eq!(at(90.0), 0.0);
    let (a, b, c) = (at(12.0), at(15.0), at(18.0));
    assert!(1.0 > a && a > b && b > c && c > 0.0, "{a} {b} {c}");
}

/// The default scene with only its spot light (and ambient light).
fn spot_only() -> Scene {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    scene.lights.retain(|l| !matches!(l, Light::Point { .. }));
    scene
}

#[test]
fn nothing_is_lit_outside_the_spot_cone() {
    let scene = spot_only();
    let Some(&Light::Spot {
        position,
        direction,
        outer_degrees,
        ..
    }) = scene
        .lights
        .iter()
        .find(|l| matches!(l, Light::Spot { .. }))
    else {
        panic!("the default scene has a spot light")
    };
    let Some(&Light::Ambient { color: ambient }) = scene
        .lights
        .iter()
        .find(|l| matches!(l, Light::Ambient { .. }))
    else {
        panic!("the default scene has ambient light")
    };
    let image = render(&scene);
    let camera = Camera::new(&scene.camera, 160, 120);
    let (mut inside, mut outside) = (0, 0);
    for y in 0..120 {
        for x in 0..160 {
            let ray: Ray = camera.primary_ray(x, y);
            let Some(hit) = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY) else {
                continue;
            };
            let from_light = (hit.point - position).normalize();
            let angle = direction.angle_between(from_light).to_degrees();
            let albedo = scene.material(&scene.objects[hit.object]).color;
            let pixel = image.get(x, y);
            if angle > outer_degrees + 0.01 {
                outside += 1;
                assert_eq!(pixel, albedo * ambient, "pixel ({x}, {y}) at {angle}°");
            } else if angle < outer_degrees - 1.0 && pixel.x > (albedo * ambient).x * 2.0 {
                inside += 1;
            }
        }
    }
    assert!(
        outside > 1000 && inside > 200,
        "{outside} outside, {inside} lit inside"
    );
}

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
            ..
        } => Light::Point {
            position,
            color,
            intensity: 1e4,
            shadows,
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
