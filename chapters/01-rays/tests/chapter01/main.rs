//! Chapter 1: the ray equation, the pinhole camera and its picture.

use ch01_rays::toolkit::scene::CameraSpec;
use ch01_rays::toolkit::{Scene, Vec3};
use ch01_rays::workbench::snapshot::{Precise, assert_image_beside};
use ch01_rays::{CHAPTER, Camera, Ray, render_sky};

fn scene() -> Scene {
    CHAPTER.default_scene().unwrap()
}

#[test]
fn a_ray_walks_t_units_along_its_unit_direction() {
    let ray = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 0.0, -10.0));
    assert_eq!(ray.direction, Vec3::new(0.0, 0.0, -1.0));
    assert_eq!(ray.at(0.0), Vec3::new(1.0, 2.0, 3.0), "r(0) is the origin");
    assert_eq!(
        ray.at(2.5),
        Vec3::new(1.0, 2.0, 0.5),
        "r(2.5) lies 2.5 units from the origin along the direction"
    );
    assert_eq!(
        ray.at(-1.0),
        Vec3::new(1.0, 2.0, 4.0),
        "r(−1) lies behind the origin"
    );
}

/// A camera that looks down at 40° with an awkward eye, as a camera over a
/// table would: the scene's up is then far from perpendicular to forward.
fn tilted() -> CameraSpec {
    CameraSpec {
        eye: Vec3::new(0.7, 4.0, 3.1),
        look_at: Vec3::new(0.7, 4.0 - 3.0 * 40f32.to_radians().tan(), 0.1),
        up: Vec3::Y,
        vfov_degrees: 50.0,
    }
}

#[test]
fn the_frame_is_orthonormal_right_handed_and_upright() {
    for spec in [scene().camera, tilted()] {
        let c = Camera::new(&spec, 320, 240);
        for (name, v) in [("forward", c.forward), ("right", c.right), ("up", c.up)] {
            assert!(
                (v.length() - 1.0).abs() < 1e-6,
                "{name} {v} has length {}, not 1: normalise it \
                 (look_at − eye is as long as the distance, forward × up₀ as the sine of their angle)",
                v.length()
            );
        }
        let forward = (spec.look_at - spec.eye).normalize();
        assert!(
            (c.forward - forward).length() < 1e-6,
            "forward {} must point from the eye towards look_at, {forward}",
            c.forward
        );
        assert!(
            c.up.dot(c.forward).abs() < 1e-6,
            "up {} is not at right angles to forward {}: the scene's up is only a hint \
             when the camera looks up or down; make up perpendicular to forward and right",
            c.up,
            c.forward
        );
        assert!(
            c.right.dot(c.forward).abs() < 1e-6,
            "right is not ⊥ forward"
        );
        assert!(c.right.dot(c.up).abs() < 1e-6, "right is not ⊥ up");
        assert!(
            c.up.dot(spec.up) > 0.0,
            "up {} points away from the scene's up {}: the picture is upside down \
             (turned by 180° if right points left too): check the order of the cross products",
            c.up,
            spec.up
        );
        assert!(
            (c.right.cross(c.up) + c.forward).length() < 1e-5,
            "right {} and up {} make a mirrored picture: right × up must be −forward, \
             as x × y = z is for a camera looking down −z (the viewer's right is forward × up₀, \
             not up₀ × forward)",
            c.right,
            c.up
        );
    }
    // Looking down −z with y up, the viewer's right is +x.
    let c = Camera::new(&scene().camera, 320, 240);
    assert!(
        c.right.x > 0.99,
        "right = {}: looking down −z with y up, the viewer's right is +x (a mirrored picture?)",
        c.right
    );
}

#[test]
fn the_image_plane_is_tan_half_the_field_of_view_high() {
    for (spec, (width, height)) in [(scene().camera, (320, 240)), (tilted(), (300, 500))] {
        let c = Camera::new(&spec, width, height);
        let half = spec.vfov_degrees.to_radians() / 2.0;
        let aspect = width as f32 / height as f32;
        let close = |a: f32, b: f32| (a - b).abs() <= 1e-5 * b.abs();
        let diagnosis = if close(c.half_height, half.tan()) {
            ""
        } else if close(c.half_height, (2.0 * half).tan()) {
            ": that is tan(vfov), the whole field of view; the top edge is half of it above forward"
        } else if close(c.half_height, half.tan() / aspect) {
            ": vfov was taken as the horizontal field of view; it is the vertical one"
        } else if close(c.half_height.abs(), (spec.vfov_degrees / 2.0).tan().abs()) {
            ": the tangent was taken of degrees; convert vfov to radians"
        } else {
            ""
        };
        assert!(
            close(c.half_height, half.tan()),
            "vfov {}°: half_height is {}, expected tan(vfov / 2) = {}{diagnosis}",
            spec.vfov_degrees,
            c.half_height,
            half.tan()
        );
        assert!(
            close(c.half_width, c.half_height * aspect),
            "{width}×{height} pixels: half_width is {}, expected half_height · width / height = {} \
             (square pixels)",
            c.half_width,
            c.half_height * aspect
        );
    }
}

#[test]
fn the_centre_of_the_image_looks_at_look_at() {
    for spec in [scene().camera, tilted()] {
        let camera = Camera::new(&spec, 320, 240);
        let ray = camera.ray_through(160.0, 120.0);
        let towards = (spec.look_at - spec.eye).normalize();
        assert!(
            ray.direction.dot(towards) > 1.0 - 1e-6,
            "the ray through the image's centre (160, 120) goes along {}, not towards look_at {towards}",
            ray.direction
        );
        assert_eq!(ray.origin, spec.eye, "every ray starts at the eye");
    }
}

/// A camera built by hand, not by `Camera::new`: a frame turned away from
/// the axes, and an image plane 0.5 high and 0.8 wide for 320 × 200 pixels.
fn hand_made() -> Camera {
    let forward = Vec3::new(0.6, 0.0, -0.8);
    let up = Vec3::new(0.0, 1.0, 0.0);
    Camera {
        eye: Vec3::new(1.0, 2.0, 3.0),
        right: forward.cross(up),
        up,
        forward,
        half_width: 0.4,
        half_height: 0.25,
        width: 320,
        height: 200,
    }
}

#[test]
fn the_image_corners_are_the_image_planes_corners() {
    let camera = hand_made();
    let (w, h) = (camera.half_width, camera.half_height);
    let through = |across: f32, down: f32| {
        (camera.forward + across * w * camera.right - down * h * camera.up).normalize()
    };
    for ((px, py), expected, name) in [
        ((0.0, 0.0), through(-1.0, -1.0), "top-left corner"),
        ((320.0, 0.0), through(1.0, -1.0), "top-right corner"),
        ((0.0, 200.0), through(-1.0, 1.0), "bottom-left corner"),
        ((320.0, 200.0), through(1.0, 1.0), "bottom-right corner"),
        ((160.0, 100.0), through(0.0, 0.0), "centre"),
        (
            (80.0, 150.0),
            through(-0.5, 0.5),
            "point halfway to the bottom-left corner",
        ),
    ] {
        let ray = camera.ray_through(px, py);
        assert_eq!(ray.origin, camera.eye, "every ray starts at the eye");
        let d = ray.direction;
        assert!(
            (d - expected).length() < 1e-5,
            "ray_through({px}, {py}) goes along {d}, not through the image plane's {name} \
             {expected}: positions are in pixels from the image's top-left corner (no half pixel \
             added: primary_ray does that), x across the width, y down the height"
        );
    }
    let centre = camera.primary_ray(0, 0).direction;
    assert!(
        (centre - through(-1.0 + 1.0 / 320.0, -1.0 + 1.0 / 200.0)).length() < 1e-5,
        "primary_ray(0, 0) passes through the centre of the top-left pixel"
    );
}

/// The direction is forward + u·right + v·up wherever the eye is. Through
/// P − eye it is not: P = eye + forward + u·right + v·up is rounded to the
/// precision of the eye's coordinates (f32 keeps 24 bits: 0.001 near 10⁴),
/// and the subtraction keeps that error.
#[test]
fn the_direction_does_not_depend_on_where_the_eye_is() {
    let camera = Camera {
        eye: Vec3::new(10000.0, -20000.0, 5000.0),
        ..hand_made()
    };
    let (w, h) = (camera.half_width, camera.half_height);
    for (px, py) in [(0.5, 0.5), (17.25, 133.75), (301.5, 7.5), (319.5, 199.5)] {
        let (u, v) = ((2.0 * px / 320.0 - 1.0) * w, (1.0 - 2.0 * py / 200.0) * h);
        let expected = (camera.forward + u * camera.right + v * camera.up).normalize();
        let d = camera.ray_through(px, py).direction;
        assert!(
            (d - expected).length() < 1e-5,
            "with the eye at {}, ray_through({px}, {py}) goes along {d}, {} away from \
             forward + u·right + v·up = {expected}: was the direction computed as P − eye? \
             P = eye + forward + u·right + v·up is rounded to the eye's precision (0.001 for \
             coordinates near 10⁴), and P − eye keeps that error: take the direction as \
             forward + u·right + v·up itself",
            camera.eye,
            (d - expected).length()
        );
    }
}

#[test]
fn the_top_and_bottom_edges_span_the_vertical_field_of_view() {
    let s = scene();
    let camera = Camera::new(&s.camera, 320, 240);
    let top = camera.ray_through(160.0, 0.0).direction;
    let bottom = camera.ray_through(160.0, 240.0).direction;
    let angle = top.angle_between(bottom).to_degrees();
    assert!(
        (angle - s.camera.vfov_degrees).abs() < 1e-3,
        "the rays through the top and bottom edges are {angle}° apart, not vfov = {}°",
        s.camera.vfov_degrees
    );
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
        "the camera looks down −z with +x to the right: pixel x = 0 is on the left \
         (left {left}, right {right}; a mirrored picture?)"
    );
    assert!(
        top.y > bottom.y,
        "image y grows down: row 0 looks higher than the last row (top {top}, bottom {bottom}; \
         an upside-down picture?)"
    );
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
    assert_image_beside("01-rays", "default", &image, PRECISE);
}

/// The tests whose messages say more than the picture's count of pixels:
/// a picture that differs names those of them that fail beside it (a frame
/// turned round, a ray through the wrong corner).
const PRECISE: &[Precise] = &[
    (
        "a_ray_walks_t_units_along_its_unit_direction",
        a_ray_walks_t_units_along_its_unit_direction,
    ),
    (
        "the_frame_is_orthonormal_right_handed_and_upright",
        the_frame_is_orthonormal_right_handed_and_upright,
    ),
    (
        "the_image_plane_is_tan_half_the_field_of_view_high",
        the_image_plane_is_tan_half_the_field_of_view_high,
    ),
    (
        "the_centre_of_the_image_looks_at_look_at",
        the_centre_of_the_image_looks_at_look_at,
    ),
    (
        "the_image_corners_are_the_image_planes_corners",
        the_image_corners_are_the_image_planes_corners,
    ),
    (
        "the_top_and_bottom_edges_span_the_vertical_field_of_view",
        the_top_and_bottom_edges_span_the_vertical_field_of_view,
    ),
    (
        "pixels_are_square_whatever_the_aspect_ratio",
        pixels_are_square_whatever_the_aspect_ratio,
    ),
    (
        "image_x_grows_to_the_right_and_y_grows_down",
        image_x_grows_to_the_right_and_y_grows_down,
    ),
];

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

/// `--seed N`: every ray at a random point of its cell, one ray too; the
/// same seed gives the same bytes on any number of threads, another seed
/// another picture, and no seed keeps the picture of the snapshots.
#[test]
fn a_seed_jitters_every_ray_the_same_way_on_any_number_of_threads() {
    use ch01_rays::workbench::cli::with_threads;
    for samples in [1, 4] {
        let mut unseeded = scene().with_size(40, 30);
        unseeded.image.samples = samples;
        let seeded = |seed| {
            let mut scene = unseeded.clone();
            scene.image.seed = Some(seed);
            scene
        };
        let on = |scene: &Scene, threads| {
            with_threads(Some(threads), || render_sky(scene, || {}).0).unwrap()
        };
        let one = on(&seeded(1), 1);
        assert_eq!(
            one.to_png(),
            on(&seeded(1), 2).to_png(),
            "seed 1, {samples} samples: 1 and 2 threads"
        );
        assert_ne!(
            one.pixels,
            on(&seeded(2), 1).pixels,
            "seeds 1 and 2, {samples} samples"
        );
        assert_ne!(
            one.pixels,
            on(&unseeded, 1).pixels,
            "seed 1 and none, {samples} samples"
        );
    }
}

#[test]
fn a_seeded_stream_differs_from_seed_to_seed_and_pixel_to_pixel() {
    use ch01_rays::{jittered_positions, seeded_stream};
    let streams: Vec<u64> = (0..4)
        .flat_map(|seed| (0..64).map(move |pixel| seeded_stream(seed, pixel)))
        .collect();
    let mut distinct = streams.clone();
    distinct.sort_unstable();
    distinct.dedup();
    assert_eq!(
        distinct.len(),
        streams.len(),
        "4 seeds × 64 pixels, all distinct"
    );
    // One jittered sample lands anywhere in the pixel, not at its centre.
    let one: Vec<(f32, f32)> = (0..8)
        .flat_map(|s| jittered_positions(3, 5, 1, s))
        .collect();
    assert!(
        one.iter()
            .all(|&(x, y)| (3.0..4.0).contains(&x) && (5.0..6.0).contains(&y))
    );
    assert!(one.iter().any(|&p| p != (3.5, 5.5)), "{one:?}");
}

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
