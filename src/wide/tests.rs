//! The rule in one walk (`rule.rs`) against chapter 2's list, on every path
//! it can take: the kept hits decide, the window reaches past the walk's
//! limit, or more hits were to be kept than there is room for. The last two
//! take the second walk; all must give chapter 2's hit, to the last bit.

use test_support::Rng;
use test_support::coincident::{coplanar, object, shuffle};

use super::{PreparedRay, WideBvh, rule};
use crate::toolkit::Vec3;
use crate::toolkit::scene::{Object, Shape};
use crate::tracer::{Ray, closest_hit, coincident_range};

const INF: f32 = f32::INFINITY;

/// A plane through `at` with normal `n`, `count` triangles of it that
/// overlap around `at` (corners its points rounded to f32), and a sphere
/// touching it, in a shuffled order.
fn coincident_scene(rng: &mut Rng, n: Vec3, at: Vec3, count: usize) -> Vec<Object> {
    let mut objects = coplanar(rng, n, at, count);
    objects.push(object(Shape::Sphere {
        center: at + n,
        radius: 1.0,
    }));
    shuffle(rng, &mut objects);
    objects
}

/// Which way the rule in one walk with room for KEEP hits answers: from
/// the kept hits (`Ok`, with whether one of them won), or by a second walk.
fn path<const KEEP: usize>(wide: &WideBvh, ray: &Ray) -> Option<Result<bool, ()>> {
    let mut found = rule::Candidates::<KEEP>::new(INF, ray.origin.abs().max_element());
    wide.walk(&mut PreparedRay::new(ray), 0.0, &mut found);
    let nearest = wide.hit(ray, found.nearest?);
    let range = coincident_range(&nearest, ray, 0.0, INF);
    (nearest.object > 0).then(|| {
        found
            .first_within(nearest.object as u32, range)
            .map(|first| first.is_some())
    })
}

#[test]
fn the_rule_in_one_walk_gives_chapter_2s_hit_on_every_path() {
    let mut rng = Rng(0x45);
    let [mut kept_won, mut past_limit, mut overflowed] = [0; 3];
    for _ in 0..30 {
        let (n, at) = (rng.unit(), rng.vec(-50.0, 50.0));
        let objects = coincident_scene(&mut rng, n, at, 24);
        let wide = WideBvh::build(&objects);
        for i in 0..200 {
            // Every tenth ray grazes the plane: its window is wide.
            let height = if i % 10 == 0 {
                0.01
            } else {
                rng.range(0.5, 20.0)
            };
            let side = if rng.range(-1.0, 1.0) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let in_plane = |v: Vec3| v - v.dot(n) * n;
            let eye = at + side * height * n + in_plane(rng.vec(-9.0, 9.0));
            let ray = Ray::new(eye, at + in_plane(rng.vec(-2.0, 2.0)) - eye);
            let expected = closest_hit(&objects, &ray, 0.0, INF);
            assert_eq!(wide.nearest_by_the_rule::<8>(&ray, 0.0, INF), expected);
            assert_eq!(wide.nearest_by_the_rule::<1>(&ray, 0.0, INF), expected);
            assert_eq!(wide.nearest_by_the_rule::<0>(&ray, 0.0, INF), expected);
            match path::<8>(&wide, &ray) {
                Some(Ok(true)) => kept_won += 1,
                Some(Err(())) => past_limit += 1,
                _ => {}
            }
            overflowed += usize::from(path::<1>(&wide, &ray) == Some(Err(())));
        }
    }
    assert!(kept_won > 500, "a kept hit won on {kept_won} rays only");
    assert!(
        past_limit > 20,
        "{past_limit} windows only reached past the limit"
    );
    assert!(overflowed > past_limit + 100, "{overflowed} overflows only");
}
