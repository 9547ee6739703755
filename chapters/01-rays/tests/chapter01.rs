//! Chapter 1: the ray equation, the pinhole camera and its picture.

use ch01_rays::toolkit::snapshot::assert_image;
use ch01_rays::toolkit::{Scene, Vec3};
use ch01_rays::{CHAPTER, Camera, Ray, render_sky};

fn scene() -> Scene {
    CHAPTER.default_scene().unwrap()
}

#[test]
fn a_ray_walks_t_units_along_its_unit_direction() {
    let ray = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 0.0, -10.0));
    assert_eq!(ray.direction, Vec3::new(0.0, 0.0, -1.0));
    assert_eq!(ray.at(0.0), Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(ray.at(2.5), Vec3::new(1.0, 2.0, 0.5));
}

#[test]
fn the_centre_of_the_image_looks_at_look_at() {
    let s = scene();
    let camera = Camera::new(&s.camera, 320, 240);
    let ray = camera.ray_through(160.0, 120.0);
    let towards = (s.camera.look_at - s.camera.eye).normalize();
    assert!(ray.direction.dot(towards) > 1.0 - 1e-6, "{ray:?}");
    assert_eq!(ray.origin, s.camera.eye, "every ray starts at the eye");
}

#[test]
fn the_top_and_bottom_edges_span_the_vertical_field_of_view() {
    let s = scene();
    let camera = Camera::new(&s.camera, 320, 240);
    let top = camera.ray_through(160.0, 0.0).direction;
    let bottom = camera.ray_through(160.0, 240.0).direction;
    let angle = top.angle_between(bottom).to_degrees();
    assert!((angle - s.camera.vfov_degrees).abs() < 1e-3, "{angle}");
}

#[test]
fn pixels_are_square_whatever_the_aspect_ratio() {
    let s = scene();
    let camera = Camera::new(&s.camera, 400, 100);
    // Width and height of one pixel on the image plane (at distance 1).
    let across = 2.0 * camera.half_width / 400.0;
    let down = 2.0 * camera.half_height / 100.0;
    assert!((across - down).abs() <= 1e-6 * down, "{across} vs {down}");
    // And the rays of neighbouring pixels are that far apart on the plane.
    let centre = camera.ray_through(200.0, 50.0).direction;
    let right = camera.ray_through(201.0, 50.0).direction;
    let on_plane = |d: Vec3| d / d.dot(camera.forward);
    assert!((on_plane(right) - on_plane(centre) - across * camera.right).length() < 1e-5);
}

#[test]
fn image_x_grows_to_the_right_and_y_grows_down() {
    let s = scene();
    let camera = Camera::new(&s.camera, 320, 240);
    let left = camera.primary_ray(0, 120).direction;
    let right = camera.primary_ray(319, 120).direction;
    let top = camera.primary_ray(160, 0).direction;
    let bottom = camera.primary_ray(160, 239).direction;
    assert!(
        left.x < 0.0 && right.x > 0.0,
        "the camera looks down −z with +x to the right"
    );
    assert!(top.y > bottom.y);
}

#[test]
fn one_primary_ray_per_pixel() {
    let (image, stats) = render_sky(&scene().with_size(37, 11), || {});
    assert_eq!(stats.primary, 37 * 11);
    assert_eq!(stats.rays(), 37 * 11);
    assert_eq!(image.pixels.len(), 37 * 11);
}

#[test]
fn snapshot_default() {
    let (image, _) = render_sky(&scene().with_size(160, 120), || {});
    assert_image("01-rays", "default", &image);
}

#[test]
fn one_sample_is_the_pixel_centre() {
    let positions: Vec<_> = ch01_rays::sample_positions(7, 3, 1, 99).collect();
    assert_eq!(positions, vec![(7.5, 3.5)]);
}

#[test]
fn samples_fill_a_grid_one_in_each_cell() {
    for n in [4u32, 16, 64] {
        let side = (n as f32).sqrt() as u32;
        let mut seen = vec![0; n as usize];
        for (px, py) in ch01_rays::sample_positions(10, 20, n, 12345) {
            assert!(
                (10.0..11.0).contains(&px) && (20.0..21.0).contains(&py),
                "{px} {py}"
            );
            let (i, j) = (
                ((px - 10.0) * side as f32) as u32,
                ((py - 20.0) * side as f32) as u32,
            );
            seen[(j * side + i) as usize] += 1;
        }
        assert!(seen.iter().all(|&c| c == 1), "n = {n}: {seen:?}");
    }
}

#[test]
fn samples_depend_on_the_pixel_only() {
    let a: Vec<_> = ch01_rays::sample_positions(1, 1, 16, 7).collect();
    let b: Vec<_> = ch01_rays::sample_positions(1, 1, 16, 7).collect();
    let c: Vec<_> = ch01_rays::sample_positions(1, 1, 16, 8).collect();
    assert_eq!(a, b);
    assert_ne!(a, c, "another pixel gets other jitter");
}

#[test]
fn n_samples_trace_n_primary_rays_and_average_them() {
    let mut scene = scene().with_size(20, 10);
    scene.image.samples = 16;
    let (image, stats) = render_sky(&scene, || {});
    assert_eq!(stats.primary, 16 * 20 * 10);
    let again = render_sky(&scene, || {}).0;
    assert_eq!(image, again, "the same scene renders to the same picture");
}
