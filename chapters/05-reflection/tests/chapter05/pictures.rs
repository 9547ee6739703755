//! The pictures: two facing mirrors where every pixel is known, the depth
//! limit, and the snapshots.

use ch05_reflection::scene_files;
use ch05_reflection::toolkit::{Color, Image, Scene, Stats, Vec3};
use ch05_reflection::workbench::snapshot::{Precise, assert_image_beside};
use ch05_reflection::{CHAPTER, render_mirrors};

use super::close;
use super::recursion::assert_the_recursion_is_sound;

/// Two facing mirrors (z = ±2), the camera between them looking askew: every
/// ray bounces between them until the depth limit ends it. Each hit's local
/// light is ambient 0.4 × albedo 0.5 = 0.2; each bounce weighs red by 0.5,
/// green by 0.25 and blue by 0.
const FACING: &str = r#"
[camera]
eye = [0.0, 0.0, 0.0]
look_at = [0.3, 0.2, -1.0]
up = [0.0, 1.0, 0.0]
vfov = 30.0

[image]
width = 4
height = 3

[materials.mirror]
color = [0.5, 0.5, 0.5]
reflectance = [0.5, 0.25, 0.0]

[[lights]]
type = "ambient"
color = [0.4, 0.4, 0.4]

[[objects]]
type = "plane"
normal = [0.0, 0.0, 1.0]
offset = 2.0
material = "mirror"

[[objects]]
type = "plane"
normal = [0.0, 0.0, -1.0]
offset = 2.0
material = "mirror"
"#;

/// The pixel after `bounces` bounces: 0.2 × Σₖ₌₀..bounces reflectanceᵏ.
fn after(bounces: u32) -> Color {
    (0..=bounces)
        .map(|k| 0.2 * Color::new(0.5, 0.25, 0.0).powf(k as f32))
        .fold(Color::ZERO, |sum, c| sum + c)
}

/// The pixel after `bounces` bounces when each mirror ray is weighted by
/// its path's weight ρᵏ (k its depth) instead of its own ρ: working back
/// from the deepest ray, c = 0.2 + ρᵏ × (what the ray at depth k brought).
fn after_by_path(bounces: u32) -> Color {
    let reflectance = Color::new(0.5, 0.25, 0.0);
    (1..=bounces).rev().fold(Color::splat(0.2), |seen, k| {
        Color::splat(0.2) + reflectance.powf(k as f32) * seen
    })
}

/// "1 bounce", "2 bounces": `n` of `thing`, in words that read.
fn count(n: u32, thing: &str) -> String {
    if n == 1 {
        format!("1 {thing}")
    } else {
        format!("{n} {thing}s")
    }
}

/// Renders with chapter 5's tracer, once the recursion is known to end.
fn render(scene: &Scene) -> (Image, Stats) {
    super::earlier::the_local_parts_first();
    assert_the_recursion_is_sound();
    render_mirrors(scene, || {})
}

#[test]
fn max_depth_n_follows_exactly_n_bounces() {
    for max_depth in 0..=3 {
        let mut scene = scene_files::parse(FACING, "facing.toml").unwrap();
        scene.trace.max_depth = max_depth;
        let (image, stats) = render(&scene);
        let expected = after(max_depth);
        for &found in &image.pixels {
            let hint = if close(found, after(max_depth + 1)) {
                " That is one bounce too many."
            } else if max_depth > 0 && close(found, after(max_depth - 1)) {
                " That is one bounce too few."
            } else if close(found, after_by_path(max_depth)) {
                " That is each mirror ray weighted by its path's weight (ρ at depth 1, ρ² at \
                 depth 2, …) instead of its own ρ: a ray brings back its own weight × what it \
                 sees."
            } else {
                ""
            };
            assert!(
                close(found, expected),
                "max_depth = {max_depth} follows exactly {}: every pixel is \
                 0.2 × (1 + ρ + … + ρ^{max_depth}) with the reflectance ρ = (0.5, 0.25, 0), \
                 {expected}; found {found}.{hint}",
                count(max_depth, "bounce")
            );
        }
        assert_eq!(
            stats.reflection,
            stats.primary * max_depth as u64,
            "max_depth = {max_depth}: {} per pixel",
            count(max_depth, "mirror ray")
        );
        assert_eq!(stats.ended_max_depth, stats.primary, "{stats}");
    }
}

#[test]
fn no_reflectance_no_reflection_ray() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for m in &mut scene.materials {
        m.reflectance = Vec3::ZERO;
    }
    let (_, stats) = render(&scene);
    assert_eq!(stats.reflection, 0, "no material reflects: no mirror ray");
}

fn corridor() -> Scene {
    scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/corridor.toml")).unwrap()
}

#[test]
fn the_corridor_is_ended_by_depth() {
    let scene = corridor().with_size(40, 30);
    let (image, stats) = render(&scene);
    assert!(stats.ended_max_depth > 0, "{stats}");
    assert!(image.pixels.iter().all(|c| c.is_finite()));
    // One less bounce allowed, fewer reflection rays.
    let mut shallower = scene.clone();
    shallower.trace.max_depth -= 1;
    let (_, fewer) = render(&shallower);
    assert!(fewer.reflection < stats.reflection);
}

/// The tests whose messages say more than a picture's count of pixels: a
/// snapshot that differs names those of them that fail beside it.
const PRECISE: &[Precise] = &[
    ("a_ray_at_45_degrees_leaves_at_45_degrees", super::mirror::a_ray_at_45_degrees_leaves_at_45_degrees),
    ("straight_on_comes_straight_back", super::mirror::straight_on_comes_straight_back),
    ("the_mirror_ray_leaves_at_the_mirror_angle_from_just_above_the_surface", super::mirror::the_mirror_ray_leaves_at_the_mirror_angle_from_just_above_the_surface),
    ("a_zero_weight_spawns_no_mirror_ray", super::mirror::a_zero_weight_spawns_no_mirror_ray),
    ("the_highlight_is_brightest_where_the_lights_mirror_image_is_seen", super::highlight::the_highlight_is_brightest_where_the_lights_mirror_image_is_seen),
    ("the_highlight_falls_off_with_the_halfway_angle_to_the_power_shininess", super::highlight::the_highlight_falls_off_with_the_halfway_angle_to_the_power_shininess),
    ("a_matte_surface_has_no_highlight", super::highlight::a_matte_surface_has_no_highlight),
    ("a_secondary_ray_is_one_bounce_deeper_and_carries_the_product_of_the_weights", super::recursion::a_secondary_ray_is_one_bounce_deeper_and_carries_the_product_of_the_weights),
    ("trace_offers_the_secondary_rays_one_bounce_deeper", super::recursion::trace_offers_the_secondary_rays_one_bounce_deeper),
    ("each_secondary_ray_brings_back_its_weight_times_what_it_sees", super::recursion::each_secondary_ray_brings_back_its_weight_times_what_it_sees),
    ("a_ray_the_tracer_stops_is_neither_traced_nor_counted", super::recursion::a_ray_the_tracer_stops_is_neither_traced_nor_counted),
    ("trace_sees_the_background_where_the_ray_hits_nothing", super::recursion::trace_sees_the_background_where_the_ray_hits_nothing),
    ("trace_adds_the_local_light_and_what_the_secondary_rays_bring_back", super::recursion::trace_adds_the_local_light_and_what_the_secondary_rays_bring_back),
];

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image_beside("05-reflection", "default", &render(&scene).0, PRECISE);
}

#[test]
fn snapshot_corridor() {
    let scene = corridor().with_size(160, 120);
    assert_image_beside("05-reflection", "corridor", &render(&scene).0, PRECISE);
}
