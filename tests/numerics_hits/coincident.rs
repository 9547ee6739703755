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

use super::INF;

fn object(shape: Shape) -> Object {
    Object {
        shape,
        material: 0,
        shadows: true,
    }
}

/// A plane through `at` with unit normal `n`, and `count` triangles of it
/// whose corners are its points rounded to f32, overlapping around `at`.
fn coplanar(rng: &mut Rng, n: Vec3, at: Vec3, count: usize) -> Vec<Object> {
    let a = n.any_orthonormal_vector();
    let b = n.cross(a);
    let mut objects = vec![object(Shape::Plane {
        normal: n,
        offset: -n.dot(at),
    })];
    for _ in 0..count {
        let centre = at + rng.range(-2.0, 2.0) * a + rng.range(-2.0, 2.0) * b;
        let size = rng.range(0.5, 3.0);
        let vertices = [0.0f32, 2.1, 4.2].map(|angle| {
            let angle = angle + rng.range(0.0, 1.0);
            centre + size * (angle.cos() * a + angle.sin() * b)
        });
        objects.push(object(Shape::Triangle { vertices }));
    }
    objects
}

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

/// Fisher–Yates, with the test's generator.
fn shuffle(rng: &mut Rng, objects: &mut [Object]) {
    for i in (1..objects.len()).rev() {
        let j = (rng.range(0.0, 1.0) * (i + 1) as f32) as usize;
        objects.swap(i, j.min(i));
    }
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
