//! The spot light: its smooth step between the cones, and nothing lit outside.

use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::toolkit::{Scene, Vec3};
use ch03_lambert::{CHAPTER, Camera, Ray, closest_hit, spot_factor};

use super::render;

#[test]
pub(crate) fn spot_factor_is_one_inside_zero_outside_and_smooth_between() {
    let axis = Vec3::new(0.0, -1.0, 0.0);
    let at = |deg: f32| {
        let r = deg.to_radians();
        spot_factor(axis, 10.0, 20.0, Vec3::new(r.sin(), -r.cos(), 0.0))
    };
    for deg in [0.0, 5.0, 9.9] {
        assert_eq!(at(deg), 1.0, "{deg}° is inside the inner cone (10°)");
    }
    for deg in [20.1, 45.0, 90.0, 180.0] {
        assert_eq!(at(deg), 0.0, "{deg}° is outside the outer cone (20°)");
    }
    let (a, b, c) = (at(12.0), at(15.0), at(18.0));
    assert!(
        1.0 > a && a > b && b > c && c > 0.0,
        "between the cones the factor falls from 1 to 0: at 12°, 15°, 18°: {a} {b} {c}"
    );
    // s = 1/4 of the way from the outer cosine to the inner one.
    let (cos_inner, cos_outer) = (10f32.to_radians().cos(), 20f32.to_radians().cos());
    let angle = (cos_outer + 0.25 * (cos_inner - cos_outer))
        .acos()
        .to_degrees();
    let quarter = at(angle);
    assert!(
        (quarter - 0.15625).abs() < 1e-3,
        "at s = 1/4 (of the way between the cosines, {angle:.2}°) the smooth step \
         3s² − 2s³ is 0.15625, got {quarter} (0.25: a linear ramp in the cosine; about 0.198: \
         a linear ramp in degrees; about 0.10: the smooth step of s measured in degrees \
         instead of cosines)"
    );
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
