//! Rays that leave a small scene's own triangles, as shadow rays leave
//! tinyraytracer's board (`src/wide/behind.rs`).

use raybook::toolkit::Vec3;
use raybook::toolkit::scene::{Object, Shape};
use raybook::tracer::{Ray, World};
use raybook::wide::WideBvh;

/// Rays that leave a small scene's triangles (as shadow rays leave
/// tinyraytracer's board: just off it, on either side, or on it) and rays
/// that come back to them: the test of the triangles' planes that lets a
/// shadow ray skip the packet it leaves answers as chapter 2's test does,
/// and is not taken for t_min < 0.
#[test]
fn rays_leaving_a_few_triangles_get_chapter_2s_answers() {
    let triangle = |vertices: [[f32; 3]; 3]| Object {
        shape: Shape::Triangle {
            vertices: vertices.map(Vec3::from_array),
        },
        material: 0,
        shadows: true,
    };
    let objects = vec![
        triangle([
            [-10.0, -4.0, -10.0],
            [10.0, -4.0, -10.0],
            [10.0, -4.0, -30.0],
        ]),
        triangle([
            [-10.0, -4.0, -10.0],
            [10.0, -4.0, -30.0],
            [-10.0, -4.0, -30.0],
        ]),
        triangle([[-3.0, -4.0, -12.0], [3.0, 2.0, -12.0], [0.0, -4.0, -20.0]]),
    ];
    let wide = WideBvh::build(&objects);
    let mut checked = 0;
    for k in 0..60 {
        let a = k as f32 * 0.37;
        let on_board = Vec3::new(9.5 * a.sin(), -4.0, -20.0 + 9.5 * (1.3 * a).cos());
        for offset in [-1e-3, -1e-5, -1e-7, 0.0, 1e-7, 1e-5, 1e-3] {
            let origin = on_board + Vec3::new(0.0, offset, 0.0);
            let slant = Vec3::new(a.cos(), 0.0, a.sin());
            for direction in [
                Vec3::Y,
                -Vec3::Y,
                slant + Vec3::Y,
                slant - 0.01 * Vec3::Y,
                slant,
            ] {
                let ray = Ray::new(origin, direction);
                for (t_min, t_max) in [(0.0, f32::INFINITY), (0.0, 3.0), (-1.0, 1.0)] {
                    assert_eq!(
                        wide.any_hit(&ray, t_min, t_max),
                        objects[..].any_hit(&ray, t_min, t_max),
                        "{ray:?} in ({t_min}, {t_max})"
                    );
                    assert_eq!(
                        wide.closest_hit(&ray, t_min, t_max),
                        objects[..].closest_hit(&ray, t_min, t_max),
                        "{ray:?} in ({t_min}, {t_max})"
                    );
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 60 * 7 * 5 * 3);
}
