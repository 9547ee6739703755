//! The triangle: the lecture's test (the plane, then α and β) and the watertight one.

use ch02_hits::toolkit::Vec3;
use ch02_hits::{Ray, intersect_triangle, triangle_by_plane};
use test_support::Rng;

use super::INF;

/// The worked example's triangle: p₀ = (0, 0, −1), p₁ = (4, 0, −1),
/// p₂ = (0, 2, −1), in the plane z = −1.
const CORNERS: [Vec3; 3] = [
    Vec3::new(0.0, 0.0, -1.0),
    Vec3::new(4.0, 0.0, -1.0),
    Vec3::new(0.0, 2.0, -1.0),
];

/// A ray from (x, y, 3) straight down the z axis: it meets the triangle's
/// plane at t = 4, in the point (x, y, −1).
fn down_z(x: f32, y: f32) -> Ray {
    Ray::new(Vec3::new(x, y, 3.0), Vec3::NEG_Z)
}

#[test]
pub(crate) fn the_triangle_worked_example() {
    // e₁ = (4, 0, 0), e₂ = (0, 2, 0), N = e₁ × e₂ = (0, 0, 8), n = (0, 0, 1),
    // d = −n·p₀ = 1. From (2, 0.5, 3) along −z: t = −(3 + 1)/(−1) = 4 and
    // x = (2, 0.5, −1); w = x − p₀ = (2, 0.5, 0), w × e₂ = (0, 0, 4) and
    // e₁ × w = (0, 0, 2), so α = 4/8 = 0.5 and β = 2/8 = 0.25.
    let hit = triangle_by_plane(CORNERS, &down_z(2.0, 0.5), 0.0, INF);
    assert_eq!(
        hit,
        Some((4.0, 0.5, 0.25)),
        "the worked example: t = 4, α = 0.5 (the weight of p₁ = p₀ + e₁), β = 0.25 (of p₂)"
    );
    // The tracer's watertight test agrees.
    let (t, alpha, beta) = intersect_triangle(CORNERS, &down_z(2.0, 0.5), 0.0, INF).unwrap();
    assert!((t - 4.0).abs() < 1e-6 && (alpha - 0.5).abs() < 1e-6 && (beta - 0.25).abs() < 1e-6);
}

#[test]
pub(crate) fn the_triangle_has_its_edges_and_corners() {
    for ((x, y), (alpha, beta), place) in [
        ((2.0, 1.0), (0.5, 0.5), "on the edge p₁p₂, where α + β = 1"),
        ((1.0, 0.0), (0.25, 0.0), "on the edge p₀p₁, where β = 0"),
        ((0.0, 1.5), (0.0, 0.75), "on the edge p₀p₂, where α = 0"),
        ((4.0, 0.0), (1.0, 0.0), "on the corner p₁"),
        ((0.0, 2.0), (0.0, 1.0), "on the corner p₂"),
        ((0.0, 0.0), (0.0, 0.0), "on the corner p₀"),
    ] {
        let hit = triangle_by_plane(CORNERS, &down_z(x, y), 0.0, INF);
        assert_eq!(
            hit,
            Some((4.0, alpha, beta)),
            "the point ({x}, {y}, −1) is {place}: it belongs to the triangle (0 ≤ α, 0 ≤ β, \
             α + β ≤ 1 with equality allowed), at α = {alpha}, β = {beta}"
        );
    }
}

#[test]
pub(crate) fn points_outside_the_triangle_are_missed() {
    for ((x, y), place) in [
        ((2.5, 1.0), "beyond the edge p₁p₂ (α + β = 1.125 > 1)"),
        ((1.0, -0.5), "below the edge p₀p₁ (β < 0)"),
        ((-0.5, 1.0), "left of the edge p₀p₂ (α < 0)"),
        (
            (3.0, 1.5),
            "far beyond p₁p₂ (α + β = 1.5 > 1), with α and β each below 1",
        ),
    ] {
        let hit = triangle_by_plane(CORNERS, &down_z(x, y), 0.0, INF);
        assert_eq!(
            hit, None,
            "the point ({x}, {y}, −1) of the plane lies {place}: outside the triangle"
        );
    }
}

#[test]
pub(crate) fn the_triangle_is_hit_from_both_sides_but_not_from_behind_the_origin() {
    let back = Ray::new(Vec3::new(2.0, 0.5, -5.0), Vec3::Z);
    assert_eq!(
        triangle_by_plane(CORNERS, &back, 0.0, INF),
        Some((4.0, 0.5, 0.25)),
        "from the other side (n·rd > 0) the triangle is hit too: both sides count"
    );
    let away = Ray::new(Vec3::new(2.0, 0.5, 3.0), Vec3::Z);
    assert_eq!(
        triangle_by_plane(CORNERS, &away, 0.0, INF),
        None,
        "the triangle is 4 units behind a ray going away from it (t = −4 < t_min)"
    );
    assert_eq!(
        triangle_by_plane(CORNERS, &down_z(2.0, 0.5), 0.0, 3.5),
        None,
        "t = 4 is beyond t_max = 3.5"
    );
    assert_eq!(
        triangle_by_plane(CORNERS, &down_z(2.0, 0.5), 4.5, INF),
        None,
        "t = 4 is below t_min = 4.5"
    );
}

#[test]
pub(crate) fn a_ray_parallel_to_the_triangle_misses_it() {
    for (z, place) in [(0.0, "above"), (-1.0, "in")] {
        let ray = Ray::new(Vec3::new(-3.0, 0.5, z), Vec3::X);
        let hit = triangle_by_plane(CORNERS, &ray, 0.0, INF);
        assert_eq!(
            hit, None,
            "a ray parallel to the triangle's plane, {place} it, meets it nowhere (or everywhere): \
             no hit, not {hit:?}"
        );
    }
}

/// (α, β) of the point where the ray's line meets the triangle's plane,
/// inside the triangle or not, in f64.
fn line_barycentrics([p0, p1, p2]: [Vec3; 3], ray: &Ray) -> (f32, f32) {
    let [p0, p1, p2] = [p0, p1, p2].map(|p| p.as_dvec3());
    let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
    let (e1, e2) = (p1 - p0, p2 - p0);
    let n = e1.cross(e2);
    let w = o + (n.dot(p0 - o) / n.dot(d)) * d - p0;
    let (alpha, beta) = (w.cross(e2).dot(n) / n.dot(n), e1.cross(w).dot(n) / n.dot(n));
    (alpha as f32, beta as f32)
}

#[test]
fn the_lectures_triangle_test_agrees_with_the_watertight_one_away_from_the_edges() {
    // Tilted triangles of all shapes and rays from all sides. Where the
    // point is clearly inside or outside (farther than 10⁻³ from an edge in
    // α, β or 1 − α − β), both tests must agree on hit or miss, t, α and β.
    let mut rng = Rng(0x7e57_0002);
    let mut compared = 0;
    for _ in 0..2000 {
        let corners = [rng.vec(-3.0, 3.0), rng.vec(-3.0, 3.0), rng.vec(-3.0, 3.0)];
        let origin = rng.vec(-8.0, 8.0);
        let aim = corners[0]
            + rng.range(-0.5, 1.5) * (corners[1] - corners[0])
            + rng.range(-0.5, 1.5) * (corners[2] - corners[0]);
        let ray = Ray::new(origin, aim - origin);
        let n = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
        if n.length() < 0.1 || n.normalize().dot(ray.direction).abs() < 0.1 {
            continue; // a sliver, or a ray at a grazing angle
        }
        let (a, b) = line_barycentrics(corners, &ray);
        if [a, b, 1.0 - a - b].iter().any(|w| w.abs() < 1e-3) {
            continue; // too close to an edge to tell
        }
        compared += 1;
        let expected = intersect_triangle(corners, &ray, 0.0, INF);
        let lecture = triangle_by_plane(corners, &ray, 0.0, INF);
        match (expected, lecture) {
            (None, None) => {}
            (Some((t, a, b)), Some((t2, a2, b2))) => assert!(
                (t - t2).abs() < 1e-4 * t.max(1.0)
                    && (a - a2).abs() < 1e-4
                    && (b - b2).abs() < 1e-4,
                "corners {corners:?}, {ray:?}: expected t = {t}, α = {a}, β = {b}, \
                 got t = {t2}, α = {a2}, β = {b2} (α is the weight of p₁, β of p₂)"
            ),
            _ => panic!(
                "corners {corners:?}, {ray:?}: expected {expected:?}, got {lecture:?} \
                 (α = {a}, β = {b} on the ray's line)"
            ),
        }
    }
    assert!(compared > 1000, "only {compared} rays compared");
}

#[test]
fn shared_edges_let_rays_through_the_lectures_triangle_test() {
    // Pairs of triangles (p₀, p₁, p₂) and (p₁, p₀, p₃) that share the edge
    // p₀p₁, as in a mesh, and rays through points of that edge. Every ray
    // passes through one triangle or the other; one that both tests miss has
    // fallen through a crack. The lecture's method decides the edge from
    // each triangle's own plane and hit point, so rounding can put the ray
    // outside both; the watertight test cannot (tests/numerics_hits/triangles.rs at the
    // workspace root does the same with Möller–Trumbore, on 20 000 rays).
    let mut rng = Rng(0x5eed_2025);
    let (mut rays, mut lecture_cracks, mut watertight_cracks) = (0, 0, 0);
    for _ in 0..10 {
        let (p0, p1) = (rng.vec(-10.0, 10.0), rng.vec(-10.0, 10.0));
        let normal = (p1 - p0).cross(rng.vec(-1.0, 1.0)).normalize();
        let across = normal.cross(p1 - p0);
        let mid = (p0 + p1) / 2.0;
        let fold = |rng: &mut Rng| rng.range(-0.1, 0.1) * (p1 - p0).length() * normal;
        let p2 = mid + rng.range(0.2, 1.0) * across + fold(&mut rng);
        let p3 = mid - rng.range(0.2, 1.0) * across + fold(&mut rng);
        let pair = [[p0, p1, p2], [p1, p0, p3]];
        for i in 0..1000 {
            let x = p0.lerp(p1, (i as f32 + 0.5) / 1000.0);
            let side = if i % 2 == 0 { 1.0 } else { -1.0 };
            let direction = (side * normal + 0.5 * rng.vec(-1.0, 1.0)).normalize();
            let origin = x + rng.range(1.0, 30.0) * direction;
            let ray = Ray::new(origin, x - origin);
            rays += 1;
            if pair
                .iter()
                .all(|&tri| triangle_by_plane(tri, &ray, 0.0, INF).is_none())
            {
                lecture_cracks += 1;
            }
            if pair
                .iter()
                .all(|&tri| intersect_triangle(tri, &ray, 0.0, INF).is_none())
            {
                watertight_cracks += 1;
            }
        }
    }
    println!(
        "{rays} rays through shared edges: {lecture_cracks} fell through with the lecture's \
         method (triangle_by_plane), {watertight_cracks} with the watertight test"
    );
    assert_eq!(
        watertight_cracks, 0,
        "rays through a shared edge fell between the tracer's triangles"
    );
}
