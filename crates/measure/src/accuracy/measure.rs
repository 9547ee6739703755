//! Rendering each setting, timing it, and measuring its picture's error
//! against the knob's reference.

use std::time::Instant;

use indicatif::ProgressBar;

use super::settings::{Knob, Setting, all_settings};
use crate::bench::median;
use raybook::toolkit::scene::Effects;
use raybook::toolkit::{Color, Image, Scene};
use raybook::tracer::render_complete;
use raybook::workbench::compare::{psnr, rmse_clamped};

/// How a setting did: what it cost, and how far its picture is from its
/// knob's reference.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// The setting measured.
    pub setting: Setting,
    /// Median wall time of the renders, building the BVH included.
    pub seconds: f64,
    /// Rays traced (all kinds) by one render.
    pub rays: u64,
    /// Against the knob's reference, in linear RGB clamped to [0, 1].
    pub rmse: f64,
    /// The peak signal-to-noise ratio of `rmse`, in dB; infinite for an
    /// exact match.
    pub psnr: f64,
    /// The largest difference of any channel of any pixel.
    pub max_error: f64,
    /// The share of pixels with some channel off by more than 1/255.
    pub share_off: f64,
}

/// How much to measure.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// Renders per setting; the median time counts.
    pub runs: usize,
    /// Fewer settings and fewer samples, for a look in under 30 seconds.
    pub quick: bool,
}

/// Runs the whole measurement on `scene`, moving `bar` on a setting at a
/// time.
pub fn run(scene: &Scene, options: Options, bar: &ProgressBar) -> Vec<Measurement> {
    let scene = scene.clone().with_size(options.width, options.height);
    let settings = all_settings(options.quick);
    bar.set_length(settings.len() as u64);
    sweep(&scene, &settings, options.runs, || bar.inc(1))
}

/// Measures every setting of `settings`, each against the last setting of
/// its knob (the most accurate). `tick` is called after each setting.
pub fn sweep(
    scene: &Scene,
    settings: &[Setting],
    runs: usize,
    tick: impl Fn(),
) -> Vec<Measurement> {
    let mut measurements = Vec::with_capacity(settings.len());
    for knob in Knob::ALL {
        let group: Vec<&Setting> = settings.iter().filter(|s| s.knob == knob).collect();
        let Some(reference) = group.last() else {
            continue;
        };
        let reference = render(scene, reference, 1).image;
        for setting in group {
            let rendered = render(scene, setting, runs);
            measurements.push(compare(setting, &reference, &rendered));
            tick();
        }
    }
    measurements
}

/// A setting's picture, with what it cost.
struct Rendered {
    image: Image,
    /// Rays traced by one render.
    rays: u64,
    /// The median wall time of the renders.
    seconds: f64,
}

/// The scene as a setting renders it.
fn scene_for(scene: &Scene, setting: &Setting) -> Scene {
    let mut scene = scene.clone().without(Effects::ALL.minus(setting.effects));
    scene.image.samples = setting.samples;
    scene
}

/// Renders a setting `runs` times (at least once) with the complete tracer,
/// as `raybook render` does: the four-wide BVH's build ([`raybook::world`])
/// and the render, timed together.
fn render(scene: &Scene, setting: &Setting, runs: usize) -> Rendered {
    let scene = scene_for(scene, setting);
    let mut seconds = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let bvh = raybook::world(&scene);
        let (image, stats) = render_complete(&scene, &bvh, setting.termination, || {});
        seconds.push(start.elapsed().as_secs_f64());
        last = Some((image, stats.rays()));
    }
    let (image, rays) = last.expect("at least one run");
    Rendered {
        image,
        rays,
        seconds: median(seconds),
    }
}

/// How `rendered`, made with `setting`, did against the `reference` picture.
fn compare(setting: &Setting, reference: &Image, rendered: &Rendered) -> Measurement {
    let rmse = rmse_clamped(reference, &rendered.image);
    let (max_error, share_off) = pixel_errors(reference, &rendered.image);
    Measurement {
        setting: setting.clone(),
        seconds: rendered.seconds,
        rays: rendered.rays,
        rmse,
        psnr: psnr(rmse),
        max_error,
        share_off,
    }
}

/// The largest channel difference, and the share of pixels off by more
/// than 1/255, of two pictures as a PNG shows them (clamped to [0, 1]).
fn pixel_errors(reference: &Image, image: &Image) -> (f64, f64) {
    let clamp = |c: Color| c.clamp(Color::ZERO, Color::ONE);
    let mut largest = 0.0f64;
    let mut off = 0usize;
    for (&a, &b) in reference.pixels.iter().zip(&image.pixels) {
        let d = f64::from((clamp(a) - clamp(b)).abs().max_element());
        largest = largest.max(d);
        if d > 1.0 / 255.0 {
            off += 1;
        }
    }
    (largest, off as f64 / reference.pixels.len().max(1) as f64)
}
