//! Chapter 5: the mirror law, the recursion, and the pictures.

use ch05_reflection::toolkit::snapshot::assert_image;
use ch05_reflection::toolkit::{Scene, Vec3};
use ch05_reflection::{CHAPTER, reflect, render_mirrors};

fn corridor() -> Scene {
    Scene::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/corridor.toml")).unwrap()
}

#[test]
fn a_ray_at_45_degrees_leaves_at_45_degrees() {
    let s = 0.5f32.sqrt();
    let d = Vec3::new(s, -s, 0.0);
    let out = reflect(d, Vec3::Y);
    assert_eq!(out, Vec3::new(s, s, 0.0));
    // Angle in = angle out, and the length is kept.
    assert_eq!(d.dot(-Vec3::Y), out.dot(Vec3::Y));
    assert_eq!(out.length(), d.length());
}

#[test]
fn straight_on_comes_straight_back() {
    assert_eq!(reflect(Vec3::NEG_Z, Vec3::Z), Vec3::Z);
}

#[test]
fn no_reflectance_no_reflection_ray() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for m in &mut scene.materials {
        m.reflectance = Vec3::ZERO;
    }
    let (_, stats) = render_mirrors(&scene, || {});
    assert_eq!(stats.reflection, 0);
}

#[test]
fn the_corridor_is_ended_by_depth() {
    let scene = corridor().with_size(40, 30);
    let (image, stats) = render_mirrors(&scene, || {});
    assert!(stats.ended_max_depth > 0, "{stats}");
    assert!(image.pixels.iter().all(|c| c.is_finite()));
    // One less bounce allowed, fewer reflection rays.
    let mut shallower = scene.clone();
    shallower.trace.max_depth -= 1;
    let (_, fewer) = render_mirrors(&shallower, || {});
    assert!(fewer.reflection < stats.reflection);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image("05-reflection", "default", &render_mirrors(&scene, || {}).0);
}

#[test]
fn snapshot_corridor() {
    let scene = corridor().with_size(160, 120);
    assert_image(
        "05-reflection",
        "corridor",
        &render_mirrors(&scene, || {}).0,
    );
}
