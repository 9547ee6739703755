//! The closest hit: among random spheres, planes and triangles, it is the closest.

use proptest::prelude::*;
use raybook::tracer::toolkit::Vec3;
use raybook::tracer::toolkit::scene::{Object, Shape};
use raybook::tracer::{Ray, closest_hit, intersect};

use super::INF;

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
