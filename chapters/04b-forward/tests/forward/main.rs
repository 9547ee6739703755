//! Idea 1, tracing forward from the lights: the picture converges to chapter
//! 4's backward one, and the share of photons that make it falls with the
//! aperture.

use ch04_shadows::scene_files;
use ch04_shadows::toolkit::{Color, Image, Scene, Vec3};
use ch04_shadows::workbench::compare::{psnr, rmse, rmse_clamped};
use ch04_shadows::{CHAPTER, Camera};
use ch04b_forward::{
    Forward, Sensor, Settings, backward_image, check_scene, cosine_hemisphere, expected_image,
    trace_forward, uniform_sphere,
};

/// A close-up of a sphere on a floor under one point light, 8×6 pixels: the
/// camera is near, so that many photons reach it and the tests stay fast.
fn close_up() -> Scene {
    let text = r#"
        [camera]
        eye = [0, 1.5, 2.5]
        look_at = [0, 0.4, 0]
        up = [0, 1, 0]
        vfov = 55
        [image]
        width = 8
        height = 6
        background = [0, 0, 0]
        [materials.floor]
        color = [0.8, 0.8, 0.8]
        [materials.red]
        color = [0.9, 0.3, 0.2]
        [[lights]]
        type = "point"
        position = [1.0, 2.5, 1.0]
        color = [1.0, 0.9, 0.8]
        intensity = 4.0
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = 0
        material = "floor"
        [[objects]]
        type = "sphere"
        center = [-0.2, 0.4, 0]
        radius = 0.4
        material = "red"
    "#;
    scene_files::parse(text, "close-up.toml").unwrap()
}

fn forward(scene: &Scene, rays: u64, aperture: f32) -> Forward {
    let settings = Settings {
        rays,
        aperture,
        seed: 7,
    };
    trace_forward(scene, &settings, |_| {})
}

fn mean(image: &Image) -> f64 {
    let sum: f64 = image
        .pixels
        .iter()
        .map(|c| f64::from(c.element_sum()))
        .sum();
    sum / (3 * image.pixels.len()) as f64
}

#[test]
fn the_error_against_the_backward_image_falls_as_the_rays_grow() {
    let scene = close_up();
    let backward = backward_image(&scene, || {});
    let expected = expected_image(&scene, 0.3, 16, || {});
    let runs: Vec<_> = [10_000, 100_000, 1_000_000]
        .map(|rays| forward(&scene, rays, 0.3).image)
        .into();
    let errors: Vec<f64> = runs.iter().map(|f| rmse_clamped(&backward, f)).collect();
    let noise: Vec<f64> = runs.iter().map(|f| rmse(&expected, f)).collect();
    let floor = rmse_clamped(&backward, &expected);
    println!("RMSE against backward {errors:?}, noise {noise:?}, floor {floor}");
    assert!(
        errors[1] < 0.9 * errors[0] && errors[2] < 0.7 * errors[1],
        "{errors:?}"
    );
    assert!(errors[2] > floor, "never better than its limit");
    // The noise falls as 1/√N: by √10 ≈ 3.2 for ten times the photons.
    for pair in noise.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((2.2..4.5).contains(&ratio), "noise {noise:?}");
    }
    assert!(psnr(errors[2]) > psnr(errors[0]));
}

#[test]
fn the_forward_image_is_on_average_right() {
    // The weight ρΦ / (a²·S·cos⁴θ) makes the expected picture the backward
    // one averaged over pixel and aperture. A mistake by a factor (π, 2, or
    // cos⁴θ, which is 0.3 in this wide view's corners) shifts the mean by far
    // more than the noise allows.
    let scene = close_up();
    let expected = expected_image(&scene, 0.5, 16, || {});
    let traced = forward(&scene, 5_000_000, 0.5);
    let noise = rmse(&expected, &traced.image);
    // The pixels' noises are independent: the mean's is noise / √pixels.
    let allowed = 4.0 * noise / (traced.image.pixels.len() as f64).sqrt();
    let (want, got) = (mean(&expected), mean(&traced.image));
    println!(
        "mean {got} against {want} ± {allowed}; {} photons on the image",
        traced.counts.on_image
    );
    assert!(allowed < 0.07 * want, "the test must be able to fail");
    assert!((got - want).abs() < allowed, "{got} against {want}");
}

#[test]
fn the_share_of_rays_reaching_the_image_falls_as_the_aperture_shrinks() {
    let scene = close_up();
    let shares: Vec<f64> = [0.4, 0.2, 0.1, 0.0]
        .map(|a| forward(&scene, 1_000_000, a).share())
        .into();
    println!("shares {shares:?}");
    assert!(shares[0] > shares[1] && shares[1] > shares[2], "{shares:?}");
    assert_eq!(shares[3], 0.0, "no photon passes a true pinhole");
    // The disc's area: half the radius, a quarter of the photons.
    for pair in shares[..3].windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((3.0..5.5).contains(&ratio), "{shares:?}");
    }
}

#[test]
fn the_picture_does_not_depend_on_the_number_of_threads() {
    let scene = close_up();
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| forward(&scene, 200_000, 0.3))
    };
    let one = run(1);
    assert!(one.counts.on_image > 10);
    assert_eq!(one, run(3));
    let other_seed = trace_forward(
        &scene,
        &Settings {
            rays: 200_000,
            aperture: 0.3,
            seed: 8,
        },
        |_| {},
    );
    assert_ne!(one.image, other_seed.image, "the seed matters");
}

#[test]
fn the_sensor_inverts_the_camera() {
    let scene = close_up().with_size(40, 30);
    let sensor = Sensor::new(&scene, 0.1);
    let camera = Camera::new(&scene.camera, 40, 30);
    for (px, py) in [(0.2, 0.3), (17.5, 9.1), (39.9, 29.8), (20.0, 15.0)] {
        let ray = camera.ray_through(px, py);
        let (index, cos) = sensor.pixel(-ray.direction).expect("in view");
        assert_eq!(index, py as usize * 40 + px as usize, "({px}, {py})");
        assert!((cos - ray.direction.dot(camera.forward)).abs() < 1e-6);
    }
    let behind = sensor.pixel(camera.forward);
    assert_eq!(behind, None, "light going away from the camera");
    // A ray from the scene straight at the eye crosses the disc at its
    // distance; one aimed a little beside the disc does not.
    let start = camera.eye + 3.0 * camera.forward;
    let t = sensor.crossing(start, -camera.forward).expect("through");
    assert!((t - 3.0).abs() < 1e-5);
    let beside = camera.eye + 0.11 * camera.right - start;
    assert_eq!(sensor.crossing(start, beside.normalize()), None);
    let within = camera.eye + 0.09 * camera.up - start;
    assert!(sensor.crossing(start, within.normalize()).is_some());
    assert_eq!(
        sensor.crossing(camera.eye - camera.forward, camera.forward),
        None
    );
}

#[test]
fn photon_directions_have_the_right_distributions() {
    // A regular grid of (u, v) stands in for random numbers.
    let n = 200;
    let grid = || (0..n * n).map(|i| ((i % n) as f32 + 0.5, (i / n) as f32 + 0.5));
    let normal = Vec3::new(1.0, 2.0, -2.0).normalize();
    let (mut z, mut z2, mut cos) = (0.0, 0.0, 0.0);
    for (u, v) in grid() {
        let (u, v) = (u / n as f32, v / n as f32);
        let d = uniform_sphere(u, v);
        assert!((d.length() - 1.0).abs() < 1e-5);
        z += d.z as f64;
        z2 += (d.z * d.z) as f64;
        let r = cosine_hemisphere(normal, u, v);
        assert!(r.dot(normal) >= 0.0, "on the normal's side");
        cos += r.dot(normal) as f64;
    }
    let count = (n * n) as f64;
    // Uniform on the sphere: mean z = 0, mean z² = 1/3.
    assert!((z / count).abs() < 1e-3);
    assert!((z2 / count - 1.0 / 3.0).abs() < 1e-3);
    // Density cos θ / π: mean cos θ = ∫cos²θ/π dω = 2/3 (uniform would give 1/2).
    assert!((cos / count - 2.0 / 3.0).abs() < 1e-3, "{}", cos / count);
}

#[test]
fn scenes_the_forward_tracer_cannot_match_are_refused() {
    assert!(check_scene(&close_up()).is_ok());
    let scene =
        scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/forward.toml")).unwrap();
    assert!(check_scene(&scene).is_ok());
    let problems = check_scene(&CHAPTER.default_scene().unwrap()).unwrap_err();
    println!("{problems}");
    assert!(
        problems.contains("lights[0] is ambient light"),
        "{problems}"
    );
    assert!(
        problems.contains("lights[2] is not a point light"),
        "{problems}"
    );
    assert!(problems.contains("background"), "{problems}");
    let mut hidden = close_up();
    hidden.objects[1].shadows = false;
    assert!(check_scene(&hidden).unwrap_err().contains("objects[1]"));
}

#[test]
fn rmse_and_psnr() {
    let grey = |v| Image {
        width: 2,
        height: 1,
        pixels: vec![Color::splat(v); 2],
    };
    assert_eq!(rmse(&grey(0.5), &grey(0.5)), 0.0);
    assert_eq!(psnr(0.0), f64::INFINITY);
    assert!((rmse(&grey(0.5), &grey(0.6)) - 0.1).abs() < 1e-6);
    assert!((psnr(0.1) - 20.0).abs() < 1e-9);
    assert!((psnr(1.0 / 255.0) - 48.13).abs() < 0.01);
    // Values above 1 count in full, unless clamped as the PNG shows them.
    assert!((rmse(&grey(1.0), &grey(3.0)) - 2.0).abs() < 1e-6);
    assert_eq!(rmse_clamped(&grey(1.0), &grey(3.0)), 0.0);
}

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
