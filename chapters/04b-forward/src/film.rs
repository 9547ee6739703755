//! The film: photons traced in parallel chunks, each with its own seeded
//! generator, and added up per pixel into the forward picture.

use rand::SeedableRng;
use rand_pcg::Pcg64Mcg;
use rayon::prelude::*;

use ch04_shadows::toolkit::{Color, Image, Scene};

use crate::photon::{Counts, Emitter, emitters, trace_photon};
use crate::sensor::Sensor;

/// Photons per chunk. Each chunk has its own random number generator, seeded
/// from the chunk's index: the same chunks give the same photons whatever
/// thread traces them.
pub const CHUNK: u64 = 1 << 14;

/// Chunks traced in parallel before their photons are added to the image, in
/// the chunks' order.
const BATCH: u64 = 64;

/// How a forward picture is taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Photons emitted, over all lights.
    pub rays: u64,
    /// The radius a of the aperture disc around the eye, in scene units.
    pub aperture: f32,
    /// Seed of the random numbers: the same seed gives the same picture.
    pub seed: u64,
}

/// A forward-traced picture and what became of its photons.
#[derive(Debug, Clone, PartialEq)]
pub struct Forward {
    pub image: Image,
    pub counts: Counts,
}

impl Forward {
    /// The share of the emitted photons that reached the image.
    pub fn share(&self) -> f64 {
        self.counts.on_image as f64 / self.counts.emitted.max(1) as f64
    }
}

/// The seed of one chunk's generator.
pub(crate) fn chunk_seed(seed: u64, chunk: u64) -> u64 {
    seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ chunk
}

/// Traces the photons of one chunk; returns the pixels they landed on.
fn trace_chunk(
    scene: &Scene,
    sensor: &Sensor,
    emitters: &[Emitter],
    settings: &Settings,
    chunk: u64,
) -> (Vec<(usize, Color)>, Counts) {
    let mut rng = Pcg64Mcg::seed_from_u64(chunk_seed(settings.seed, chunk));
    let photons = CHUNK.min(settings.rays - chunk * CHUNK);
    let mut counts = Counts::default();
    let landed = (0..photons)
        .filter_map(|_| trace_photon(scene, sensor, emitters, &mut rng, &mut counts))
        .collect();
    (landed, counts)
}

/// Idea 1: emits `settings.rays` photons from the scene's point lights and
/// records those that reach the image through the aperture (`photon.rs`
/// derives each one's value). `progress(photons)` is called as chunks of
/// photons finish.
///
/// The chunks run in parallel; their photons are added to the image in the
/// chunks' order, so the picture is the same bytes whatever the number of
/// threads. The scene should pass [`check_scene`](crate::check_scene).
pub fn trace_forward(scene: &Scene, settings: &Settings, progress: impl Fn(u64) + Sync) -> Forward {
    let sensor = Sensor::new(scene, settings.aperture);
    let emitters = emitters(scene);
    let (width, height) = (scene.image.width, scene.image.height);
    let mut sums = vec![[0f64; 3]; width as usize * height as usize];
    let mut counts = Counts::default();
    let chunks = settings.rays.div_ceil(CHUNK);
    for first in (0..chunks).step_by(BATCH as usize) {
        let batch: Vec<_> = (first..chunks.min(first + BATCH))
            .into_par_iter()
            .map(|chunk| {
                let traced = trace_chunk(scene, &sensor, &emitters, settings, chunk);
                progress(traced.1.emitted);
                traced
            })
            .collect();
        for (landed, chunk_counts) in batch {
            counts += chunk_counts;
            for (pixel, value) in landed {
                for (sum, v) in sums[pixel].iter_mut().zip(value.to_array()) {
                    *sum += f64::from(v);
                }
            }
        }
    }
    let a = f64::from(settings.aperture);
    let scale = 4.0 * std::f64::consts::PI
        / (settings.rays.max(1) as f64 * a * a * f64::from(sensor.pixel_area));
    let pixels = sums
        .iter()
        .map(|s| Color::new(s[0] as f32, s[1] as f32, s[2] as f32) * scale as f32)
        .map(|c| if c.is_finite() { c } else { Color::ZERO })
        .collect();
    Forward {
        image: Image {
            width,
            height,
            pixels,
        },
        counts,
    }
}
