//! Planes, and a triangle's plane: parallel and almost parallel rays.

use raybook::tracer::toolkit::Vec3;
use raybook::tracer::{Ray, intersect_plane, intersect_triangle};
use test_support::Rng;

use super::{INF, finite_triangle_hit, relative_error};

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
