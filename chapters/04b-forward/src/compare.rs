//! Idea 1 against Idea 2: the backward pictures a forward one is measured
//! against, and the measurements.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use std::time::Instant;

use ch04_shadows::toolkit::{Color, Image, Scene, Stats};
use ch04_shadows::workbench::compare::{rmse, rmse_clamped};
use ch04_shadows::{Camera, Ray, ShadowStart, render_shadows, trace};

use crate::film::{Forward, Settings, chunk_seed, trace_forward};

/// Idea 2, for comparison: chapter 4's picture of the scene, one ray per
/// pixel cast backwards from the eye.
pub fn backward_image(scene: &Scene, on_row: impl Fn() + Sync) -> Image {
    render_shadows(scene, ShadowStart::Offset, on_row).0
}

/// What [`trace_forward`] converges to, computed backwards with chapter 4's
/// tracer: each pixel's value averaged over its area and over the aperture
/// disc (rays from points of the disc, in the directions of the pixel's
/// points), with `samples`² rays per pixel. Both averages are stratified:
/// the pixel is cut into `samples` × `samples` cells, the disc into as many
/// cells of equal area (rings × sectors), and each ray pairs one cell of
/// each, at random positions inside them, seeded by the pixel's index.
///
/// Its distance from [`backward_image`] is the part of the forward image's
/// error that no number of photons removes.
pub fn expected_image(
    scene: &Scene,
    aperture: f32,
    samples: u32,
    on_row: impl Fn() + Sync,
) -> Image {
    let (width, height) = (scene.image.width, scene.image.height);
    let camera = Camera::new(&scene.camera, width, height);
    let n = samples.max(1);
    let pixel = |x: u32, y: u32, stats: &mut Stats| {
        let index = u64::from(y) * u64::from(width) + u64::from(x);
        let mut rng = Pcg64Mcg::seed_from_u64(chunk_seed(0x5EED, index));
        // Which disc cell each pixel cell is paired with: a random permutation.
        let mut disc_cells: Vec<u32> = (0..n * n).collect();
        for i in (1..disc_cells.len()).rev() {
            disc_cells.swap(i, rng.random_range(0..=i));
        }
        let mut sum = Color::ZERO;
        for (cell, disc_cell) in (0..n * n).zip(disc_cells) {
            let px = x as f32 + ((cell % n) as f32 + rng.random::<f32>()) / n as f32;
            let py = y as f32 + ((cell / n) as f32 + rng.random::<f32>()) / n as f32;
            let ring = ((disc_cell / n) as f32 + rng.random::<f32>()) / n as f32;
            let sector = ((disc_cell % n) as f32 + rng.random::<f32>()) / n as f32;
            let r = aperture * ring.sqrt(); // equal areas: r² uniform
            let (sin, cos) = (std::f32::consts::TAU * sector).sin_cos();
            let ray = Ray {
                origin: camera.eye + r * (cos * camera.right + sin * camera.up),
                direction: camera.ray_through(px, py).direction,
            };
            sum += trace(scene, &ray, ShadowStart::Offset, stats);
        }
        sum / (n * n) as f32
    };
    Image::render(width, height, pixel, on_row).0
}

/// How many photons make the noise `target`, from a run of `rays` photons
/// whose noise (RMSE against [`expected_image`]) was `noise`. Each photon is
/// independent of the others, so the variance of the picture falls as 1/N
/// and its RMSE as 1/√N: N·noise² is the same for every N.
pub fn rays_needed(rays: u64, noise: f64, target: f64) -> f64 {
    rays as f64 * (noise / target).powi(2)
}

/// One forward picture and how it measures up.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Photons emitted.
    pub rays: u64,
    pub forward: Forward,
    /// The time [`trace_forward`] took.
    pub seconds: f64,
    /// RMSE against the backward picture, as the PNGs show them.
    pub error: f64,
    /// RMSE against the expected picture, unclamped: the noise alone.
    pub noise: f64,
}

/// Traces the scene forward with `settings` and measures the picture against
/// `backward` ([`backward_image`]) and `expected` ([`expected_image`]).
/// `progress` is handed to [`trace_forward`].
pub fn measure(
    scene: &Scene,
    settings: &Settings,
    backward: &Image,
    expected: &Image,
    progress: impl Fn(u64) + Sync,
) -> Run {
    let start = Instant::now();
    let forward = trace_forward(scene, settings, progress);
    let seconds = start.elapsed().as_secs_f64();
    Run {
        rays: settings.rays,
        error: rmse_clamped(backward, &forward.image),
        noise: rmse(expected, &forward.image),
        forward,
        seconds,
    }
}

/// The pictures side by side, left to right, with a grey line between. There
/// is at least one, and each has the size of the first.
pub fn strip(images: &[&Image]) -> Image {
    const GAP: u32 = 2;
    let (w, h) = (images[0].width, images[0].height);
    let width = images.len() as u32 * (w + GAP) - GAP;
    let mut pixels = vec![Color::splat(0.5); (width * h) as usize];
    for (i, image) in images.iter().enumerate() {
        let left = i as u32 * (w + GAP);
        for y in 0..h {
            for x in 0..w {
                pixels[(y * width + left + x) as usize] = image.get(x, y);
            }
        }
    }
    Image {
        width,
        height: h,
        pixels,
    }
}
