//! The rule in one walk (`rule.rs`) against chapter 2's list, on every path
//! it can take: the kept hits decide, the window reaches past the walk's
//! limit, or more hits were to be kept than there is room for. The last two
//! take the second walk; all must give chapter 2's hit, to the last bit.

use test_support::Rng;
use test_support::coincident::{coplanar, object, shuffle};

use super::{PreparedRay, WideBvh, rule};
use crate::toolkit::Vec3;
use crate::toolkit::scene::{Object, Shape};
use crate::tracer::{Ray, closest_hit, closest_hit_by, coincident_range, intersect};

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

/// The window's test without its division (`rule::window_fits`) against
/// chapter 2's `coincident_range`: wherever it says the window fits in the
/// room left below a limit, the exact window's upper end is at most that
/// limit. Over planes, triangles and spheres, far from the origin and near
/// it, grazing rays included; and it must say so for most rays, or the
/// walk's answer would take the exact way every time.
#[test]
fn the_window_without_its_division_never_claims_more_room_than_it_has() {
    let mut rng = Rng(0x451);
    let [mut fits, mut asked] = [0usize; 2];
    for scale in [1e-3, 1.0, 1e3, 1e5] {
        for _ in 0..20 {
            let (n, at) = (rng.unit(), scale * rng.vec(-50.0, 50.0));
            let objects = coincident_scene(&mut rng, n, at, 4);
            for i in 0..200 {
                let height = if i % 4 == 0 {
                    1e-4
                } else {
                    rng.range(0.01, 20.0)
                };
                let in_plane = |v: Vec3| v - v.dot(n) * n;
                let eye = at + height * n + in_plane(rng.vec(-9.0, 9.0));
                let ray = Ray::new(eye, at + in_plane(rng.vec(-2.0, 2.0)) - eye);
                let Some(hit) = closest_hit_by(intersect, &objects, &ray, 0.0, INF) else {
                    continue;
                };
                let origin = ray.origin.abs().max_element();
                let slack = hit.t + rule::SLACK * (origin + hit.t);
                let tiny = hit.t.next_up();
                let random = hit.t + rng.range(0.0, 1e-3) * (origin + hit.t);
                for limit in [slack, tiny, random, INF] {
                    let upper = coincident_range(&hit, &ray, 0.0, INF).1;
                    if rule::window_fits(&hit, &ray, origin, limit - hit.t) {
                        assert!(upper <= limit, "{hit:?} {ray:?}: {upper} > {limit}");
                        fits += usize::from(limit == slack);
                    }
                }
                asked += 1;
            }
        }
    }
    assert!(
        fits * 10 > asked * 6,
        "the window fits on {fits} of {asked} rays only"
    );
}

/// The walk's limit (`rule::reach`) is the larger of t + slack and the next
/// number above t, as it was written before: at 0, subnormal, negative,
/// large and infinite t, and far from the origin.
#[test]
fn the_walks_limit_is_the_larger_of_the_slack_and_the_next_number() {
    let mut rng = Rng(0x452);
    let special = [0.0, -0.0, 1e-45, 1e-40, 1e-30, -1e-40, 1.0, -1.0, 3e38, INF];
    let random = (0..10_000).map(|_| rng.range(-1.0, 1.0) * 10f32.powf(rng.range(-44.0, 38.0)));
    for t in special.into_iter().chain(random) {
        for origin in [0.0, 1e-40, 1.0, 1e5, 3e38] {
            let before = (t + rule::SLACK * (origin + t.abs())).max(t.next_up());
            assert_eq!(
                rule::reach(t, origin).to_bits(),
                before.to_bits(),
                "{t} {origin}"
            );
        }
    }
}
