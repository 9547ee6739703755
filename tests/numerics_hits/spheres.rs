//! Spheres: tangent rays, far tiny spheres, huge close spheres, and chords.

use proptest::prelude::*;
use raybook::tracer::toolkit::Vec3;
use raybook::tracer::toolkit::scene::Shape;
use raybook::tracer::{Ray, hit_at, intersect, intersect_sphere, sphere_roots};
use test_support::Rng;

use super::{INF, NEEDS_STABLE, relative_error};

/// The near and far roots of the ray's line meeting the sphere, in f64, from
/// the f32 inputs (the direction's length taken as it is, not as 1), by
/// geometry rather than by a quadratic's coefficients: the line's point
/// closest to the centre is at t_c, at distance |h|; the sphere cuts a chord
/// of half length √(ρ² − |h|²) around it. A reference independent of the
/// tracer's root formula, and accurate far beyond what is checked here: h
/// is the one difference of nearly equal vectors (both about |f| long), and
/// f64 gets it to about 10⁻¹⁶·|f|, 10⁻¹² at 10⁴ units, a ten-billionth of a
/// radius of 0.01.
fn exact_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f64, f64)> {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.direction.as_dvec3();
    let r = radius as f64;
    let t_closest = -f.dot(d) / d.dot(d);
    let h = f + t_closest * d;
    let half_chord2 = r * r - h.dot(h);
    (half_chord2 >= 0.0).then(|| {
        let half = (half_chord2 / d.dot(d)).sqrt();
        (t_closest - half, t_closest + half)
    })
}

/// The distance from the centre to the ray's line, in f64.
fn distance_from_line(center: Vec3, ray: &Ray) -> f64 {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.direction.as_dvec3().normalize();
    (f - f.dot(d) * d).length()
}

#[test]
fn worked_example_hits_at_1_and_3() {
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &ray), Some((1.0, 3.0)));
}

#[test]
fn tangent_ray_touches_once_and_near_misses_are_decided() {
    // Along x, 1 unit (exactly) above the unit sphere's centre: tangent.
    let past = |height: f32| Ray::new(Vec3::new(-5.0, height, 0.0), Vec3::X);
    let (t0, t1) = sphere_roots(Vec3::ZERO, 1.0, &past(1.0)).expect("a tangent ray touches");
    assert!(t0.is_finite() && t1.is_finite());
    assert_eq!(t0, t1, "a tangent ray has a double root");
    assert_eq!(t0, 5.0);

    let (t0, t1) = sphere_roots(Vec3::ZERO, 1.0, &past(1.0 - 1e-4)).expect("just inside hits");
    assert!(t0.is_finite() && t1.is_finite() && t0 < t1, "{t0} {t1}");
    // Two roots 2·√(1 − 0.9999²) ≈ 0.0283 apart.
    assert!((t1 - t0 - 0.028_283).abs() < 1e-4, "{}", t1 - t0);

    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &past(1.0 + 1e-4)), None);

    // Tangent from a point on the sphere: c' = 0 and q = 0, so c'/q is 0/0;
    // min and max drop that NaN and leave the double root 0.
    let on_surface = Ray::new(Vec3::Y, Vec3::X);
    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &on_surface), Some((0.0, 0.0)));
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &on_surface, 0.0, INF),
        None
    );

    // The same in an awkward frame. Built from f32 numbers, the ray is
    // tangent only up to rounding: its distance ρ from the centre (in f64)
    // is 1 within 10⁻⁶. The tracer must answer for that ray: a chord of
    // 2·√(1 − ρ²) if ρ ≤ 1, nothing if ρ > 1, and never a NaN.
    let center = Vec3::new(3.7, -1.3, 2.9);
    let d = Vec3::new(0.3, -0.7, 0.55).normalize();
    let side = d.cross(Vec3::new(1.0, 2.0, 3.0)).normalize();
    let past = |height: f32| Ray::new(center - 5.0 * d + height * side, d);
    let rho = distance_from_line(center, &past(1.0));
    assert!((rho - 1.0).abs() < 1e-6, "ρ = {rho}");
    match sphere_roots(center, 1.0, &past(1.0)) {
        Some((t0, t1)) => {
            let chord = 2.0 * (1.0 - rho * rho).sqrt();
            assert!(
                ((t1 - t0) as f64 - chord).abs() < 1e-5,
                "{t0} {t1}, ρ = {rho}: {NEEDS_STABLE}"
            );
        }
        None => assert!(rho > 1.0, "ρ = {rho}: {NEEDS_STABLE}"),
    }
    let (t0, t1) = sphere_roots(center, 1.0, &past(1.0 - 1e-4))
        .unwrap_or_else(|| panic!("just inside missed: {NEEDS_STABLE}"));
    assert!(t0 < t1, "{t0} {t1}: {NEEDS_STABLE}");
    assert_eq!(
        sphere_roots(center, 1.0, &past(1.0 + 1e-4)),
        None,
        "just outside hit: {NEEDS_STABLE}"
    );
}

/// The quadratic as first written down, all in f32 (chapter 2's lecture
/// method, `sphere_roots_abc`): the near root, if the discriminant says
/// there is one.
fn naive_near_root(center: Vec3, radius: f32, ray: &Ray) -> Option<f32> {
    ch02_hits::sphere_roots_abc(center, radius, ray).map(|(near, _)| near)
}

/// How the naive formula went wrong on one far tiny sphere.
#[derive(Debug, Default)]
struct NaiveFailures {
    misses: u32,
    t_off: u32,
    misses_at_0_9: u32,
    hits_at_1_1: u32,
    any: u32,
}

/// A sphere of radius 0.01 at distance 10⁴ along the ray, and rays parallel
/// to it moved sideways by 0, 0.9 and 1.1 radii: the tracer must hit, hit and
/// miss, with t within 10⁻⁴ relative. Counts in `naive` how the naive
/// formula fared on the same rays.
fn far_tiny_sphere(origin: Vec3, direction: Vec3, side: Vec3, naive: &mut NaiveFailures) {
    let radius = 0.01;
    let center = origin + 1e4 * direction;
    let ray = |offset: f32| Ray::new(origin + offset * radius * side, direction);
    let context = format!("origin {origin}, direction {direction}, side {side}");

    for offset in [0.0, 0.9] {
        let exact = exact_roots(center, radius, &ray(offset))
            .expect("the reference hits")
            .0;
        let (t, _) = sphere_roots(center, radius, &ray(offset))
            .unwrap_or_else(|| panic!("missed at {offset} r: {context}; {NEEDS_STABLE}"));
        let error = relative_error(t, exact);
        assert!(
            error < 1e-4,
            "{offset} r: t = {t}, exact {exact}, {context}; {NEEDS_STABLE}"
        );
    }
    assert!(exact_roots(center, radius, &ray(1.1)).is_none());
    assert_eq!(
        sphere_roots(center, radius, &ray(1.1)),
        None,
        "hit at 1.1 r: {context}; {NEEDS_STABLE}"
    );

    let exact = exact_roots(center, radius, &ray(0.0)).unwrap().0;
    let through_centre = naive_near_root(center, radius, &ray(0.0));
    let failures = [
        through_centre.is_none(),
        through_centre.is_some_and(|t| relative_error(t, exact) > 1e-4),
        naive_near_root(center, radius, &ray(0.9)).is_none(),
        naive_near_root(center, radius, &ray(1.1)).is_some(),
    ];
    naive.misses += failures[0] as u32;
    naive.t_off += failures[1] as u32;
    naive.misses_at_0_9 += failures[2] as u32;
    naive.hits_at_1_1 += failures[3] as u32;
    naive.any += failures.contains(&true) as u32;
}

#[test]
fn far_tiny_sphere_is_hit_where_the_naive_formula_fails() {
    // The naive discriminant b² − 4ac is the difference of two numbers near
    // 4·10⁸, where f32 steps by 32, while its true value is 4·(r² − offset²),
    // below 4·10⁻⁴: what is left is rounding noise.

    // One sphere along an awkward direction. Here the noise happens to be 0:
    // the naive formula hits all three rays at t = 10⁴ (1e-6 off), including
    // the one that passes 1.1 radii from the centre.
    let d = Vec3::new(0.48, -0.6, 0.64).normalize();
    let mut naive = NaiveFailures::default();
    far_tiny_sphere(
        Vec3::new(0.3, -1.7, 2.9),
        d,
        d.cross(Vec3::Y).normalize(),
        &mut naive,
    );
    assert_eq!(naive.hits_at_1_1, 1, "{naive:?}");

    // A thousand more, from random origins in random directions.
    let mut rng = Rng(0x7e57_0003);
    let mut naive = NaiveFailures::default();
    for _ in 0..1000 {
        let (origin, d) = (rng.vec(-3.0, 3.0), rng.unit());
        far_tiny_sphere(origin, d, d.cross(rng.unit()).normalize(), &mut naive);
    }
    println!("naive quadratic on 1000 far tiny spheres: {naive:?}");
    // Every way of failing shows up, and in most of the cases.
    assert!(naive.misses > 0 && naive.t_off > 0, "{naive:?}");
    assert!(
        naive.misses_at_0_9 > 0 && naive.hits_at_1_1 > 0,
        "{naive:?}"
    );
    assert!(naive.any > 500, "{naive:?}");
}

#[test]
fn huge_sphere_close_to_the_ray_origin() {
    // The surface of a sphere of radius 10⁴ passes through y = 0; the ray
    // starts 10⁻² above it and points at the centre.
    let center = Vec3::new(0.0, -1e4, 0.0);
    let ray = Ray::new(Vec3::new(0.0, 1e-2, 0.0), Vec3::NEG_Y);
    let t = intersect_sphere(center, 1e4, &ray, 0.0, INF)
        .unwrap_or_else(|| panic!("missed: {NEEDS_STABLE}"));
    assert!(
        relative_error(t, 1e-2) < 1e-3,
        "t = {t}, exact 0.01: {NEEDS_STABLE}"
    );

    // The same in an awkward direction, against the exact distance (the
    // rounded centre moves the sphere by up to half a unit in the last place,
    // about 5·10⁻⁴, so the exact distance itself is only near 10⁻²).
    let n = Vec3::new(0.36, 0.48, -0.8).normalize();
    let origin = Vec3::new(0.7, -0.2, 1.3);
    let center = origin - (1e4 + 1e-2) * n;
    let ray = Ray::new(origin, -n);
    let exact = exact_roots(center, 1e4, &ray).unwrap().0;
    let t = intersect_sphere(center, 1e4, &ray, 0.0, INF)
        .unwrap_or_else(|| panic!("missed: {NEEDS_STABLE}"));
    println!("huge sphere, awkward: t = {t}, exact {exact}");
    assert!(
        relative_error(t, exact) < 1e-3,
        "t = {t}, exact {exact}: {NEEDS_STABLE}"
    );
}

/// A point on the sphere hit by a random ray, and a direction into the sphere
/// at `angle` from the inward normal, turned by `azimuth` around it.
fn chord_case(
    center: Vec3,
    radius: f32,
    eye: Vec3,
    aim: Vec3,
    angle: f32,
    azimuth: f32,
) -> (Vec3, Vec3) {
    let shape = Shape::Sphere { center, radius };
    let ray = Ray::new(eye, center + 0.9 * radius * aim - eye);
    let t = intersect(&shape, &ray, 0.0, INF).expect("aimed inside the sphere");
    let hit = hit_at(&shape, &ray, t, 0);
    let inward = -hit.normal;
    let u = inward.any_orthonormal_vector();
    let v = inward.cross(u);
    let sideways = azimuth.cos() * u + azimuth.sin() * v;
    (hit.point, angle.cos() * inward + angle.sin() * sideways)
}

proptest! {
    /// From a point where a ray hit the sphere, a ray into the sphere at angle
    /// θ to the inward normal crosses it along a chord of length 2r·cos θ.
    /// (That it never re-hits the sphere when pointing outward needs an
    /// origin offset, which a later chapter adds; not tested here.)
    #[test]
    fn chord_from_a_hit_point_has_length_2r_cos(
        center in prop::array::uniform3(-10.0f32..10.0),
        radius in 0.5f32..5.0,
        eye_direction in prop::array::uniform3(-1.0f32..1.0),
        eye_distance in 1.5f32..20.0,
        aim in prop::array::uniform3(-0.57f32..0.57),
        angle in 0.0f32..1.35,
        azimuth in 0.0f32..std::f32::consts::TAU,
    ) {
        let center = Vec3::from(center);
        let eye_direction = Vec3::from(eye_direction);
        prop_assume!(eye_direction.length() > 0.1);
        let eye = center + eye_distance * radius * eye_direction.normalize();
        let (point, direction) =
            chord_case(center, radius, eye, Vec3::from(aim), angle, azimuth);
        let ray = Ray::new(point, direction);
        let (near, far) = sphere_roots(center, radius, &ray).expect("starts on the sphere");
        prop_assert!(near.is_finite() && far.is_finite());
        // The geometry: θ measured from the actual point to the centre, in f64.
        let to_center = (center.as_dvec3() - point.as_dvec3()).normalize();
        let cos = to_center.dot(ray.direction.as_dvec3().normalize());
        let chord = 2.0 * radius as f64 * cos;
        prop_assert!(relative_error(far, chord) < 1e-4, "far {far}, 2r·cos θ = {chord}");
        // The near root is the start point itself, up to rounding.
        prop_assert!(near.abs() < 1e-5 * radius.max(center.abs().max_element()), "near {near}");
    }
}
