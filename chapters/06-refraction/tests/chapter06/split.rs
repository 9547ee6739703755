//! The split at a glass surface: a glass floor (y = 0, outward normal +y),
//! rays from above entering it, rays from below leaving it.

use ch06_refraction::scene_files;
use ch06_refraction::toolkit::{Color, Scene, Vec3};
use ch06_refraction::{Ray, Split, Surface, closest_hit, split};

use super::{arriving_at, earlier};

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
pub(crate) fn entering_glass_the_ray_bends_towards_the_normal() {
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
pub(crate) fn leaving_glass_the_ray_bends_away_from_the_normal() {
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
pub(crate) fn the_weights_add_up_to_what_the_glass_transmits() {
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
pub(crate) fn schlicks_cosine_is_taken_on_the_side_of_the_smaller_index() {
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
pub(crate) fn schlicks_cosine_entering_a_bubble_is_the_refracted_rays() {
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
pub(crate) fn an_air_bubble_in_glass_reflects_totally_beyond_41_81_degrees() {
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
