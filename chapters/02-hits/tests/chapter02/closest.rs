//! The closest hit: the nearest object along the ray, wherever it is in the list.

use ch02_hits::toolkit::Vec3;
use ch02_hits::toolkit::scene::{Object, Shape};
use ch02_hits::{Ray, closest_hit, closest_hit_by};

use super::{INF, scene};

#[test]
pub(crate) fn closest_hit_is_the_nearest_object() {
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

#[test]
pub(crate) fn a_later_object_replaces_the_hit_only_if_it_is_nearer() {
    // Two spheres, the nearer first in the list: a fake `intersect` meets the
    // one at x = 5 at t = 4, the one at x = 10 at t = 9 (inside the range it
    // is asked about), and records the t_max it was given each time.
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let objects = [sphere(5.0), sphere(10.0)];
    let asked = std::cell::RefCell::new(Vec::new());
    let fake = |shape: &Shape, _: &Ray, t_min: f32, t_max: f32| {
        let Shape::Sphere { center, .. } = shape else {
            unreachable!()
        };
        let t = center.x - 1.0;
        asked.borrow_mut().push((t, t_max));
        (t_min < t && t < t_max).then_some(t)
    };
    let hit = closest_hit_by(fake, &objects, &ray, 0.0, INF).expect("two spheres ahead");
    let asked = asked.into_inner();
    assert_eq!(
        (hit.object, hit.t),
        (0, 4.0),
        "object 0 is met at t = 4, then object 1 at t = 9 (asked with t_max = {:?}): the \
         later, farther hit replaced the nearer one. After a hit, only a nearer one may \
         replace it: ask the next objects only up to the nearest t found so far (t_max \
         shrinks), or keep a new hit only if its t is smaller",
        asked.get(1).map(|(_, t_max)| *t_max)
    );
}

/// A fake `intersect` for spheres on the x axis, met by a ray from the
/// origin along +x at t = x − 1 when that t is inside the range asked
/// about; it records each call's t_max in `asked`.
fn recording(
    asked: &std::cell::RefCell<Vec<f32>>,
) -> impl Fn(&Shape, &Ray, f32, f32) -> Option<f32> + '_ {
    move |shape, _, t_min, t_max| {
        let Shape::Sphere { center, .. } = shape else {
            unreachable!()
        };
        asked.borrow_mut().push(t_max);
        let t = center.x - 1.0;
        (t_min < t && t < t_max).then_some(t)
    }
}

#[test]
fn two_objects_met_at_the_same_t_the_first_listed_wins() {
    // Objects 1 and 2 are the same sphere, both met at t = 4.
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let objects = [sphere(10.0), sphere(5.0), sphere(5.0), sphere(15.0)];
    let asked = std::cell::RefCell::new(Vec::new());
    let hit = closest_hit_by(recording(&asked), &objects, &ray, 0.0, INF).expect("a hit");
    assert_eq!(
        (hit.object, hit.t),
        (1, 4.0),
        "objects 1 and 2 are both met at t = 4, the nearest: of two objects hit at the \
         same t, the first listed wins (README, question (3)). A later hit may replace \
         the one kept only if it is strictly nearer: t < best, not t <= best"
    );
}

#[test]
fn each_object_is_asked_only_up_to_the_nearest_t_so_far() {
    // Met at t = 9, 4, 14, 2 and 6, asked within (0, 20).
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let objects = [10.0, 5.0, 15.0, 3.0, 7.0].map(sphere);
    let asked = std::cell::RefCell::new(Vec::new());
    let hit = closest_hit_by(recording(&asked), &objects, &ray, 0.0, 20.0).expect("a hit");
    assert_eq!(
        (hit.object, hit.t),
        (3, 2.0),
        "object 3, met at t = 2, is the nearest"
    );
    assert_eq!(
        asked.into_inner(),
        [20.0, 9.0, 4.0, 4.0, 2.0],
        "the t_max each object was asked with, in list order: the first is asked up to \
         t_max = 20, each next one only up to the nearest t found so far (README, question \
         (1)). A bound that does not shrink (every object asked up to t_max) makes an \
         object behind the nearest one cost a whole test (the same shrinking bound lets \
         chapter 8's hierarchy skip whole boxes behind the nearest hit)"
    );
}
