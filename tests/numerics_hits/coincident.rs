//! Coincident surfaces: triangles and a plane in one plane (their corners
//! points of it rounded to f32), in shuffled orders. Whatever the order in
//! which they are listed and traversed, the winner is the rule's: the
//! first listed of the surfaces at the point, by the list, chapter 8's BVH
//! and the wide BVH alike.

use ch08_bvh::Bvh;
use raybook::tracer::toolkit::scene::{Object, Shape};
use raybook::tracer::toolkit::{DVec3, Vec3};
use raybook::tracer::{Ray, World, closest_hit};
use raybook::wide::WideBvh;
use test_support::Rng;
use test_support::coincident::{coplanar, shuffle};

use super::INF;

/// The rule's winner in f64: the first listed object that covers the point
/// where the ray meets the plane, or None if the point is within 10⁻⁴ of a
/// triangle's edge (too close to call).
fn first_covering(objects: &[Object], ray: &Ray, n: DVec3, at: DVec3) -> Option<usize> {
    let (o, d) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
    let p = o + n.dot(at - o) / n.dot(d) * d;
    let mut first = None;
    for (index, object) in objects.iter().enumerate().rev() {
        let covers = match object.shape {
            Shape::Triangle { vertices } => {
                let [a, b, c] = vertices.map(|v| v.as_dvec3());
                let area = |u: DVec3, v: DVec3, w: DVec3| (v - u).cross(w - u).dot(n);
                let whole = area(a, b, c);
                let w = [area(p, b, c), area(a, p, c), area(a, b, p)].map(|w| w / whole);
                if w.iter().any(|w| w.abs() < 1e-4) {
                    return None;
                }
                w.iter().all(|&w| w > 0.0)
            }
            _ => true,
        };
        if covers {
            first = Some(index);
        }
    }
    first
}

#[test]
fn coincident_surfaces_give_the_first_listed_whatever_the_order_of_traversal() {
    let mut rng = Rng(0x36);
    let (mut decided, mut overlaps) = (0, 0);
    for _ in 0..40 {
        let n = rng.unit();
        let at = rng.vec(-50.0, 50.0);
        let mut objects = coplanar(&mut rng, n, at, 24);
        for _ in 0..5 {
            shuffle(&mut rng, &mut objects);
            let (bvh, wide) = (Bvh::build(&objects), WideBvh::build(&objects));
            for _ in 0..200 {
                let side = if rng.range(-1.0, 1.0) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                let in_plane = |v: Vec3| v - v.dot(n) * n;
                let eye = at + side * rng.range(0.5, 20.0) * n + in_plane(rng.vec(-9.0, 9.0));
                let ray = Ray::new(eye, at + in_plane(rng.vec(-2.0, 2.0)) - eye);
                let Some(expected) = first_covering(&objects, &ray, n.as_dvec3(), at.as_dvec3())
                else {
                    continue;
                };
                let list = closest_hit(&objects, &ray, 0.0, INF).map(|h| h.object);
                let in_bvh = bvh.closest_hit(&ray, 0.0, INF).map(|h| h.object);
                let in_wide = wide.closest_hit(&ray, 0.0, INF).map(|h| h.object);
                assert_eq!(list, Some(expected), "the list, ray {ray:?}");
                assert_eq!(in_bvh, Some(expected), "chapter 8's BVH, ray {ray:?}");
                assert_eq!(in_wide, Some(expected), "the wide BVH, ray {ray:?}");
                decided += 1;
                overlaps += usize::from(objects[expected].shape != objects[0].shape);
            }
        }
    }
    assert!(decided > 20_000, "only {decided} rays decided");
    assert!(overlaps > 5_000, "only {overlaps} rays saw a triangle");
}
