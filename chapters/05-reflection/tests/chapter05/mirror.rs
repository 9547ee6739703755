//! The mirror law (`reflect`) and the mirror ray (`mirror_ray`).

use ch05_reflection::toolkit::{Color, Vec3};
use ch05_reflection::{SecondaryKind, mirror_ray, reflect};

use super::{arriving, floor, surface};

#[test]
pub(crate) fn a_ray_at_45_degrees_leaves_at_45_degrees() {
    let s = 0.5f32.sqrt();
    let d = Vec3::new(s, -s, 0.0);
    let out = reflect(d, Vec3::Y);
    assert!(
        (out - Vec3::new(s, s, 0.0)).length() < 1e-7,
        "reflect({d}, n = +y) gave {out}: expected {}, the part along n reversed and the part \
         across n kept",
        Vec3::new(s, s, 0.0)
    );
    // Angle in = angle out, and the length is kept.
    assert!((d.dot(-Vec3::Y) - out.dot(Vec3::Y)).abs() < 1e-7);
    assert!((out.length() - d.length()).abs() < 1e-7);
}

#[test]
pub(crate) fn straight_on_comes_straight_back() {
    let out = reflect(Vec3::NEG_Z, Vec3::Z);
    assert!(
        (out - Vec3::Z).length() < 1e-7,
        "a ray straight onto a mirror comes straight back: reflect(-z, +z) gave {out}"
    );
}

#[test]
fn the_mirror_law_does_not_care_which_way_the_normal_points() {
    let d = Vec3::new(0.48, -0.6, 0.64);
    let n = Vec3::new(0.0, 0.8, 0.6);
    let (up, down) = (reflect(d, n), reflect(d, -n));
    assert!((up - down).length() < 1e-6, "{up} and {down}");
    assert!(
        (up.dot(n) + d.dot(n)).abs() < 1e-6,
        "the part along n must be reversed: d·n = {}, out·n = {}",
        d.dot(n),
        up.dot(n)
    );
}

// The mirror ray.

#[test]
pub(crate) fn the_mirror_ray_leaves_at_the_mirror_angle_from_just_above_the_surface() {
    super::earlier::reflect_first();
    let scene = floor();
    let s = 0.5f32.sqrt();
    let incoming = arriving(Vec3::new(s, -s, 0.0));
    let surface = surface(&scene, &incoming);
    let weight = Color::new(0.1, 0.2, 0.4);
    let Some(mirror) = mirror_ray(&surface, &incoming, weight) else {
        panic!("a weight of {weight} spawns a mirror ray, but mirror_ray gave none");
    };
    let expected = Vec3::new(s, s, 0.0);
    assert!(
        (mirror.ray.direction - expected).length() < 1e-6,
        "the mirror ray goes {}: expected the mirror direction {expected} (angle out = angle in)",
        mirror.ray.direction
    );
    let above = (mirror.ray.origin - surface.hit.point).dot(Vec3::Y);
    assert!(
        above > 0.0,
        "the mirror ray starts {above} along the normal from the hit point: it must start just \
         off the surface on the side it leaves to (offset_origin), or it can hit its own surface"
    );
    assert_eq!(
        mirror.weight, weight,
        "the mirror ray carries the weight it is given ({weight}), not the material's \
         reflectance: chapter 6 passes more than the reflectance"
    );
    assert_eq!(
        mirror.kind,
        SecondaryKind::Reflection,
        "a mirror ray is counted as a reflection"
    );
}

#[test]
pub(crate) fn a_zero_weight_spawns_no_mirror_ray() {
    let scene = floor();
    let incoming = arriving(Vec3::new(0.3, -1.0, 0.2));
    let surface = surface(&scene, &incoming);
    assert_eq!(
        mirror_ray(&surface, &incoming, Color::ZERO),
        None,
        "a mirror ray of weight zero would add nothing: spawn none"
    );
}
