//! The sphere: the lecture's quadratic, the stable roots, and the nearest hit ahead.

use ch02_hits::toolkit::Vec3;
use ch02_hits::{Ray, intersect_sphere, nearest_root, sphere_roots, sphere_roots_abc};

use super::INF;

#[test]
pub(crate) fn the_lectures_worked_example() {
    // A ray from (0, 2, 0) straight down onto the unit sphere at the origin:
    // a = 1, b = −4, c = 3, so t² − 4t + 3 = 0.
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    let roots = sphere_roots_abc(Vec3::ZERO, 1.0, &ray);
    assert_eq!(
        roots,
        Some((1.0, 3.0)),
        "this ray's quadratic is t² − 4t + 3 = 0 (a = 1, b = −4, c = 3: check yours on paper), \
         with the roots 1 and 3, nearest first"
    );
    let (t0, t1) = roots.unwrap();
    assert_eq!(ray.at(t0), Vec3::new(0.0, 1.0, 0.0), "enters at the top");
    assert_eq!(
        ray.at(t1),
        Vec3::new(0.0, -1.0, 0.0),
        "leaves at the bottom"
    );
    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &ray), Some((1.0, 3.0)));
}

#[test]
pub(crate) fn a_sphere_away_from_the_origin_with_radius_2() {
    // Centre m = (1, −2, 3), radius ρ = 2, a ray from (1, 4, 3) straight
    // down: r0 − m = (0, 6, 0), so a = 1, b = −12, c = 32 and
    // t² − 12t + 32 = 0: t = 4 and t = 8.
    let (m, rho) = (Vec3::new(1.0, -2.0, 3.0), 2.0);
    let ray = Ray::new(Vec3::new(1.0, 4.0, 3.0), Vec3::NEG_Y);
    assert_eq!(
        sphere_roots_abc(m, rho, &ray),
        Some((4.0, 8.0)),
        "t² − 12t + 32 = 0 (r0 − m = (0, 6, 0), ρ = 2: a = 1, b = −12, c = 32, check yours on paper) has the roots 4 and 8"
    );
    // Sideways, 1 off the centre: the chord is 2·√(ρ² − 1) = 2√3 long.
    let ray = Ray::new(Vec3::new(-5.0, -1.0, 3.0), Vec3::X);
    let (t0, t1) = sphere_roots_abc(m, rho, &ray).expect("passes 1 from the centre: a hit");
    let chord = 2.0 * 3f32.sqrt();
    assert!(
        (t0 - (6.0 - chord / 2.0)).abs() < 1e-5 && (t1 - (6.0 + chord / 2.0)).abs() < 1e-5,
        "passing 1 from the centre of a sphere of radius 2: roots 6 ∓ √3, got {t0} and {t1}"
    );
}

#[test]
pub(crate) fn a_tangent_ray_touches_the_sphere_once() {
    // Along x, exactly 1 above the unit sphere's centre: a = 1, b = −10,
    // c = 25, and the discriminant b² − 4ac = 100 − 100 is exactly 0.
    let ray = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X);
    for (name, roots) in [
        ("sphere_roots_abc", sphere_roots_abc(Vec3::ZERO, 1.0, &ray)),
        ("sphere_roots", sphere_roots(Vec3::ZERO, 1.0, &ray)),
    ] {
        assert_eq!(
            roots,
            Some((5.0, 5.0)),
            "{name}: a tangent ray (discriminant exactly 0) touches the sphere at one point, \
             a double root t = 5; it is a hit, not None"
        );
    }
}

#[test]
pub(crate) fn a_ray_past_the_sphere_misses() {
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, 0.0, 0.0));
    let roots = sphere_roots_abc(Vec3::ZERO, 1.0, &ray);
    assert_eq!(
        roots, None,
        "a ray 2 above the unit sphere's centre passes by (negative discriminant), not {roots:?}"
    );
    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &ray), None);
}

#[test]
fn the_roots_of_a_line_are_behind_as_well_as_ahead() {
    // The roots are where the ray's whole line meets the sphere: going up
    // from above it, both lie behind the origin.
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y);
    assert_eq!(
        sphere_roots_abc(Vec3::ZERO, 1.0, &ray),
        Some((-3.0, -1.0)),
        "the line meets the sphere at t = −3 and t = −1 (behind the origin), nearest first"
    );
}

#[test]
pub(crate) fn the_nearest_root_ahead_is_the_hit() {
    let down = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::NEG_Y);
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &down, 0.0, INF),
        Some(1.0),
        "roots 1 and 3: the ray first meets the sphere at the nearest one, 1"
    );
    // Starting inside the sphere, the first hit ahead is the far side.
    let inside = Ray::new(Vec3::new(0.0, 0.5, 0.0), Vec3::NEG_Y);
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &inside, 0.0, INF),
        Some(1.5),
        "from inside the sphere (roots −0.5 and 1.5) the hit is the far root: the near one is behind"
    );
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &down, 1.5, INF),
        Some(3.0),
        "with t_min = 1.5 the near root 1 is too near: the hit is the far root 3"
    );
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &down, 0.0, 0.5),
        None,
        "both roots (1 and 3) are beyond t_max = 0.5: no hit"
    );
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &down, 0.0, 2.0),
        Some(1.0),
        "t_max = 2 lets the near root 1 through"
    );
}

#[test]
fn a_ray_leaving_the_sphere_does_not_hit_it_at_t_0() {
    // From the top of the unit sphere, straight up: the roots are −2 and 0.
    let ray = Ray::new(Vec3::Y, Vec3::Y);
    let (near, far) = sphere_roots(Vec3::ZERO, 1.0, &ray).unwrap();
    assert_eq!((near, far), (-2.0, 0.0));
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &ray, 0.0, INF),
        None,
        "a ray starting on the sphere meets it at t = 0, outside (t_min, t_max) = (0, ∞): \
         the bounds are strict"
    );
}

#[test]
fn a_sphere_behind_the_ray_is_not_hit() {
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &ray, 0.0, INF),
        None,
        "both roots (−3 and −1) are behind the ray's origin: no hit"
    );
}

#[test]
fn a_root_at_either_bound_is_no_hit() {
    // The range (t_min, t_max) is open at both ends.
    assert_eq!(
        nearest_root((1.0, 3.0), 1.0, 10.0),
        Some(3.0),
        "a root equal to t_min is no hit (t > t_min, not ≥): the far root is the hit"
    );
    assert_eq!(
        nearest_root((2.0, 3.0), 0.0, 2.0),
        None,
        "a root equal to t_max is no hit (t < t_max, not ≤)"
    );
    assert_eq!(nearest_root((2.0, 3.0), 0.0, 2.5), Some(2.0));
}
