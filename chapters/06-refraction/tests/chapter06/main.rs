//! Chapter 6: Snell's law with known angles, total internal reflection,
//! Schlick's Fresnel term, the split at a glass surface (entering and
//! leaving, the weights), and the pictures.

use ch06_refraction::scene_files;
use ch06_refraction::toolkit::scene::{Material, Object, Shape};
use ch06_refraction::toolkit::{Color, Scene, Vec3};
use ch06_refraction::workbench::compare::{Tolerance, compare};
use ch06_refraction::workbench::snapshot::{Precise, assert_image_beside};
use ch06_refraction::{
    CHAPTER, Ray, Split, Surface, closest_hit, refract, render_glass, schlick, split,
};

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

// The split at a glass surface: a glass floor (y = 0, outward normal +y),
// rays from above entering it, rays from below leaving it.

const GLASS_FLOOR: &str = r#"
[camera]
eye = [0.0, 1.0, 3.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 4
height = 3

[materials.glass]
color = [0.0, 0.0, 0.0]
reflectance = [0.05, 0.1, 0.0]
transparency = 0.8
ior = 1.5

[[lights]]
type = "ambient"
color = [0.2, 0.2, 0.2]

[[objects]]
type = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0
material = "glass"
"#;

fn glass_floor(fresnel: bool) -> Scene {
    earlier::refract_and_schlick_first();
    let mut scene = scene_files::parse(GLASS_FLOOR, "glass-floor.toml").unwrap();
    scene.materials[0].fresnel = fresnel;
    scene
}

const REFLECTANCE: Color = Color::new(0.05, 0.1, 0.0);
const TRANSPARENCY: f32 = 0.8;

/// A ray that arrives at the floor's point (0.3, 0, 0.7) at `degrees` from
/// the normal: from above (entering the glass) or from below (leaving it).
fn arriving_ray(degrees: f32, from_above: bool) -> Ray {
    let mut direction = arriving_at(degrees);
    if !from_above {
        direction.y = -direction.y;
    }
    let spot = Vec3::new(0.3, 0.0, 0.7);
    Ray {
        origin: spot - 2.0 * direction,
        direction,
    }
}

/// The split where `ray` meets the floor of `scene`.
fn split_at(scene: &Scene, ray: &Ray) -> Split {
    let hit = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY).expect("the ray hits the floor");
    split(&Surface::new(scene, hit, ray), ray)
}

/// The refracted direction of a split, which must have one.
fn refracted_direction(split: &Split, case: &str) -> Vec3 {
    let Some((_, direction)) = split.refracted else {
        panic!("{case}: below the critical angle there is a refracted ray, but split gave none");
    };
    direction
}

/// Angle between `d` and the axis ±y it should be near.
fn angle_to(d: Vec3, axis: Vec3) -> f32 {
    d.angle_between(axis).to_degrees()
}

#[test]
fn entering_glass_the_ray_bends_towards_the_normal() {
    let scene = glass_floor(false);
    let split = split_at(&scene, &arriving_ray(30.0, true));
    let d = refracted_direction(&split, "entering at 30°");
    let angle = angle_to(d, Vec3::NEG_Y);
    assert!(
        d.y < 0.0,
        "entering glass from above, the refracted ray {d} must go on down into it: refract \
         needs the normal on the side the ray comes from (surface.normal)"
    );
    assert!(
        (angle - 19.47).abs() < 0.01,
        "entering glass at 30° (from n₁ = 1 into n₂ = 1.5, η = n₁/n₂ = 1/1.5) the ray bends \
         towards the normal, to 19.47°; found {angle:.2}° (48.59° would be η inverted)"
    );
}

#[test]
fn leaving_glass_the_ray_bends_away_from_the_normal() {
    let scene = glass_floor(false);
    let split = split_at(&scene, &arriving_ray(30.0, false));
    let d = refracted_direction(&split, "leaving at 30°");
    assert!(
        d.y > 0.0,
        "leaving glass upwards, the refracted ray {d} must go on up, out of it: refract needs \
         the normal on the side the ray comes from (surface.normal faces the ray; the outward \
         hit.normal does not when the ray leaves)"
    );
    let angle = angle_to(d, Vec3::Y);
    // 19.47° is η = 1/1.5, as on the way in: the indices split returned say why.
    let why = if split.indices.0 > split.indices.1 {
        format!(
            "the indices {:?} are right, so 19.47° would be η inverted: n₂/n₁ instead of n₁/n₂",
            split.indices
        )
    } else {
        format!(
            "with the indices {:?}, 19.47° would be leaving glass not detected, treated as \
             entering",
            split.indices
        )
    };
    assert!(
        (angle - 48.59).abs() < 0.01,
        "leaving glass at 30° (d·n > 0 with the outward normal: from n₁ = 1.5 into n₂ = 1, \
         η = 1.5) the ray bends away from the normal: sin θ₂ = 1.5 sin 30°, θ₂ = 48.59°; \
         found {angle:.2}° ({why})"
    );
}

#[test]
fn total_internal_reflection_sends_everything_transmitted_to_the_mirror() {
    for fresnel in [false, true] {
        let scene = glass_floor(fresnel);
        let split = split_at(&scene, &arriving_ray(42.0, false));
        assert_eq!(
            split.refracted, None,
            "leaving glass at 42°, beyond the critical angle 41.81°: no refracted ray"
        );
        let expected = REFLECTANCE + Color::splat(TRANSPARENCY);
        assert!(
            (split.reflected - expected).abs().max_element() < 1e-6,
            "on total internal reflection the transmitted weight goes to the mirror ray too: \
             reflectance + transparency = {expected}; found {}",
            split.reflected
        );
    }
}

/// R by Schlick, written out here so that this test does not lean on `schlick`.
fn schlick_r(cos_theta: f32) -> f32 {
    0.04 + 0.96 * (1.0 - cos_theta).powi(5)
}

#[test]
fn the_weights_add_up_to_what_the_glass_transmits() {
    for fresnel in [false, true] {
        let scene = glass_floor(fresnel);
        for (degrees, from_above) in [
            (0.0, true),
            (30.0, true),
            (60.0, true),
            (85.0, true),
            (0.0, false),
            (20.0, false),
            (40.0, false),
            (41.7, false),
        ] {
            let split = split_at(&scene, &arriving_ray(degrees, from_above));
            let side = if from_above { "entering" } else { "leaving" };
            let Some((weight, _)) = split.refracted else {
                panic!("{side} at {degrees}°: there is a refracted ray, but split gave none");
            };
            let shares = (split.reflected - REFLECTANCE) + weight;
            assert!(
                (shares - Color::splat(TRANSPARENCY)).abs().max_element() < 1e-6,
                "{side} at {degrees}° (fresnel = {fresnel}): the transmitted weight {TRANSPARENCY} \
                 is shared between the mirror ray (reflected − reflectance = {}) and the \
                 refracted ray ({weight}); the shares add up to {shares}",
                split.reflected - REFLECTANCE
            );
            if !fresnel {
                assert_eq!(
                    split.reflected, REFLECTANCE,
                    "{side} at {degrees}°: without fresnel the mirror ray gets the reflectance only"
                );
            }
        }
    }
}

#[test]
fn schlicks_cosine_is_taken_on_the_side_of_the_smaller_index() {
    let scene = glass_floor(true);
    // Entering at 80°: the angle outside is θ₁ itself.
    let entering = split_at(&scene, &arriving_ray(80.0, true));
    let expected = TRANSPARENCY * schlick_r(80f32.to_radians().cos());
    let found = entering.reflected.x - REFLECTANCE.x;
    assert!(
        (found - expected).abs() < 1e-4,
        "entering glass at 80°, Schlick's cos θ is cos θ₁ = cos 80° (the cosine on the side of \
         the smaller index: here the arriving ray's, in air): the mirror ray gets transparency × \
         R = {expected:.4} more; found {found:.4}"
    );
    // Leaving at 41.7°, just below the critical angle: the angle outside is
    // θ₂ (86.2°), and R = 0.72, nearing 1, as total internal reflection takes over.
    let leaving = split_at(&scene, &arriving_ray(41.7, false));
    let direction = refracted_direction(&leaving, "leaving at 41.7°");
    let expected = TRANSPARENCY * schlick_r(direction.y);
    let found = leaving.reflected.x - REFLECTANCE.x;
    assert!(
        (found - expected).abs() < 1e-3 && expected > 0.5,
        "leaving glass at 41.7°, Schlick's cos θ is cos θ₂ = {:.4} (the cosine on the side of \
         the smaller index, wherever the ray goes: here the refracted ray's, in air): the mirror \
         ray gets transparency × R = {expected:.4} more, rising to all of it at the critical \
         angle; found {found:.4}",
        direction.y
    );
}

/// The rule in general: Schlick's cosine is the one on the side of the
/// smaller index, whichever way the ray goes. Entering an air bubble in
/// glass (ior 1/1.5) the smaller index is inside, so it is the refracted
/// ray's cosine, though the ray enters: "the arriving ray's when entering"
/// holds only for an ior above 1.
#[test]
fn schlicks_cosine_entering_a_bubble_is_the_refracted_rays() {
    let mut scene = glass_floor(true);
    scene.materials[0].ior = 1.0 / 1.5;
    let into = split_at(&scene, &arriving_ray(40.0, true));
    let direction = refracted_direction(&into, "into the bubble at 40°");
    let expected = TRANSPARENCY * schlick_r(-direction.y);
    let found = into.reflected.x - REFLECTANCE.x;
    assert!(
        (found - expected).abs() < 1e-3,
        "entering an air bubble (ior 1/1.5) at 40°: from n₁ = 1 into n₂ = 0.667, the smaller \
         index is on the far side, so Schlick's cos θ is the refracted ray's, cos θ₂ = {:.4} \
         (θ₂ = {:.1}°), though the ray enters. \"The arriving ray's cosine when entering\" \
         holds only for an ior above 1: take the cosine on the side of the smaller index. The \
         mirror ray gets transparency × R = {expected:.4} more; found {found:.4}",
        -direction.y,
        angle_to(direction, Vec3::NEG_Y)
    );
}

/// An air bubble in glass has the relative index 1/1.5: entering it is
/// like leaving glass, and total internal reflection happens going in.
#[test]
fn an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees() {
    let mut scene = glass_floor(false);
    scene.materials[0].ior = 1.0 / 1.5;
    let into = split_at(&scene, &arriving_ray(30.0, true));
    let d = refracted_direction(&into, "into the bubble at 30°");
    let angle = angle_to(d, Vec3::NEG_Y);
    assert!(
        (angle - 48.59).abs() < 0.01,
        "into a bubble (ior 1/1.5) at 30°: from n₁ = 1 into n₂ = 1/1.5, the ray bends away \
         from the normal, to 48.59°; found {angle:.2}°"
    );
    let steep = split_at(&scene, &arriving_ray(42.0, true));
    assert_eq!(
        steep.refracted, None,
        "into a bubble at 42°: total internal reflection"
    );
}

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
        entering_glass_the_ray_bends_towards_the_normal,
    ),
    (
        "leaving_glass_the_ray_bends_away_from_the_normal",
        leaving_glass_the_ray_bends_away_from_the_normal,
    ),
    (
        "the_weights_add_up_to_what_the_glass_transmits",
        the_weights_add_up_to_what_the_glass_transmits,
    ),
    (
        "schlicks_cosine_is_taken_on_the_side_of_the_smaller_index",
        schlicks_cosine_is_taken_on_the_side_of_the_smaller_index,
    ),
    (
        "schlicks_cosine_entering_a_bubble_is_the_refracted_rays",
        schlicks_cosine_entering_a_bubble_is_the_refracted_rays,
    ),
    (
        "an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees",
        an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees,
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
