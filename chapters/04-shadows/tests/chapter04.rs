//! Chapter 4: shadow rays block what they should, and nothing else.

use ch04_shadows::toolkit::scene::{Light, Object, Shape};
use ch04_shadows::toolkit::snapshot::assert_image;
use ch04_shadows::toolkit::{Image, Scene, Vec3};
use ch04_shadows::{CHAPTER, Ray, ShadowStart, any_hit, offset_origin, render_shadows};

fn render(scene: &Scene, origin: ShadowStart) -> Image {
    render_shadows(scene, origin, || {}).0
}

/// Chapter 3's picture of the same scene: every light free everywhere.
fn unshadowed(scene: &Scene) -> Image {
    ch03_lambert::render_lambert(scene, || {}).0
}

/// Pixels darker with shadow rays than without: in a scene where nothing
/// can block anything, each one is acne.
fn shadowed_pixels(scene: &Scene, origin: ShadowStart) -> usize {
    let free = unshadowed(scene);
    let shadowed = render(scene, origin);
    let lit = free.pixels.iter().filter(|c| c.max_element() > 0.0).count();
    assert!(
        lit > scene.image.width as usize * 10,
        "the test scene must be lit: {lit}"
    );
    free.pixels
        .iter()
        .zip(&shadowed.pixels)
        .filter(|(a, b)| a != b)
        .count()
}

/// A floor lit by a light 1° above its horizon, seen from above. The floor
/// is tilted a little (normal (0.2, 1, 0.1)): on a level floor y = 0 the hit
/// points put back onto the plane come out exact, and even rays without an
/// offset would show no acne.
fn grazing_floor() -> Scene {
    let normal = Vec3::new(0.2, 1.0, 0.1).normalize();
    let along = normal.cross(Vec3::X).normalize();
    let (s, c) = 1f32.to_radians().sin_cos();
    let light = 1000.0 * (c * along + s * normal);
    let text = format!(
        r#"
        [camera]
        eye = [0, 3, 6]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 50
        [image]
        width = 160
        height = 120
        [materials.white]
        color = [1, 1, 1]
        [[lights]]
        type = "point"
        position = [{}, {}, {}]
        intensity = 2e7
        [[objects]]
        type = "plane"
        normal = [{}, {}, {}]
        offset = 0
        material = "white"
        "#,
        light.x, light.y, light.z, normal.x, normal.y, normal.z
    );
    Scene::parse(&text, "grazing.toml").unwrap()
}

/// A sphere far from the origin (around 1e4), lit from the side.
fn far_sphere() -> Scene {
    let text = r#"
        [camera]
        eye = [10000, 10000, 10005]
        look_at = [10000, 10000, 10000]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 160
        height = 120
        [materials.white]
        color = [1, 1, 1]
        [[lights]]
        type = "point"
        position = [10010, 10000, 10000]
        intensity = 60
        [[objects]]
        type = "sphere"
        center = [10000, 10000, 10000]
        radius = 1
        material = "white"
    "#;
    Scene::parse(text, "far.toml").unwrap()
}

#[test]
fn no_acne_on_a_floor_lit_at_a_grazing_angle() {
    assert_eq!(shadowed_pixels(&grazing_floor(), ShadowStart::Offset), 0);
}

#[test]
fn no_acne_on_the_same_floor_far_from_the_origin() {
    let far = grazing_floor().translated(Vec3::new(1e4, 0.0, 1e4));
    assert_eq!(shadowed_pixels(&far, ShadowStart::Offset), 0);
}

#[test]
fn no_acne_on_a_sphere_far_from_the_origin() {
    assert_eq!(shadowed_pixels(&far_sphere(), ShadowStart::Offset), 0);
}

#[test]
fn without_the_offset_the_same_scenes_show_acne() {
    // The three tests above could fail: here is the failure they guard against.
    let floor = shadowed_pixels(&grazing_floor(), ShadowStart::HitPoint);
    let far_floor = shadowed_pixels(
        &grazing_floor().translated(Vec3::new(1e4, 0.0, 1e4)),
        ShadowStart::HitPoint,
    );
    let sphere = shadowed_pixels(&far_sphere(), ShadowStart::HitPoint);
    let pixels = 160 * 120;
    println!(
        "acne without offset: floor {floor}, far floor {far_floor}, far sphere {sphere} of {pixels}"
    );
    assert!(floor > pixels / 100, "floor: {floor}");
    assert!(far_floor > pixels / 100, "far floor: {far_floor}");
    assert!(sphere > 100, "far sphere: {sphere}");
}

#[test]
fn the_offset_moves_to_the_lights_side_and_scales_with_magnitude() {
    // A unit sphere near the origin and one far from it, hit from above.
    let hit_top = |center: Vec3| {
        let sphere = [Object {
            shape: Shape::Sphere {
                center,
                radius: 1.0,
            },
            material: 0,
            shadows: true,
        }];
        let ray = Ray::new(center + Vec3::new(0.0, 5.0, 0.0), Vec3::NEG_Y);
        ch04_shadows::closest_hit(&sphere, &ray, 0.0, f32::INFINITY).unwrap()
    };
    let (near, far) = (hit_top(Vec3::ZERO), hit_top(Vec3::splat(1e4)));
    for hit in [near, far] {
        let up = offset_origin(&hit, Vec3::Y);
        let down = offset_origin(&hit, -Vec3::Y);
        assert!(
            up.y > hit.point.y && down.y < hit.point.y,
            "{hit:?}: {up} {down}"
        );
        assert_eq!(
            (up.x, up.z),
            (hit.point.x, hit.point.z),
            "only along the normal"
        );
    }
    let moved = |hit: &ch04_shadows::Hit| offset_origin(hit, Vec3::Y).y - hit.point.y;
    assert!(
        moved(&far) > 1000.0 * moved(&near),
        "{} vs {}",
        moved(&near),
        moved(&far)
    );
}

#[test]
fn a_blocker_between_point_and_light_blocks_it_one_behind_does_not() {
    let scene = far_sphere();
    let ray = Ray::new(
        Vec3::new(10000.0, 10000.0, 10003.0),
        Vec3::new(0.0, 0.0, -1.0),
    );
    assert!(
        any_hit(&scene.objects, &ray, 0.0, 10.0),
        "the sphere is 2 to 4 units ahead"
    );
    assert!(
        !any_hit(&scene.objects, &ray, 0.0, 1.5),
        "the light is closer than the sphere"
    );
}

#[test]
fn objects_that_opt_out_cast_no_shadow() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for object in &mut scene.objects {
        object.shadows = false;
    }
    let (image, stats) = render_shadows(&scene, ShadowStart::Offset, || {});
    assert_eq!(image, unshadowed(&scene));
    assert!(stats.shadow > 0, "the lights still ask");
}

#[test]
fn lights_that_opt_out_trace_no_shadow_ray() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for light in &mut scene.lights {
        if let Light::Point { shadows, .. } | Light::Spot { shadows, .. } = light {
            *shadows = false;
        }
    }
    let (image, stats) = render_shadows(&scene, ShadowStart::Offset, || {});
    assert_eq!(stats.shadow, 0);
    assert_eq!(image, unshadowed(&scene));
}

#[test]
fn the_box_keeps_its_light_inside() {
    let scene = Scene::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/box.toml"))
        .unwrap()
        .with_size(80, 60);
    let Some(&Light::Ambient { color: ambient }) = scene.lights.first() else {
        panic!("the box scene starts with its ambient light")
    };
    let image = render(&scene, ShadowStart::Offset);
    let camera = ch04_shadows::Camera::new(&scene.camera, 80, 60);
    for y in 0..60 {
        for x in 0..80 {
            let ray = camera.primary_ray(x, y);
            let hit = ch04_shadows::closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY);
            let expected = match hit {
                Some(hit) => scene.material(&scene.objects[hit.object]).color * ambient,
                None => scene.image.background,
            };
            assert_eq!(image.get(x, y), expected, "pixel ({x}, {y})");
        }
    }
    // And the box does matter: without the walls the floor is lit.
    let mut open = scene.clone();
    open.objects
        .retain(|o| !matches!(o.shape, Shape::Triangle { .. }));
    assert_ne!(
        render(&open, ShadowStart::Offset),
        render(&scene, ShadowStart::Offset)
    );
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image(
        "04-shadows",
        "default",
        &render(&scene, ShadowStart::Offset),
    );
}

#[test]
fn snapshot_box() {
    let scene = Scene::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/box.toml"))
        .unwrap()
        .with_size(160, 120);
    assert_image("04-shadows", "box", &render(&scene, ShadowStart::Offset));
}
