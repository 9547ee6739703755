//! Rendering the rows: each setting rendered once per seed, its seeds one
//! after another (so that only one setting's pictures are held at a time),
//! each render timed and compared with the one reference.

use std::time::Instant;

use raybook::toolkit::scene::Effects;
use raybook::toolkit::{Color, Image, Scene};
use raybook::tracer::{Termination, render_complete, render_terminated};

use super::estimate::{Estimate, Split, split};
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
/// wide BVH's build and the render, timed together), `on_row` called
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
    /// The mean MSE over the seeds, and its split into bias² and variance,
    /// each with its standard error ([`super::estimate`]).
    pub mse: Estimate,
    pub bias2: Estimate,
    pub variance: Estimate,
}

/// Renders every one of `settings` once per seed of `seeds` (a row
/// without randomness is rendered as often, for its time), compares each
/// render with `reference`, and splits each row's error into bias² and
/// variance. `keep(setting)` says which rows' first pictures to hand back
/// (for the error maps); `on_row(setting)` is called per row of pixels
/// rendered.
///
/// A setting's seeds are rendered one after another, since its split
/// needs every pair of its pictures: holding every setting's pictures at
/// once would take gigabytes in the full study. So a slow spell of the
/// machine falls on a few settings' times: the report ranks by rays, and
/// shows times with their spread. Call [`warm_up`] first: no render here
/// is untimed.
pub fn measure_rows(
    scene: &Scene,
    settings: &[Setting],
    seeds: std::ops::Range<u64>,
    reference: &Image,
    keep: impl Fn(&Setting) -> bool,
    on_row: &(dyn Fn(&Setting) + Sync),
) -> (Vec<Row>, Vec<(Setting, Image)>) {
    let mut kept = Vec::new();
    let mut rows = Vec::new();
    for setting in settings {
        let renders: Vec<Rendered> = seeds
            .clone()
            .map(|seed| render_timed(scene, setting, Some(seed), &|| on_row(setting)))
            .collect();
        rows.push(row(*setting, &renders, reference));
        if keep(setting) {
            let first = renders.into_iter().next().expect("at least one seed");
            kept.push((*setting, first.image));
        }
    }
    (rows, kept)
}

/// The row of `setting` from its `renders` (one per seed).
fn row(setting: Setting, renders: &[Rendered], reference: &Image) -> Row {
    let k = renders.len().max(1) as u64;
    let differences: Vec<Vec<f32>> = renders
        .iter()
        .map(|r| difference(&r.image, reference))
        .collect();
    let Split {
        mse,
        bias2,
        variance,
    } = split(&differences);
    let (mse, bias2, variance) = if setting.sampling.is_random() {
        (mse, bias2, variance)
    } else {
        // Every seed renders the same picture: its error is known exactly
        // (given the reference), and all of it is bias.
        let mse = Estimate::exact(mse.value);
        (mse, mse, Estimate::exact(0.0))
    };
    Row {
        setting,
        rays: renders.iter().map(|r| r.rays).sum::<u64>() / k,
        seconds: renders.iter().map(|r| r.seconds).collect(),
        errors: renders
            .iter()
            .map(|r| metrics::errors(&r.image, reference))
            .collect(),
        mse,
        bias2,
        variance,
    }
}

/// `image` − `reference`, every channel of every pixel, as a flat list.
fn difference(image: &Image, reference: &Image) -> Vec<f32> {
    image
        .pixels
        .iter()
        .zip(&reference.pixels)
        .flat_map(|(&x, &r)| {
            let d: Color = x - r;
            [d.x, d.y, d.z]
        })
        .collect()
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
