//! Triangles: no cracks at shared edges and no hole at a fan's apex, unlike
//! Möller–Trumbore, and nothing hit along an edge in the plane.

use raybook::tracer::toolkit::Vec3;
use raybook::tracer::{Ray, intersect_triangle};
use test_support::Rng;

use super::{INF, NEEDS_WATERTIGHT, finite_triangle_hit};

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
