//! The plane: the hit of n·x + d = 0, its strict bounds, and parallel rays.

use ch02_hits::toolkit::Vec3;
use ch02_hits::{Ray, intersect_plane};

use super::INF;

#[test]
pub(crate) fn plane_hit_solves_n_dot_x_plus_d() {
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
pub(crate) fn a_plane_behind_the_ray_is_not_hit() {
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
pub(crate) fn a_ray_parallel_to_the_plane_misses_it() {
    for (y, place) in [(5.0, "above"), (-5.0, "below"), (1.0, "in")] {
        let parallel = Ray::new(Vec3::new(0.0, y, 0.0), Vec3::new(0.6, 0.0, 0.8));
        let hit = intersect_plane(Vec3::Y, -1.0, &parallel, 0.0, INF);
        assert_eq!(
            hit, None,
            "a ray parallel to the plane y = 1, {place} it, has n·rd = 0: no hit, not {hit:?}"
        );
    }
}
