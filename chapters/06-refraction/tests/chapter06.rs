//! Chapter 6: Snell's law with the numbers, total internal
//! reflection, Fresnel, and the pictures.

use ch06_refraction::toolkit::compare::{Tolerance, compare};
use ch06_refraction::toolkit::scene::{Material, Object, Shape};
use ch06_refraction::toolkit::snapshot::assert_image;
use ch06_refraction::toolkit::{Scene, Vec3};
use ch06_refraction::{CHAPTER, refract, render_glass, schlick};

/// A unit direction arriving at `degrees` from the normal +y, going down.
fn arriving_at(degrees: f32) -> Vec3 {
    let (s, c) = degrees.to_radians().sin_cos();
    Vec3::new(s, -c, 0.0)
}

/// The angle between a refracted direction and the normal −y, in degrees.
fn angle_out(d: Vec3) -> f32 {
    d.angle_between(Vec3::NEG_Y).to_degrees()
}

#[test]
fn normal_incidence_passes_straight_through() {
    let d = refract(Vec3::NEG_Y, Vec3::Y, 1.0 / 1.5).unwrap();
    assert!((d - Vec3::NEG_Y).length() < 1e-7, "{d}");
}

#[test]
fn thirty_degrees_into_glass_leaves_at_19_47_degrees() {
    let d = refract(arriving_at(30.0), Vec3::Y, 1.0 / 1.5).unwrap();
    // sin θ₂ = sin 30° / 1.5 = 1/3, θ₂ = 19.471°.
    let expected = (1.0f64 / 3.0).asin().to_degrees() as f32;
    assert!((angle_out(d) - expected).abs() < 0.01, "{}", angle_out(d));
    assert!((angle_out(d) - 19.47).abs() < 0.01);
    assert!((d.length() - 1.0).abs() < 1e-6);
}

#[test]
fn from_inside_glass_41_5_degrees_refracts_and_42_reflects_totally() {
    // Critical angle: sin θc = 1/1.5, θc = 41.81°.
    let critical = (1.0f32 / 1.5).asin().to_degrees();
    assert!((critical - 41.81).abs() < 0.005, "{critical}");
    let below = refract(arriving_at(41.5), Vec3::Y, 1.5);
    assert!(below.is_some_and(|d| d.is_finite() && (d.length() - 1.0).abs() < 1e-6));
    assert_eq!(refract(arriving_at(42.0), Vec3::Y, 1.5), None);
    assert!(refract(arriving_at(critical - 0.01), Vec3::Y, 1.5).is_some());
    assert_eq!(refract(arriving_at(critical + 0.01), Vec3::Y, 1.5), None);
}

#[test]
fn schlick_is_r0_head_on_and_one_at_grazing() {
    let r0 = ((1.5f32 - 1.0) / (1.5 + 1.0)).powi(2);
    assert!((schlick(1.0, 1.0, 1.5) - r0).abs() < 1e-7);
    assert!((r0 - 0.04).abs() < 1e-6);
    assert_eq!(schlick(0.0, 1.0, 1.5), 1.0);
}

/// Chapter 4's diffuse scene (no glass: two bounces spent passing through
/// the sphere must not run into the depth limit elsewhere), and the same with
/// an invisible sphere in front: no colour of its own, ior 1, fully
/// transparent, no shadow.
#[test]
fn a_sphere_of_ior_1_and_transparency_1_changes_nothing() {
    let without = Scene::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../04-shadows/scenes/default.toml"
    ))
    .unwrap()
    .with_size(160, 120);
    let mut with = without.clone();
    with.materials.push(Material {
        name: "nothing".into(),
        color: Vec3::ZERO,
        reflectance: Vec3::ZERO,
        specular: 0.0,
        shininess: 1.0,
        transparency: 1.0,
        ior: 1.0,
        fresnel: false,
    });
    with.objects.push(Object {
        shape: Shape::Sphere {
            center: Vec3::new(-0.8, 1.0, 2.5),
            radius: 0.9,
        },
        material: with.materials.len() - 1,
        shadows: false,
    });
    let (a, stats) = render_glass(&with, || {});
    let (b, _) = render_glass(&without, || {});
    assert!(stats.refraction > 0, "rays do pass through the sphere");
    let verdict = compare(&b.to_rgb8(), &a.to_rgb8(), Tolerance::for_size(160, 120));
    assert!(verdict.passed(), "{verdict}");
}

#[test]
fn opaque_materials_spawn_no_refraction_ray() {
    let scene = Scene::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../05-reflection/scenes/default.toml"
    ))
    .unwrap()
    .with_size(80, 60);
    let (_, stats) = render_glass(&scene, || {});
    assert_eq!(stats.refraction, 0);
    assert!(stats.reflection > 0);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image("06-refraction", "default", &render_glass(&scene, || {}).0);
}

#[test]
fn snapshot_bubble() {
    let scene = Scene::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/bubble.toml"))
        .unwrap()
        .with_size(160, 120);
    assert_image("06-refraction", "bubble", &render_glass(&scene, || {}).0);
}
