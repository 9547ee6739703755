//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch02_hits::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 3);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn the_worked_example_meets_the_sphere_at_one_and_three() {
    // ANCHOR: sphere_roots_abc
    use ch02_hits::{Ray, sphere_roots_abc, toolkit::Vec3};

    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(sphere_roots_abc(Vec3::ZERO, 1.0, &ray), Some((1.0, 3.0)));
    let touching = Ray::new(Vec3::new(1.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(sphere_roots_abc(Vec3::ZERO, 1.0, &touching), Some((2.0, 2.0)));
    // ANCHOR_END: sphere_roots_abc
}

#[test]
#[rustfmt::skip] // as the text shows it
fn the_ray_meets_the_triangle_at_its_barycentric_point() {
    // ANCHOR: triangle_by_plane
    use ch02_hits::{Ray, triangle_by_plane, toolkit::Vec3};

    let corners = [Vec3::new(0.0, 0.0, -1.0), Vec3::new(4.0, 0.0, -1.0), Vec3::new(0.0, 2.0, -1.0)];
    let ray = Ray::new(Vec3::new(2.0, 0.5, 3.0), Vec3::NEG_Z);
    assert_eq!(triangle_by_plane(corners, &ray, 0.0, f32::INFINITY), Some((4.0, 0.5, 0.25)));
    // ANCHOR_END: triangle_by_plane
}

#[test]
#[rustfmt::skip] // as the text shows it
fn the_stable_roots_hold_far_away_and_up_close() {
    // ANCHOR: far_sphere
    use ch02_hits::{Ray, sphere_roots, sphere_roots_abc, toolkit::Vec3};

    // A sphere of radius 0.01, 10⁴ units along an awkward direction, passed at
    // 0.9 and at 1.1 radii from its centre.
    let d = Vec3::new(0.48, -0.6, 0.64).normalize();
    let origin = Vec3::new(0.3, -1.7, 2.9);
    let side = d.cross(Vec3::Y).normalize();
    let past = |radii: f32| Ray::new(origin + radii * 0.01 * side, d);
    assert!(sphere_roots(origin + 1e4 * d, 0.01, &past(0.9)).is_some());
    assert!(sphere_roots(origin + 1e4 * d, 0.01, &past(1.1)).is_none());
    // The lecture's formula, in f32: a hit 1.1 radii from the centre.
    assert!(sphere_roots_abc(origin + 1e4 * d, 0.01, &past(1.1)).is_some());

    // A sphere of radius 10⁴ whose top is at y = 0, seen from 0.01 above it.
    let ray = Ray::new(Vec3::new(0.0, 0.01, 0.0), Vec3::NEG_Y);
    let (t, _) = sphere_roots(Vec3::new(0.0, -1e4, 0.0), 1e4, &ray).unwrap();
    assert!((t - 0.01).abs() < 1e-5);
    // ANCHOR_END: far_sphere
}
