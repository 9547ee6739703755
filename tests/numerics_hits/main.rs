//! The hard numerical cases of chapter 2's intersections, in the tracer's f32.
//!
//! Each case states a geometric fact and checks the tracer against an exact
//! answer computed in f64 from the same f32 inputs. Where a naive formula is
//! the reason for the case (the textbook quadratic, Möller–Trumbore), it is
//! written here too, and the test shows that it really fails: otherwise the
//! case would prove nothing.

use proptest::prelude::*;
use raybook::tracer::toolkit::Vec3;
use raybook::tracer::toolkit::scene::{Object, Shape};
use raybook::tracer::{
    Ray, closest_hit, hit_at, intersect, intersect_plane, intersect_sphere, intersect_triangle,
    sphere_roots,
};
use test_support::Rng;

const INF: f32 = f32::INFINITY;

/// Said by the cases that need more than the lecture's formulas, so that a
/// student who tries the lecture's method in the tracer (chapter 2's
/// exercises) knows that this failure is expected, not a mistake.
const NEEDS_STABLE: &str = "this needs the stable quadratic (chapter 2's sphere_roots); \
    the lecture's a, b, c formula in f32 is expected to fail here";
const NEEDS_WATERTIGHT: &str = "this needs the watertight test (chapter 2's intersect_triangle); \
    the lecture's method (the plane, then α and β) is expected to fail here";

/// |actual − exact| / |exact|.
fn relative_error(actual: f32, exact: f64) -> f64 {
    (actual as f64 - exact).abs() / exact.abs()
}

/// The near and far roots of the ray's line meeting the sphere: the textbook
/// formula, in f64, from the f32 inputs (the direction's length taken as it
/// is, not as 1). It is a reference independent of the tracer's formula, and
/// accurate enough here: f64 rounds the discriminant b² − 4ac by about
/// 10⁻¹⁶·b²; with |b| ≤ 2·10⁴ that moves the distance of closest approach by
/// about 10⁻⁶ (a ten-thousandth of a radius of 0.01) and the roots by less
/// than 10⁻⁸ relative.
fn exact_roots(center: Vec3, radius: f32, ray: &Ray) -> Option<(f64, f64)> {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.direction.as_dvec3();
    let r = radius as f64;
    let (a, b, c) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
    let discriminant = b * b - 4.0 * a * c;
    (discriminant >= 0.0).then(|| {
        let root = discriminant.sqrt();
        ((-b - root) / (2.0 * a), (-b + root) / (2.0 * a))
    })
}

/// The distance from the centre to the ray's line, in f64.
fn distance_from_line(center: Vec3, ray: &Ray) -> f64 {
    let f = ray.origin.as_dvec3() - center.as_dvec3();
    let d = ray.direction.as_dvec3().normalize();
    (f - f.dot(d) * d).length()
}

// ---------------------------------------------------------------- spheres --

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

/// The quadratic as first written down (a = d·d, b = 2f·d, c = f·f − r²),
/// all in f32: the near root, if the discriminant says there is one.
fn naive_near_root(center: Vec3, radius: f32, ray: &Ray) -> Option<f32> {
    let f = ray.origin - center;
    let a = ray.direction.dot(ray.direction);
    let b = 2.0 * f.dot(ray.direction);
    let c = f.dot(f) - radius * radius;
    let discriminant = b * b - 4.0 * a * c;
    (discriminant >= 0.0).then(|| (-b - discriminant.sqrt()) / (2.0 * a))
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

// ----------------------------------------------------------------- planes --

/// No NaN and no infinity in a triangle hit.
fn finite_triangle_hit(hit: Option<(f32, f32, f32)>) -> bool {
    hit.is_none_or(|(t, a, b)| t.is_finite() && a.is_finite() && b.is_finite())
}

#[test]
fn parallel_and_almost_parallel_rays() {
    // Exactly parallel: n·d = 0.
    let along = Ray::new(Vec3::new(0.3, 2.0, -0.7), Vec3::new(0.6, 0.0, 0.8));
    assert_eq!(
        intersect_plane(Vec3::Y, -2.0, &along, 0.0, INF),
        None,
        "in the plane"
    );
    assert_eq!(
        intersect_plane(Vec3::Y, 0.0, &along, 0.0, INF),
        None,
        "above it"
    );

    // A ray in a triangle's plane, through its inside: no single hit.
    let triangle = [
        Vec3::new(-2.1, 0.4, -1.9),
        Vec3::new(3.3, 0.4, -0.7),
        Vec3::new(0.2, 0.4, 4.1),
    ];
    for direction in [
        Vec3::X,
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(-0.28, 0.0, 0.96),
    ] {
        let ray = Ray::new(Vec3::new(0.1, 0.4, 0.3) - 7.0 * direction, direction);
        assert_eq!(intersect_triangle(triangle, &ray, 0.0, INF), None);
    }

    // Almost parallel: n·d = 10⁻⁷ gives t = 10⁷ from one unit away.
    let d = Vec3::new(1.0, 1e-7, 0.0);
    let below = Ray::new(Vec3::new(0.0, -1.0, 0.0), d);
    assert_eq!(below.direction.y, 1e-7);
    let t = intersect_plane(Vec3::Y, 0.0, &below, 0.0, INF).expect("far ahead");
    assert!(relative_error(t, 1e7) < 1e-6, "t = {t}");
    let above = Ray::new(Vec3::new(0.0, 1.0, 0.0), d);
    assert_eq!(
        intersect_plane(Vec3::Y, 0.0, &above, 0.0, INF),
        None,
        "behind"
    );

    // Even flatter, down to the smallest subnormal: t overflows, which is no
    // hit, never an infinite or NaN one.
    for tiny in [1e-20, 1e-38, 1e-45] {
        let ray = Ray {
            origin: Vec3::new(0.0, -1e20, 0.0),
            direction: Vec3::new(1.0, tiny, 0.0),
        };
        let hit = intersect_plane(Vec3::Y, 0.0, &ray, 0.0, INF);
        assert!(hit.is_none_or(f32::is_finite), "{tiny}: {hit:?}");
    }

    // The same tilt against the triangle: from 10⁻⁷ below its plane, the
    // ray meets it after one unit, inside it.
    let ray = Ray::new(Vec3::new(-0.9, 0.4 - 1e-7, 0.3), d);
    let hit = intersect_triangle(triangle, &ray, 0.0, INF);
    assert!(finite_triangle_hit(hit), "{hit:?}");

    // Almost parallel to the triangle, in many awkward directions: a finite
    // hit or none.
    let mut rng = Rng(7);
    for _ in 0..1000 {
        let tilt = rng.range(-1e-6, 1e-6);
        let heading = rng.range(0.0, std::f32::consts::TAU);
        let d = Vec3::new(heading.cos(), tilt, heading.sin());
        let origin = Vec3::new(rng.range(-1.0, 1.0), 0.4, rng.range(-1.0, 1.0)) - 3.0 * d;
        let hit = intersect_triangle(triangle, &Ray::new(origin, d), 0.0, INF);
        assert!(finite_triangle_hit(hit), "{hit:?}");
        let hit = intersect_plane(Vec3::Y, -0.4, &Ray::new(origin, d), 0.0, INF);
        assert!(hit.is_none_or(f32::is_finite), "{hit:?}");
    }
}

// -------------------------------------------------------------- triangles --

/// Möller–Trumbore as usually written: the barycentric coordinates (u, v) by
/// Cramer's rule from the edges leaving corner a, two-sided, in f32.
fn moller_trumbore([a, b, c]: [Vec3; 3], ray: &Ray) -> Option<f32> {
    let (e1, e2) = (b - a, c - a);
    let p = ray.direction.cross(e2);
    let determinant = e1.dot(p);
    if determinant == 0.0 {
        return None;
    }
    let inverse = 1.0 / determinant;
    let s = ray.origin - a;
    let u = s.dot(p) * inverse;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = ray.direction.dot(q) * inverse;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = e2.dot(q) * inverse;
    (t > 0.0).then_some(t)
}

/// Whether the ray's line passes through the triangle, decided in f64: the
/// three volumes d·((p − r0) × (q − r0)) over the edges pq have one sign.
/// The f32 inputs make these exact to about 10⁻¹⁶, far below the f32
/// rounding that the tests look at, so this is the geometric truth.
fn passes_through([a, b, c]: [Vec3; 3], ray: &Ray) -> bool {
    let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
    let [a, b, c] = [a, b, c].map(|p| p.as_dvec3() - o);
    let volumes = [d.dot(a.cross(b)), d.dot(b.cross(c)), d.dot(c.cross(a))];
    volumes.iter().all(|&v| v >= 0.0) || volumes.iter().all(|&v| v <= 0.0)
}

/// Two triangles (a, b, c) and (b, a, d) sharing the edge ab, wound the same
/// way as in a mesh, with awkward coordinates and a little fold between them.
fn triangle_pair(rng: &mut Rng) -> ([Vec3; 3], [Vec3; 3], Vec3) {
    let (a, b) = (rng.vec(-10.0, 10.0), rng.vec(-10.0, 10.0));
    let normal = (b - a).cross(rng.unit()).normalize();
    let across = normal.cross(b - a); // in the plane, perpendicular to ab
    let mid = (a + b) / 2.0;
    let c = mid + rng.range(0.2, 1.0) * across + rng.range(-0.1, 0.1) * (b - a).length() * normal;
    let d = mid - rng.range(0.2, 1.0) * across + rng.range(-0.1, 0.1) * (b - a).length() * normal;
    ([a, b, c], [b, a, d], normal)
}

/// A ray through p from a random point in front of or behind the surface,
/// at most about 33° (atan 0.55) from its normal.
fn ray_through(p: Vec3, normal: Vec3, rng: &mut Rng) -> Ray {
    let side = if rng.range(-1.0, 1.0) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let direction = (side * normal + 0.55 * rng.unit()).normalize();
    let origin = p + rng.range(1.0, 30.0) * direction;
    Ray::new(origin, p - origin)
}

#[test]
fn shared_edges_have_no_cracks_unlike_moller_trumbore() {
    // 20 seeded pairs, 1000 rays each through points spread along the shared
    // edge. Each ray passes through one triangle or the other (checked in
    // f64), so a ray that neither test hits is a crack. Möller–Trumbore
    // decides the shared edge in each triangle from different numbers
    // (r0 − a and b − a in one, r0 − b and a − b in the other), whose
    // roundings can put a ray outside both; the edge functions of
    // `intersect_triangle` compute the same value, of opposite sign, for both.
    let mut rng = Rng(0x5eed_2024);
    let (mut rays, mut cracks, mut naive_cracks) = (0, 0, 0);
    for _ in 0..20 {
        let (left, right, normal) = triangle_pair(&mut rng);
        let [a, b, _] = left;
        for i in 0..1000 {
            let p = a.lerp(b, (i as f32 + 0.5) / 1000.0);
            let ray = ray_through(p, normal, &mut rng);
            rays += 1;
            assert!(passes_through(left, &ray) || passes_through(right, &ray));
            let hits = [left, right].map(|tri| intersect_triangle(tri, &ray, 0.0, INF));
            assert!(hits.into_iter().all(finite_triangle_hit), "{hits:?}");
            if hits.iter().all(Option::is_none) {
                cracks += 1;
            }
            if [left, right]
                .iter()
                .all(|&tri| moller_trumbore(tri, &ray).is_none())
            {
                naive_cracks += 1;
            }
        }
    }
    println!(
        "{rays} rays through shared edges: {cracks} cracks, {naive_cracks} with Möller–Trumbore"
    );
    assert_eq!(
        cracks, 0,
        "rays through a shared edge fell between the triangles: {NEEDS_WATERTIGHT}"
    );
    assert!(
        naive_cracks > 0,
        "Möller–Trumbore was expected to leave a crack"
    );
}

#[test]
fn a_fan_has_no_hole_at_its_shared_vertex() {
    let mut rng = Rng(0xfa7);
    let (mut rays, mut naive_holes) = (0, 0);
    for _ in 0..10 {
        // Eight triangles around an apex slightly raised above their rim.
        let normal = rng.unit();
        let u = normal.any_orthonormal_vector();
        let v = normal.cross(u);
        let rim_center = rng.vec(-10.0, 10.0);
        let apex = rim_center + 0.2 * normal;
        let rim: Vec<Vec3> = (0..8)
            .map(|i| {
                let angle = (i as f32 + rng.range(-0.3, 0.3)) * std::f32::consts::TAU / 8.0;
                rim_center + rng.range(0.7, 1.3) * (angle.cos() * u + angle.sin() * v)
            })
            .collect();
        let fan: Vec<[Vec3; 3]> = (0..8).map(|i| [apex, rim[i], rim[(i + 1) % 8]]).collect();
        for _ in 0..1000 {
            let ray = ray_through(apex, normal, &mut rng);
            rays += 1;
            assert!(fan.iter().any(|&tri| passes_through(tri, &ray)));
            let hits: Vec<_> = fan
                .iter()
                .map(|&tri| intersect_triangle(tri, &ray, 0.0, INF))
                .collect();
            assert!(hits.iter().all(|&hit| finite_triangle_hit(hit)));
            assert!(
                hits.iter().any(Option::is_some),
                "a ray through the apex fell through: {ray:?}; {NEEDS_WATERTIGHT}"
            );
            if fan.iter().all(|&tri| moller_trumbore(tri, &ray).is_none()) {
                naive_holes += 1;
            }
        }
    }
    println!("{rays} rays through fan apexes: 0 holes, {naive_holes} with Möller–Trumbore");
}

#[test]
fn a_ray_along_an_edge_in_the_plane_hits_nothing() {
    // The triangle lies in a coordinate plane, so a ray along an edge is
    // exactly in its plane (a tilted plane would round it slightly off).
    let corners = [
        Vec3::new(-1.37, 0.3, 0.91),
        Vec3::new(2.13, 0.3, -0.47),
        Vec3::new(0.59, 0.3, 3.07),
    ];
    for axes in [[0, 1, 2], [1, 2, 0], [2, 0, 1]] {
        let triangle = corners.map(|p| Vec3::new(p[axes[0]], p[axes[1]], p[axes[2]]));
        for i in 0..3 {
            let (from, to) = (triangle[i], triangle[(i + 1) % 3]);
            for (start, direction) in [
                (from - 0.37 * (to - from), to - from), // before the edge, along it
                (from, to - from),                      // from a corner, along it
                (to + 0.37 * (to - from), from - to),   // beyond it, back along it
            ] {
                let ray = Ray::new(start, direction);
                assert_eq!(
                    intersect_triangle(triangle, &ray, 0.0, INF),
                    None,
                    "{ray:?}"
                );
            }
        }
    }
}

// ------------------------------------------------------------ closest hit --

fn shape() -> impl Strategy<Value = Shape> {
    let point = || prop::array::uniform3(-10.0f32..10.0).prop_map(Vec3::from);
    let direction = || {
        prop::array::uniform3(-1.0f32..1.0)
            .prop_filter("a direction", |v| Vec3::from(*v).length() > 0.1)
            .prop_map(|v| Vec3::from(v).normalize())
    };
    prop_oneof![
        (point(), 0.1f32..4.0).prop_map(|(center, radius)| Shape::Sphere { center, radius }),
        (direction(), -10.0f32..10.0).prop_map(|(normal, offset)| Shape::Plane { normal, offset }),
        prop::array::uniform3(point()).prop_map(|vertices| Shape::Triangle { vertices }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The closest hit is no farther than any object's own hit, it is one of
    /// them, and there is none only when every object misses.
    #[test]
    fn closest_hit_is_closest(
        shapes in prop::collection::vec(shape(), 1..12),
        origin in prop::array::uniform3(-15.0f32..15.0),
        direction in prop::array::uniform3(-1.0f32..1.0),
    ) {
        prop_assume!(Vec3::from(direction).length() > 0.1);
        let ray = Ray::new(Vec3::from(origin), Vec3::from(direction));
        let objects: Vec<Object> = shapes
            .iter()
            .map(|&shape| Object { shape, material: 0, shadows: true })
            .collect();
        let each: Vec<Option<f32>> =
            shapes.iter().map(|shape| intersect(shape, &ray, 0.0, INF)).collect();
        match closest_hit(&objects, &ray, 0.0, INF) {
            None => prop_assert!(each.iter().all(Option::is_none), "missed {each:?}"),
            Some(hit) => {
                prop_assert!(hit.t.is_finite() && hit.t > 0.0);
                for t in each.iter().flatten() {
                    prop_assert!(hit.t <= *t, "closest {} but object at {t}", hit.t);
                }
                prop_assert_eq!(each[hit.object], Some(hit.t));
            }
        }
    }
}
