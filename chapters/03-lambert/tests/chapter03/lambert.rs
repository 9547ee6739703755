//! Lambert's cosine law: on a lit sphere, on a floor, and from a plane's back.

use ch03_lambert::toolkit::{Color, Vec3};
use ch03_lambert::{Incoming, Surface, closest_hit, lambert};

use super::{ALBEDO, close, floor_facing, floor_with, render, sphere_lit_at};

#[test]
pub(crate) fn cosine_law_head_on_versus_sixty_degrees() {
    // The centre pixel sees the point (0, 0, 1) whose normal is +z.
    let head_on = render(&sphere_lit_at(0.0)).get(20, 20);
    let at_sixty = render(&sphere_lit_at(60.0)).get(20, 20);
    // Head on: 0.9 × 50 / 10² = 0.45, below 1, so nothing is clamped.
    assert!(
        (head_on.x - 0.45).abs() < 1e-3,
        "head on, albedo 0.9 × irradiance 50/10² × cos 0° = 0.45, got {head_on} \
         (0.5: the albedo is missing; 0.0045: the 1/r² is applied twice; \
         0: l points away from the light)"
    );
    let ratio = at_sixty.x / head_on.x;
    assert!(
        (ratio - 0.5).abs() < 0.005,
        "at 60° the cosine law gives cos 60° = 0.5 of the head-on value, measured {ratio}"
    );
}

#[test]
pub(crate) fn a_light_behind_the_surface_adds_nothing() {
    let behind = render(&sphere_lit_at(120.0)).get(20, 20);
    assert_eq!(
        behind,
        Vec3::ZERO,
        "a light 120° from the normal is behind the surface"
    );
}

#[test]
fn lambert_gives_the_cosine_law_and_nothing_from_behind() {
    let (scene, ray) = floor_with("");
    let hit = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    let surface = Surface::new(&scene, hit, &ray);
    let from = |direction: Vec3| Incoming {
        direction: direction.normalize(),
        distance: 2.0,
        irradiance: Vec3::new(2.0, 1.0, 0.5),
        casts_shadows: true,
    };
    let sixty = lambert(&surface, &from(Vec3::new(3f32.sqrt(), 1.0, 0.0)));
    let want = ALBEDO * Vec3::new(2.0, 1.0, 0.5) * 0.5;
    assert!(
        close(sixty, want),
        "light at 60° from the normal: albedo × irradiance × cos 60° = {want}, got {sixty}"
    );
    let behind = lambert(&surface, &from(Vec3::new(1.0, -1.0, 0.0)));
    assert_eq!(
        behind,
        Color::ZERO,
        "light from behind the surface (n·l < 0) must give nothing, not a negative amount"
    );
}

#[test]
fn a_plane_seen_from_its_back_is_lit_like_its_front() {
    let light = r#"
        [[lights]]
        type = "point"
        position = [1, 3, 0]
        intensity = 10
    "#;
    let front = render(&floor_facing(1.0, light).0).get(4, 4);
    let back = render(&floor_facing(-1.0, light).0).get(4, 4);
    assert!(front.x > 0.1, "the floor is lit: {front}");
    assert_eq!(
        back, front,
        "the floor written with normal (0, -1, 0) is seen from its back: it is lit like \
         its front (shade with the normal that faces the eye, Surface::normal)"
    );
}
