//! Chapter 2: the three intersections, the closest hit, and the pictures.

use ch02_hits::toolkit::scene::{Object, Shape};
use ch02_hits::toolkit::{Image, Scene, Vec3};
use ch02_hits::workbench::compare::{Tolerance, compare};
use ch02_hits::workbench::snapshot::{assert_image, check, reference_path};
use ch02_hits::{
    CHAPTER, Ray, View, closest_hit, intersect, intersect_plane, intersect_sphere,
    intersect_triangle, render_hits, sphere_roots, sphere_roots_abc, triangle_by_plane,
};
use test_support::Rng;

const INF: f32 = f32::INFINITY;

fn scene() -> Scene {
    CHAPTER.default_scene().unwrap().with_size(160, 120)
}

fn render(scene: &Scene, view: View) -> Image {
    render_hits(scene, view, || {}).0
}

// ------------------------------------------------------------------ plane --

#[test]
fn plane_hit_solves_n_dot_x_plus_d() {
    // The plane y = 1 is n = (0, 1, 0), d = −1.
    let ray = Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 0.0, INF),
        Some(4.0),
        "a ray from y = 5 straight down meets the plane y = 1 (n = (0, 1, 0), d = −1) at t = 4, \
         where n·r(t) + d = 0"
    );
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 0.0, 3.0),
        None,
        "t = 4 is beyond t_max = 3: no hit"
    );
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 4.5, INF),
        None,
        "t = 4 is below t_min = 4.5: no hit"
    );
}

#[test]
fn a_plane_behind_the_ray_is_not_hit() {
    // Going up from y = 5, the plane y = 1 is behind: t = −4.
    let ray = Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::Y);
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 0.0, INF),
        None,
        "the plane y = 1 is 4 units behind a ray going up from y = 5 (t = −4 < t_min)"
    );
}

#[test]
fn a_ray_leaving_the_plane_does_not_hit_it_at_t_0() {
    // From a point of the floor, going up or down: the only solution is t = 0,
    // which is not in the open interval (0, ∞).
    for direction in [Vec3::new(0.3, 1.0, 0.2), Vec3::new(0.3, -1.0, 0.2)] {
        let ray = Ray::new(Vec3::new(1.5, 0.0, -2.0), direction);
        assert_eq!(
            intersect_plane(Vec3::Y, 0.0, &ray, 0.0, INF),
            None,
            "a ray starting on the plane meets it at t = 0, outside (t_min, t_max) = (0, ∞): \
             the bounds are strict"
        );
    }
}

#[test]
fn a_ray_parallel_to_the_plane_misses_it() {
    for (y, place) in [(5.0, "above"), (-5.0, "below"), (1.0, "in")] {
        let parallel = Ray::new(Vec3::new(0.0, y, 0.0), Vec3::new(0.6, 0.0, 0.8));
        let hit = intersect_plane(Vec3::Y, -1.0, &parallel, 0.0, INF);
        assert_eq!(
            hit, None,
            "a ray parallel to the plane y = 1, {place} it, has n·rd = 0: no hit, not {hit:?}"
        );
    }
}

// ----------------------------------------------------------------- sphere --

#[test]
fn the_lectures_worked_example() {
    // A ray from (0, 2, 0) straight down onto the unit sphere at the origin:
    // a = 1, b = −4, c = 3, so t² − 4t + 3 = 0.
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    let roots = sphere_roots_abc(Vec3::ZERO, 1.0, &ray);
    assert_eq!(
        roots,
        Some((1.0, 3.0)),
        "t² − 4t + 3 = 0 (a = rd·rd = 1, b = 2 (r0 − m)·rd = −4, c = |r0 − m|² − ρ² = 3) \
         has the roots 1 and 3, nearest first"
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
fn a_sphere_away_from_the_origin_with_radius_2() {
    // Centre m = (1, −2, 3), radius ρ = 2, a ray from (1, 4, 3) straight
    // down: r0 − m = (0, 6, 0), so a = 1, b = −12, c = 36 − 4 = 32 and
    // t² − 12t + 32 = 0: t = 4 and t = 8.
    let (m, rho) = (Vec3::new(1.0, -2.0, 3.0), 2.0);
    let ray = Ray::new(Vec3::new(1.0, 4.0, 3.0), Vec3::NEG_Y);
    assert_eq!(
        sphere_roots_abc(m, rho, &ray),
        Some((4.0, 8.0)),
        "t² − 12t + 32 = 0 (r0 − m = (0, 6, 0), c = |r0 − m|² − ρ² with ρ² = 4) has the roots 4 and 8"
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
fn a_tangent_ray_touches_the_sphere_once() {
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
fn a_ray_past_the_sphere_misses() {
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
fn the_nearest_root_ahead_is_the_hit() {
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

// --------------------------------------------------------------- triangle --

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
fn the_triangle_worked_example() {
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
fn the_triangle_has_its_edges_and_corners() {
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
fn points_outside_the_triangle_are_missed() {
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
fn the_triangle_is_hit_from_both_sides_but_not_from_behind_the_origin() {
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
fn a_ray_parallel_to_the_triangle_misses_it() {
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
    // outside both; the watertight test cannot (tests/numerics_hits.rs at the
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

// ------------------------------------------------------------ closest hit --

#[test]
fn closest_hit_is_the_nearest_object() {
    let s = scene();
    // Straight down from high above the red sphere: it is above the floor.
    let ray = Ray::new(Vec3::new(-1.0, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    let hit = closest_hit(&s.objects, &ray, 0.0, INF).unwrap();
    assert!(
        matches!(s.objects[hit.object].shape, Shape::Sphere { .. }),
        "from above, the red sphere (object 1) hides the floor (object 0); got object {}",
        hit.object
    );
    assert!((hit.t - 8.0).abs() < 1e-5, "{}", hit.t);
    assert!((hit.normal - Vec3::Y).length() < 1e-6);
    assert!(
        closest_hit(&s.objects, &ray, 0.0, 7.9).is_none(),
        "with t_max = 7.9, below the sphere's t = 8, nothing is hit"
    );
}

fn sphere(x: f32) -> Object {
    Object {
        shape: Shape::Sphere {
            center: Vec3::new(x, 0.0, 0.0),
            radius: 1.0,
        },
        material: 0,
        shadows: true,
    }
}

#[test]
fn the_nearest_object_wins_wherever_it_is_in_the_list() {
    // Three unit spheres along x, met at t = 4, 9 and 14 by a ray from the origin.
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let spheres = [sphere(5.0), sphere(10.0), sphere(15.0)];
    for order in [[0, 1, 2], [2, 1, 0], [1, 0, 2], [2, 0, 1]] {
        let objects: Vec<Object> = order.iter().map(|&i| spheres[i].clone()).collect();
        let hit = closest_hit(&objects, &ray, 0.0, INF).expect("three spheres ahead");
        let nearest = order.iter().position(|&i| i == 0).unwrap();
        assert_eq!(
            (hit.object, hit.t),
            (nearest, 4.0),
            "spheres met at t = {:?} in this order: the hit is the nearest one, \
             object {nearest} at t = 4, whatever its place in the list",
            order.map(|i| 4 + 5 * i)
        );
        let beyond = closest_hit(&objects, &ray, 4.5, INF).expect("the first sphere's far side");
        assert_eq!(
            (beyond.object, beyond.t),
            (nearest, 6.0),
            "with t_min = 4.5 the first hit is the far side of the nearest sphere, t = 6"
        );
        let far = closest_hit(&objects, &ray, 6.5, 12.0).expect("the middle sphere");
        let middle = order.iter().position(|&i| i == 1).unwrap();
        assert_eq!(
            (far.object, far.t),
            (middle, 9.0),
            "within (6.5, 12) only the middle sphere is met, at t = 9"
        );
    }
    assert!(
        closest_hit(&[], &ray, 0.0, INF).is_none(),
        "no objects, no hit"
    );
}

// --------------------------------------------------------------- pictures --

/// The closest hit with the lecture's methods: `sphere_roots_abc` for
/// spheres, `triangle_by_plane` for triangles.
fn lecture_hit(objects: &[Object], ray: &Ray) -> Option<usize> {
    let mut nearest: Option<(f32, usize)> = None;
    for (index, object) in objects.iter().enumerate() {
        let bound = nearest.map_or(INF, |(t, _)| t);
        let t = match object.shape {
            Shape::Sphere { center, radius } => sphere_roots_abc(center, radius, ray)
                .and_then(|(t0, t1)| [t0, t1].into_iter().find(|&t| t > 0.0 && t < bound)),
            Shape::Triangle { vertices } => {
                triangle_by_plane(vertices, ray, 0.0, bound).map(|(t, _, _)| t)
            }
            ref shape => intersect(shape, ray, 0.0, bound),
        };
        if let Some(t) = t {
            nearest = Some((t, index));
        }
    }
    nearest.map(|(_, index)| index)
}

#[test]
fn the_lectures_methods_draw_the_same_picture() {
    // The flat view of the default scene, its spheres and its triangle hit
    // with the lecture's formulas instead of the tracer's robust ones: the
    // same picture, within the snapshot tolerance.
    let s = scene();
    let image = ch02_hits::render(
        &s,
        |ray, _| match lecture_hit(&s.objects, ray) {
            Some(index) => s.material(&s.objects[index]).color,
            None => s.image.background,
        },
        || {},
    )
    .0;
    let tracer = render(&s, View::Flat);
    let verdict = compare(
        &tracer.to_rgb8(),
        &image.to_rgb8(),
        Tolerance::for_size(160, 120),
    );
    println!("the lecture's methods against the tracer's, flat view: {verdict}");
    let reference = std::fs::read(reference_path("02-hits", "flat")).unwrap();
    if let Err(report) = check("02-hits", "flat-lecture", &reference, &image.to_rgb8()) {
        panic!(
            "the flat picture drawn with sphere_roots_abc and triangle_by_plane differs from \
             the reference:\n{report}"
        );
    }
}

#[test]
fn snapshot_flat() {
    assert_image("02-hits", "flat", &render(&scene(), View::Flat));
}

#[test]
fn snapshot_normals() {
    assert_image("02-hits", "normals", &render(&scene(), View::Normals));
}

#[test]
fn snapshot_depth() {
    assert_image("02-hits", "depth", &render(&scene(), View::Depth));
}

// The snapshot tolerance, checked on this chapter's own pictures: a real
// mistake fails, a harmless last-bit change passes.

fn verdict_against_default(changed: &Scene, view: View) -> ch02_hits::workbench::compare::Verdict {
    let expected = render(&scene(), view).to_rgb8();
    let actual = render(changed, view).to_rgb8();
    compare(&expected, &actual, Tolerance::for_size(160, 120))
}

/// The default scene with object `index` changed by `change`.
fn changed(index: usize, change: impl Fn(&mut Shape)) -> Scene {
    let mut s = scene();
    change(&mut s.objects[index].shape);
    s
}

#[test]
fn a_sphere_one_pixel_off_fails_the_snapshot() {
    // At the sphere's distance (6 units) one pixel of a 45° view 120 pixels
    // high is 2·6·tan(22.5°)/120 ≈ 0.041 units.
    let moved = changed(1, |shape| {
        if let Shape::Sphere { center, .. } = shape {
            center.x += 0.041;
        }
    });
    assert!(!verdict_against_default(&moved, View::Flat).passed());
}

#[test]
fn a_missing_object_fails_the_snapshot() {
    let mut s = scene();
    s.objects.remove(2);
    assert!(!verdict_against_default(&s, View::Flat).passed());
}

#[test]
fn a_flipped_normal_fails_the_snapshot() {
    let flipped = changed(0, |shape| {
        if let Shape::Plane { normal, offset } = shape {
            (*normal, *offset) = (-*normal, -*offset);
        }
    });
    assert!(!verdict_against_default(&flipped, View::Normals).passed());
}

#[test]
fn a_last_bit_change_passes_the_snapshot() {
    // Moving the eye by a few units in the last place changes every ray's
    // rounding, as another correct implementation would.
    let mut s = scene();
    s.camera.eye *= 1.0 + 2.0 * f32::EPSILON;
    let verdict = verdict_against_default(&s, View::Normals);
    assert!(verdict.passed(), "{verdict}");
}
