//! Rendering the rows: each setting rendered once per seed, the settings
//! taken in turn within each round (interleaved, so that a slow spell of
//! the machine falls on every row alike rather than on a few), each render
//! timed and compared with the one reference.

use std::time::Instant;

use raybook::toolkit::scene::Effects;
use raybook::toolkit::{Color, Image, Scene};
use raybook::tracer::{Termination, render_complete, render_terminated};

use super::metrics::{self, Errors};
use super::settings::{Sampling, Setting, Tracer};

/// One render: its picture, the rays it traced and how long it took.
pub struct Rendered {
    pub image: Image,
    /// Rays of every kind traced.
    pub rays: u64,
    /// Wall time of building the BVH and rendering, as `raybook render`
    /// spends it.
    pub seconds: f64,
}

/// The scene as `setting` renders it: its effects, its rays per pixel, and
/// `seed` for the positions of the rays (`None` for the centre ray).
pub fn scene_for(scene: &Scene, setting: &Setting, seed: Option<u64>) -> Scene {
    let mut scene = scene.clone().without(Effects::ALL.minus(setting.effects));
    scene.image.samples = setting.sampling.samples();
    scene.image.seed = match setting.sampling {
        Sampling::Centre => None,
        Sampling::Jittered(_) => seed,
    };
    scene
}

/// Renders `setting` once with its tracer (for the complete one, the
/// four-wide BVH's build and the render, timed together), `on_row` called
/// per row.
pub fn render_timed(
    scene: &Scene,
    setting: &Setting,
    seed: Option<u64>,
    on_row: &(dyn Fn() + Sync),
) -> Rendered {
    let scene = scene_for(scene, setting, seed);
    let start = Instant::now();
    let (image, stats) = match setting.tracer {
        Tracer::Complete => {
            let bvh = raybook::world(&scene);
            render_complete(&scene, &bvh, setting.termination, on_row)
        }
        Tracer::Chapter7 => render_terminated(&scene, setting.termination, on_row),
    };
    Rendered {
        image,
        rays: stats.rays(),
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// A setting's renders, one per seed, against the reference.
#[derive(Debug, Clone)]
pub struct Row {
    pub setting: Setting,
    /// Rays traced by one render (the mean over the seeds).
    pub rays: u64,
    /// The wall time of each render, in the order rendered.
    pub seconds: Vec<f64>,
    /// The errors of each render.
    pub errors: Vec<Errors>,
    /// The squared bias: how far the mean over the seeds is from the
    /// reference, less what the seeds' noise adds to that distance.
    pub bias2: f64,
    /// The variance: how far each render is from the mean of the seeds.
    pub variance: f64,
}

/// What accumulates over a row's renders: the sum of its pictures and of
/// its MSEs, for the bias and variance split.
struct Tally {
    sum: Vec<Color>,
    rays: u64,
    seconds: Vec<f64>,
    errors: Vec<Errors>,
}

/// Renders every one of `settings` `seeds` times (seeds 1, 2, …; a row
/// without randomness is rendered as often, for its time), compares each
/// render with `reference`, and splits each row's error into bias² and
/// variance. `keep(setting)` says which rows' first pictures to hand back
/// (for the error maps); `on_row(setting)` is called per row of pixels
/// rendered.
///
/// Round k renders every setting with seed k, each round starting at a
/// different setting, so that each setting's renders fall at different
/// moments of the study. Call [`warm_up`] first: no render here is
/// untimed.
pub fn measure_rows(
    scene: &Scene,
    settings: &[Setting],
    seeds: u32,
    reference: &Image,
    keep: impl Fn(&Setting) -> bool,
    on_row: &(dyn Fn(&Setting) + Sync),
) -> (Vec<Row>, Vec<(Setting, Image)>) {
    let mut tallies: Vec<Tally> = settings.iter().map(|_| Tally::new()).collect();
    let mut kept = Vec::new();
    let n = settings.len();
    for round in 0..seeds as usize {
        let seed = round as u64 + 1;
        let first = round * n / seeds as usize;
        for i in (0..n).map(|k| (first + k) % n) {
            let setting = &settings[i];
            let rendered = render_timed(scene, setting, Some(seed), &|| on_row(setting));
            if round == 0 && keep(setting) {
                kept.push((*setting, rendered.image.clone()));
            }
            tallies[i].add(rendered, reference);
        }
    }
    let rows = settings
        .iter()
        .zip(tallies)
        .map(|(setting, tally)| tally.row(*setting, reference))
        .collect();
    (rows, kept)
}

/// The primary rays `settings` trace in one render each at `width` ×
/// `height`.
pub fn primary_rays(settings: &[Setting], width: u32, height: u32) -> u64 {
    let per_pixel: u64 = settings
        .iter()
        .map(|s| u64::from(s.sampling.samples()))
        .sum();
    per_pixel * u64::from(width) * u64::from(height)
}

/// What one primary ray of a termination costs, from one render with the
/// centre ray: seconds, and rays traced in all (primary and the rays it
/// spawns).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerRay {
    pub termination: Termination,
    pub seconds: f64,
    pub rays: f64,
}

/// The warm-up: one untimed render of each distinct termination of
/// `settings`, with the centre ray (the thread pool started, the caches
/// and the allocator warm). Its times, per primary ray, size the study
/// before it starts and weigh its progress bar.
pub fn warm_up(scene: &Scene, settings: &[Setting]) -> Vec<PerRay> {
    let mut costs: Vec<PerRay> = Vec::new();
    let pixels = f64::from(scene.image.width * scene.image.height).max(1.0);
    for setting in settings {
        if costs.iter().any(|c| c.termination == setting.termination) {
            continue;
        }
        let centre = Setting {
            sampling: Sampling::Centre,
            ..*setting
        };
        let r = render_timed(scene, &centre, None, &|| {});
        costs.push(PerRay {
            termination: setting.termination,
            seconds: r.seconds / pixels,
            rays: r.rays as f64 / pixels,
        });
    }
    costs
}

impl Tally {
    fn new() -> Tally {
        Tally {
            sum: Vec::new(),
            rays: 0,
            seconds: Vec::new(),
            errors: Vec::new(),
        }
    }

    /// Counts one render in.
    fn add(&mut self, rendered: Rendered, reference: &Image) {
        self.errors
            .push(metrics::errors(&rendered.image, reference));
        self.seconds.push(rendered.seconds);
        self.rays += rendered.rays;
        if self.sum.is_empty() {
            self.sum = rendered.image.pixels;
        } else {
            for (s, p) in self.sum.iter_mut().zip(rendered.image.pixels) {
                *s += p;
            }
        }
    }

    /// The row, once every seed is in.
    ///
    /// With K renders X₁ … X_K, their mean X̄ and the reference R, the
    /// mean MSE splits exactly as (1/K) Σₖ ‖Xₖ − R‖² = ‖X̄ − R‖² +
    /// (1/K) Σₖ ‖Xₖ − X̄‖². The variance is estimated without bias by
    /// V = Σₖ ‖Xₖ − X̄‖² / (K − 1), and E‖X̄ − R‖² = bias² + V/K, so
    /// bias² = ‖X̄ − R‖² − V/K and mean MSE = bias² + V. A setting without
    /// randomness has V = 0: all its error is bias.
    fn row(self, setting: Setting, reference: &Image) -> Row {
        let k = self.errors.len().max(1) as f64;
        let mean_mse = self.errors.iter().map(|e| e.mse).sum::<f64>() / k;
        let mean = Image {
            width: reference.width,
            height: reference.height,
            pixels: self.sum.iter().map(|&s| s / k as f32).collect(),
        };
        let mse_of_mean = metrics::mse(&mean, reference);
        let (bias2, variance) = if setting.sampling.is_random() && k > 1.0 {
            let variance = (k * (mean_mse - mse_of_mean) / (k - 1.0)).max(0.0);
            (mean_mse - variance, variance)
        } else {
            (mean_mse, 0.0)
        };
        Row {
            setting,
            rays: self.rays / k as u64,
            seconds: self.seconds,
            errors: self.errors,
            bias2,
            variance,
        }
    }
}
