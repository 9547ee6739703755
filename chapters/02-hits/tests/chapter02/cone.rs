//! The bonus primitive: cones and cylinders (NFF `c`, the SPD scenes'
//! rings and trees). Exact cases first, then random rays whose hits must
//! lie on the surface.

use ch02_hits::toolkit::Vec3;
use ch02_hits::toolkit::scene::Shape;
use ch02_hits::{Ray, hit_at, intersect};
use proptest::prelude::*;

/// The cone from `base` (radius rb) to `apex` (radius ra), outside out.
fn cone(base: Vec3, rb: f32, apex: Vec3, ra: f32) -> Shape {
    Shape::Cone {
        base,
        base_radius: rb,
        apex,
        apex_radius: ra,
        inside_out: false,
    }
}

/// The unit cylinder along z from z = 0 to z = 2.
fn cylinder() -> Shape {
    cone(Vec3::ZERO, 1.0, 2.0 * Vec3::Z, 1.0)
}

fn hit(shape: &Shape, origin: Vec3, direction: Vec3) -> Option<f32> {
    intersect(shape, &Ray::new(origin, direction), 0.0, f32::INFINITY)
}

#[test]
fn a_ray_across_the_axis_hits_at_its_distance_less_the_radius() {
    // From 5 away, straight at the axis: the side is 5 − 1 = 4 away, and
    // its normal there points back along the ray, −d̂.
    let ray = Ray::new(Vec3::new(5.0, 0.0, 1.0), -Vec3::X);
    let t = intersect(&cylinder(), &ray, 0.0, f32::INFINITY).unwrap();
    assert_eq!(t, 4.0);
    let h = hit_at(&cylinder(), &ray, t, 0);
    assert_eq!(h.point, Vec3::new(1.0, 0.0, 1.0));
    assert!((h.normal - Vec3::X).length() < 1e-6, "{}", h.normal);
    assert_eq!(h.normal, h.shading_normal);
    // A farther t_min skips the near wall for the far one, 5 + 1 away.
    assert_eq!(intersect(&cylinder(), &ray, 4.5, f32::INFINITY), Some(6.0));
}

#[test]
fn a_ray_along_a_cylinders_axis_never_meets_its_side() {
    // a = b = 0 in the quadratic: no root, and no NaN either.
    for origin in [Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.5, 0.0, -3.0)] {
        for direction in [Vec3::Z, -Vec3::Z] {
            assert_eq!(
                hit(&cylinder(), origin, direction),
                None,
                "{origin} {direction}"
            );
        }
    }
    // Nearly along it: a is tiny, and the far root q/a huge but finite, or
    // dropped; the near one is still exact.
    let t = hit(
        &cylinder(),
        Vec3::new(0.0, 0.0, 0.5),
        Vec3::new(1e-4, 0.0, 1.0).normalize(),
    );
    assert!(t.is_none_or(|t| t.is_finite()), "{t:?}");
}

#[test]
fn a_ray_along_a_cones_axis_from_inside_meets_the_narrowing_side() {
    // Radius 1 at z = 0 to 0 at z = 2: r = 1 − z/2 is 0.5 at z = 1, so the
    // ray up the line x = 0.5 from z = 0.5 meets the side after 0.5.
    let shape = cone(Vec3::ZERO, 1.0, 2.0 * Vec3::Z, 0.0);
    let t = hit(&shape, Vec3::new(0.5, 0.0, 0.5), Vec3::Z).unwrap();
    assert!((t - 0.5).abs() < 1e-6, "{t}");
}

#[test]
fn a_ray_beyond_an_end_misses() {
    // Level with z = 3, above the cylinder's top at z = 2: its line meets
    // the infinite cylinder, but outside 0 ≤ s ≤ h.
    assert_eq!(hit(&cylinder(), Vec3::new(5.0, 0.0, 3.0), -Vec3::X), None);
    assert_eq!(hit(&cylinder(), Vec3::new(5.0, 0.0, -0.1), -Vec3::X), None);
    // A pointed cone's mirror image beyond the apex is no part of it.
    let shape = cone(Vec3::ZERO, 1.0, Vec3::Z, 0.0);
    assert_eq!(hit(&shape, Vec3::new(5.0, 0.0, 1.5), -Vec3::X), None);
}

#[test]
fn a_ray_into_the_open_end_hits_the_inside_of_the_wall() {
    // No caps: from above the axis, down and sideways into the open top,
    // to the wall at x = 1 on the way down (z = 4 − 3 = 1).
    let direction = Vec3::new(1.0, 0.0, -3.0).normalize();
    let ray = Ray::new(Vec3::new(0.0, 0.0, 4.0), direction);
    let t = intersect(&cylinder(), &ray, 0.0, f32::INFINITY).unwrap();
    let h = hit_at(&cylinder(), &ray, t, 0);
    assert!(
        (h.point - Vec3::new(1.0, 0.0, 1.0)).length() < 1e-5,
        "{}",
        h.point
    );
    assert!(
        h.normal.dot(direction) > 0.0,
        "the outward normal faces away"
    );
}

#[test]
fn inside_out_turns_the_normal_towards_the_axis() {
    let inside = Shape::Cone {
        base: Vec3::ZERO,
        base_radius: 1.0,
        apex: 2.0 * Vec3::Z,
        apex_radius: 1.0,
        inside_out: true,
    };
    let ray = Ray::new(Vec3::new(5.0, 0.0, 1.0), -Vec3::X);
    let h = hit_at(&inside, &ray, 4.0, 0);
    assert!((h.normal + Vec3::X).length() < 1e-6, "{}", h.normal);
}

#[test]
fn a_cones_normal_is_perpendicular_to_its_surface() {
    // Radius 2 at the base, 0.5 at the apex, along a slanted axis.
    let (base, apex) = (Vec3::new(1.0, -2.0, 0.5), Vec3::new(2.0, 1.0, 3.0));
    let (rb, ra) = (2.0, 0.5);
    let shape = cone(base, rb, apex, ra);
    let w = (apex - base).normalize();
    let (u, v) = w.any_orthonormal_pair();
    for i in 0..12 {
        let angle = i as f32 * 0.5;
        let across = u * angle.cos() + v * angle.sin();
        // The side's line at this angle, from the base circle to the apex circle.
        let (from, to) = (base + rb * across, apex + ra * across);
        let on_surface = from.lerp(to, 0.3);
        // Aim at that point from outside, along −across.
        let ray = Ray::new(on_surface + 5.0 * across, -across);
        let t = intersect(&shape, &ray, 0.0, f32::INFINITY).unwrap();
        let h = hit_at(&shape, &ray, t, 0);
        assert!(
            (h.point - on_surface).length() < 1e-5,
            "{} ≠ {on_surface}",
            h.point
        );
        assert!((h.normal.length() - 1.0).abs() < 1e-6);
        let along_side = (to - from).normalize();
        let around = w.cross(across);
        assert!(h.normal.dot(along_side).abs() < 1e-5, "⊥ the side's line");
        assert!(h.normal.dot(around).abs() < 1e-5, "⊥ the circle");
        assert!(h.normal.dot(across) > 0.0, "outward");
    }
}

/// How far `p` lies off the (infinite) cone's side, measured across the
/// axis, in f64; and s, its place along the axis.
fn off_surface(p: Vec3, base: Vec3, rb: f32, apex: Vec3, ra: f32) -> (f64, f64) {
    let (p, base, apex) = (p.as_dvec3(), base.as_dvec3(), apex.as_dvec3());
    let h = (apex - base).length();
    let w = (apex - base) / h;
    let s = (p - base).dot(w);
    let r = f64::from(rb) + (f64::from(ra) - f64::from(rb)) * s / h;
    (((p - base) - s * w).length() - r, s / h)
}

fn point() -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(-10.0f32..10.0).prop_map(Vec3::from_array)
}

fn direction() -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(-1.0f32..1.0)
        .prop_map(Vec3::from_array)
        .prop_filter("non-zero", |v| v.length() > 0.1)
        .prop_map(Vec3::normalize)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Rays from anywhere towards a point near the cone: every hit lies on
    /// the side, between the ends, within its error bound; and a ray that
    /// leaves the hit point outwards, started off the surface by that bound
    /// (chapter 4's offset), does not meet the cone again.
    #[test]
    fn hits_lie_on_the_surface_and_rays_leave_it_cleanly(
        base in point(),
        apex in point(),
        rb in 0.0f32..3.0,
        ra in 0.0f32..3.0,
        origin in point(),
        aim in 0.0f32..1.0,
        out in direction(),
    ) {
        prop_assume!(base.distance(apex) > 0.1 && rb.max(ra) > 0.05);
        let shape = cone(base, rb, apex, ra);
        let target = base.lerp(apex, aim) + Vec3::splat(0.3 * rb.max(ra));
        prop_assume!(origin.distance(target) > 1e-3);
        let ray = Ray::new(origin, (target - origin).normalize());
        if let Some(t) = intersect(&shape, &ray, 0.0, f32::INFINITY) {
            prop_assert!(t.is_finite() && t > 0.0);
            let h = hit_at(&shape, &ray, t, 0);
            let (off, s) = off_surface(h.point, base, rb, apex, ra);
            prop_assert!(off.abs() <= f64::from(h.error), "{off} off, error {}", h.error);
            prop_assert!((-1e-5..=1.0 + 1e-5).contains(&s), "s/h = {s}");
            // Leave outwards, n·out > 0, from the offset point. The solid
            // cone is convex and the tangent plane there supports it, so a
            // ray into the open side of that plane meets it nowhere.
            let n = h.normal;
            let out = if out.dot(n) < 0.0 { -out } else { out };
            prop_assume!(out.dot(n) > 0.05);
            let leaving = Ray::new(h.point + h.error * n, out);
            prop_assert_eq!(intersect(&shape, &leaving, 0.0, f32::INFINITY), None);
        }
    }
}
