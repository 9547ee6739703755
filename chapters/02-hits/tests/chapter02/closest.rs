//! The closest hit: the nearest object along the ray, wherever it is in the list.

use ch02_hits::toolkit::Vec3;
use ch02_hits::toolkit::scene::{Object, Shape};
use ch02_hits::{Ray, closest_hit};

use super::{INF, scene};

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
