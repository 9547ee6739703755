//! Chapter 6: Snell's law with known angles, total internal reflection,
//! Schlick's Fresnel term, the split at a glass surface (entering and
//! leaving, the weights), and the pictures.

use ch06_refraction::scene_files;
use ch06_refraction::toolkit::Vec3;
use ch06_refraction::toolkit::scene::{Material, Object, Shape};
use ch06_refraction::workbench::compare::{Tolerance, compare};
use ch06_refraction::workbench::snapshot::{Precise, assert_image_beside};
use ch06_refraction::{CHAPTER, refract, render_glass, schlick};

/// The exercises the split builds on, checked first by its tests.
mod earlier;

/// A unit direction arriving at `degrees` from the normal +y, going down.
fn arriving_at(degrees: f32) -> Vec3 {
    let (s, c) = degrees.to_radians().sin_cos();
    Vec3::new(s, -c, 0.0)
}

/// The angle between a refracted direction and the normal −y, in degrees.
fn angle_out(d: Vec3) -> f32 {
    d.angle_between(Vec3::NEG_Y).to_degrees()
}

/// `refract`, which must give a direction here.
fn refracted(d: Vec3, n: Vec3, eta: f32) -> Vec3 {
    let out = refract(d, n, eta);
    out.unwrap_or_else(|| {
        panic!("refract({d}, {n}, η = {eta}) gave None: below the critical angle there is a refracted ray")
    })
}

#[test]
fn normal_incidence_passes_straight_through() {
    let d = refracted(Vec3::NEG_Y, Vec3::Y, 1.0 / 1.5);
    assert!(
        (d - Vec3::NEG_Y).length() < 1e-7,
        "a ray along the normal is not bent: expected {}, found {d}",
        Vec3::NEG_Y
    );
}

#[test]
fn thirty_degrees_into_glass_leaves_at_19_47_degrees() {
    let d = refracted(arriving_at(30.0), Vec3::Y, 1.0 / 1.5);
    // sin θ₂ = sin 30° / 1.5 = 1/3, θ₂ = 19.471°.
    let expected = (1.0f64 / 3.0).asin().to_degrees() as f32;
    assert!(
        (angle_out(d) - expected).abs() < 0.01,
        "30° into glass (η = 1/1.5): Snell's law gives sin θ₂ = sin 30° / 1.5, θ₂ = 19.47°; the \
         refracted ray is {d}, {:.2}° from the normal",
        angle_out(d)
    );
    assert!(
        d.y < 0.0 && d.x > 0.0,
        "the refracted ray {d} goes on through the surface, on the same side of the normal"
    );
    assert!(
        (d.length() - 1.0).abs() < 1e-6,
        "the refracted direction {d} is a unit vector"
    );
}

#[test]
fn from_inside_glass_41_5_degrees_refracts_and_42_reflects_totally() {
    // Critical angle: sin θc = 1/1.5, θc = 41.81°.
    let critical = (1.0f32 / 1.5).asin().to_degrees();
    assert!((critical - 41.81).abs() < 0.005, "{critical}");
    let below = refracted(arriving_at(41.5), Vec3::Y, 1.5);
    assert!(
        below.is_finite() && (below.length() - 1.0).abs() < 1e-6,
        "{below}"
    );
    for degrees in [42.0, critical + 0.01, 60.0, 89.0] {
        let found = refract(arriving_at(degrees), Vec3::Y, 1.5);
        assert_eq!(
            found, None,
            "from glass into air at {degrees}°, beyond the critical angle arcsin(1/1.5) = \
             41.81°, sin θ₂ would exceed 1: no refracted ray, refract must give None"
        );
    }
    assert!(refract(arriving_at(critical - 0.01), Vec3::Y, 1.5).is_some());
}

/// The critical angles of water, glass and diamond (the chapter's
/// exercise: predict them first).
#[test]
fn the_critical_angle_is_arcsin_of_one_over_the_index() {
    for (ior, critical) in [(1.33f32, 48.75f32), (1.5, 41.81), (2.42, 24.41)] {
        assert!(
            refract(arriving_at(critical - 0.02), Vec3::Y, ior).is_some(),
            "{ior}"
        );
        assert_eq!(
            refract(arriving_at(critical + 0.02), Vec3::Y, ior),
            None,
            "index {ior} into air: total internal reflection from {critical}° on"
        );
    }
}

/// refract never gives NaN: head-on rays with random normals.
mod contract;

#[test]
fn schlick_is_r0_head_on_and_one_at_grazing() {
    let r0 = ((1.5f32 - 1.0) / (1.5 + 1.0)).powi(2);
    assert!((r0 - 0.04).abs() < 1e-6);
    let head_on = schlick(1.0, 1.0, 1.5);
    assert!(
        (head_on - r0).abs() < 1e-7,
        "head-on, glass reflects R₀ = ((n₁ − n₂)/(n₁ + n₂))² = 0.04; schlick gave {head_on}"
    );
    assert_eq!(
        schlick(0.0, 1.0, 1.5),
        1.0,
        "at grazing incidence (cos θ = 0) everything is reflected"
    );
    let half = schlick(0.5, 1.0, 1.5);
    let expected = 0.04 + 0.96 * 0.5f32.powi(5);
    assert!(
        (half - expected).abs() < 1e-6,
        "at 60° (cos θ = 0.5): R = R₀ + (1 − R₀)(1 − cos θ)⁵ = {expected}; schlick gave {half}"
    );
    assert!(
        (schlick(1.0, 1.5, 1.0) - r0).abs() < 1e-7,
        "R₀ is the same either way through the surface"
    );
    assert_eq!(schlick(-0.2, 1.0, 1.5), 1.0, "a cosine below 0 counts as 0");
    assert!(
        (schlick(1.2, 1.0, 1.5) - r0).abs() < 1e-7,
        "a cosine above 1 counts as 1"
    );
}

/// The split at a glass surface: entering and leaving a glass floor, the
/// weights, Schlick's cosine, an air bubble.
mod split;

/// Chapter 4's diffuse scene (no glass: two bounces spent passing through
/// the sphere must not run into the depth limit elsewhere), and the same with
/// an invisible sphere in front: no colour of its own, ior 1, fully
/// transparent, no shadow.
#[test]
fn a_sphere_of_ior_1_and_transparency_1_changes_nothing() {
    earlier::refract_and_schlick_first();
    let without = scene_files::load(concat!(
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
    earlier::refract_and_schlick_first();
    let scene = scene_files::load(concat!(
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
    earlier::refract_and_schlick_first();
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    let picture = render_glass(&scene, || {}).0;
    assert_image_beside("06-refraction", "default", &picture, PRECISE);
}

/// The tests whose messages say more than the pictures' counts of pixels:
/// a picture that differs names those of them that fail beside it.
const PRECISE: &[Precise] = &[
    (
        "entering_glass_the_ray_bends_towards_the_normal",
        split::entering_glass_the_ray_bends_towards_the_normal,
    ),
    (
        "leaving_glass_the_ray_bends_away_from_the_normal",
        split::leaving_glass_the_ray_bends_away_from_the_normal,
    ),
    (
        "the_weights_add_up_to_what_the_glass_transmits",
        split::the_weights_add_up_to_what_the_glass_transmits,
    ),
    (
        "schlicks_cosine_is_taken_on_the_side_of_the_smaller_index",
        split::schlicks_cosine_is_taken_on_the_side_of_the_smaller_index,
    ),
    (
        "schlicks_cosine_entering_a_bubble_is_the_refracted_rays",
        split::schlicks_cosine_entering_a_bubble_is_the_refracted_rays,
    ),
    (
        "an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees",
        split::an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees,
    ),
];

#[test]
fn snapshot_bubble() {
    earlier::refract_and_schlick_first();
    let scene = scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/bubble.toml"))
        .unwrap()
        .with_size(160, 120);
    let picture = render_glass(&scene, || {}).0;
    assert_image_beside("06-refraction", "bubble", &picture, PRECISE);
}

// Last: `workbook progress` ranks failures in this file's order, theirs after these.
/// `--pixel X,Y`: the ray tree at glass, its split, colours and short form.
mod ray_tree;

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
