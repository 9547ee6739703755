//! `raybook accuracy`: what each accuracy setting costs in time, and what it
//! buys, measured.
//!
//! Four knobs are swept, one at a time, with the others held at their most
//! accurate values: the maximum depth, the weight threshold, the samples per
//! pixel, and the effects themselves, added a chapter at a time. Each
//! setting is rendered several times (the median wall time counts) and
//! compared with the knob's most accurate setting, the reference.

use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use indicatif::ProgressBar;

use crate::toolkit::compare::{psnr, rmse_clamped};
use crate::toolkit::scene::{Effect, Effects};
use crate::toolkit::{Color, Image, Scene};
use crate::tracer::Termination;

/// The accuracy knobs of the tracer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Knob {
    Depth,
    Threshold,
    Samples,
    Effects,
}

impl Knob {
    pub fn name(self) -> &'static str {
        match self {
            Knob::Depth => "max depth",
            Knob::Threshold => "weight threshold",
            Knob::Samples => "samples per pixel",
            Knob::Effects => "effects",
        }
    }
}

/// One setting of the tracer.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    pub knob: Knob,
    /// The knob's value, as shown in the table.
    pub value: String,
    pub termination: Termination,
    pub samples: u32,
    pub effects: Effects,
}

/// How a setting did.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub setting: Setting,
    /// Median wall time of the renders.
    pub seconds: f64,
    /// Rays traced (all kinds) by one render.
    pub rays: u64,
    /// Against the knob's reference, in linear RGB clamped to [0, 1].
    pub rmse: f64,
    pub psnr: f64,
    /// The largest difference of any channel of any pixel.
    pub max_error: f64,
    /// The share of pixels with some channel off by more than 1/255.
    pub share_off: f64,
}

/// How much to measure.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    pub width: u32,
    pub height: u32,
    /// Renders per setting; the median time counts.
    pub runs: usize,
    /// Fewer settings and fewer samples, for a look in under 30 seconds.
    pub quick: bool,
}

/// The most accurate setting: every bounce, no threshold, every effect.
fn best(samples: u32) -> Setting {
    Setting {
        knob: Knob::Depth,
        value: String::new(),
        termination: Termination {
            max_depth: 12,
            min_weight: 0.0,
        },
        samples,
        effects: Effects::ALL,
    }
}

/// The settings of one sweep, most accurate last (it is the reference).
pub fn settings(knob: Knob, quick: bool) -> Vec<Setting> {
    let base = best(1);
    let with = |value: String, change: &dyn Fn(&mut Setting)| {
        let mut s = Setting {
            knob,
            value,
            ..base.clone()
        };
        change(&mut s);
        s
    };
    match knob {
        Knob::Depth => {
            let depths: Vec<u32> = if quick {
                vec![0, 1, 2, 3, 4, 6, 8, 12]
            } else {
                (0..=12).collect()
            };
            depths
                .into_iter()
                .map(|d| with(d.to_string(), &|s| s.termination.max_depth = d))
                .collect()
        }
        Knob::Threshold => [0.1f32, 1e-2, 1e-3, 1e-4, 0.0]
            .into_iter()
            .map(|w| with(w.to_string(), &|s| s.termination.min_weight = w))
            .collect(),
        Knob::Samples => {
            let counts: &[u32] = if quick { &[1, 4, 16] } else { &[1, 4, 16, 64] };
            counts
                .iter()
                .map(|&n| with(n.to_string(), &|s| s.samples = n))
                .collect()
        }
        Knob::Effects => {
            use Effect::*;
            let steps: [(&str, &[Effect]); 4] = [
                ("lambert", &[Lambert, Spot]),
                ("+ shadows", &[Lambert, Spot, Shadows]),
                ("+ reflection", &[Lambert, Spot, Shadows, Reflection]),
                (
                    "+ refraction",
                    &[Lambert, Spot, Shadows, Reflection, Refraction],
                ),
            ];
            steps
                .into_iter()
                .map(|(name, effects)| {
                    with(name.to_string(), &|s| s.effects = Effects::of(effects))
                })
                .collect()
        }
    }
}

/// Every knob's sweep.
pub fn all_settings(quick: bool) -> Vec<Setting> {
    [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects]
        .into_iter()
        .flat_map(|knob| settings(knob, quick))
        .collect()
}

/// The scene as a setting renders it.
fn scene_for(scene: &Scene, setting: &Setting) -> Scene {
    let mut scene = scene.clone().without(Effects::ALL.minus(setting.effects));
    scene.image.samples = setting.samples;
    scene
}

/// Renders a setting `runs` times: the picture, the rays of one render and
/// the median time.
fn measure(scene: &Scene, setting: &Setting, runs: usize) -> (Image, u64, Duration) {
    let scene = scene_for(scene, setting);
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let (image, stats) = ch08_bvh::render_bvh(&scene, setting.termination, || {});
        times.push(start.elapsed());
        last = Some((image, stats.rays()));
    }
    times.sort();
    let (image, rays) = last.expect("at least one run");
    (image, rays, times[times.len() / 2])
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

/// Measures every setting of `settings`, each against the last setting of
/// its knob (the most accurate). `tick` is called after each setting.
pub fn sweep(scene: &Scene, settings: &[Setting], runs: usize, tick: impl Fn()) -> Vec<Row> {
    let mut rows = Vec::with_capacity(settings.len());
    for knob in [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects] {
        let group: Vec<&Setting> = settings.iter().filter(|s| s.knob == knob).collect();
        let Some(reference_setting) = group.last() else {
            continue;
        };
        let (reference, ..) = measure(scene, reference_setting, 1);
        for setting in group {
            let (image, rays, time) = measure(scene, setting, runs);
            let rmse = rmse_clamped(&reference, &image);
            let (max_error, share_off) = pixel_errors(&reference, &image);
            rows.push(Row {
                setting: setting.clone(),
                seconds: time.as_secs_f64(),
                rays,
                rmse,
                psnr: psnr(rmse),
                max_error,
                share_off,
            });
            tick();
        }
    }
    rows
}

/// Runs the whole measurement on `scene` with a progress bar.
pub fn run(scene: &Scene, options: Options, bar: &ProgressBar) -> Vec<Row> {
    let scene = scene.clone().with_size(options.width, options.height);
    let settings = all_settings(options.quick);
    bar.set_length(settings.len() as u64);
    sweep(&scene, &settings, options.runs, || bar.inc(1))
}

/// The rows as a table for the terminal (and the README).
pub fn table(rows: &[Row]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "| knob | value | time (s) | rays | RMSE | PSNR (dB) | max error | pixels off > 1/255 |"
    );
    let _ = writeln!(
        out,
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    for r in rows {
        let _ = writeln!(
            out,
            "| {} | {} | {:.4} | {} | {:.5} | {} | {:.4} | {:.2}% |",
            r.setting.knob.name(),
            r.setting.value,
            r.seconds,
            r.rays,
            r.rmse,
            if r.psnr.is_finite() {
                format!("{:.1}", r.psnr)
            } else {
                "∞".to_owned()
            },
            r.max_error,
            100.0 * r.share_off
        );
    }
    out
}

/// The rows as CSV, one line per setting. An exact match has an infinite
/// PSNR, written `inf`.
pub fn csv(rows: &[Row]) -> String {
    let mut out = String::from("knob,value,seconds,rays,rmse,psnr_db,max_error,share_off_1_255\n");
    for r in rows {
        let _ = writeln!(
            out,
            "{},{},{:.6},{},{:.8},{:.3},{:.6},{:.6}",
            r.setting.knob.name(),
            r.setting.value,
            r.seconds,
            r.rays,
            r.rmse,
            r.psnr,
            r.max_error,
            r.share_off
        );
    }
    out
}

/// The rows on the Pareto front: no other row is both faster and more
/// accurate (rows with zero error are the references, and on it if fastest).
pub fn pareto(rows: &[Row]) -> Vec<&Row> {
    let mut front: Vec<&Row> = rows
        .iter()
        .filter(|r| {
            !rows.iter().any(|o| {
                o.seconds <= r.seconds
                    && o.rmse <= r.rmse
                    && (o.seconds < r.seconds || o.rmse < r.rmse)
            })
        })
        .collect();
    front.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
    front
}

/// The smallest error drawn on the log scale: exact matches sit on it.
const ERROR_FLOOR: f64 = 1e-5;

/// Error against time on log scales, one curve per knob, the Pareto front
/// marked, as an SVG file.
pub fn plot(rows: &[Row], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let error = |r: &Row| r.rmse.max(ERROR_FLOOR);
    let (t0, t1) = rows.iter().fold((f64::MAX, 0.0f64), |(lo, hi), r| {
        (lo.min(r.seconds), hi.max(r.seconds))
    });
    let e1 = rows.iter().map(error).fold(ERROR_FLOOR * 10.0, f64::max);
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption("error against time", ("sans-serif", 24))
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(
            (t0 * 0.8..t1 * 1.25).log_scale(),
            (ERROR_FLOOR * 0.8..e1 * 1.5).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("wall time per render (s, median)")
        .y_desc("RMSE against the reference (linear RGB)")
        .draw()?;
    let colours = [RED, BLUE, GREEN, MAGENTA];
    for (i, knob) in [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects]
        .into_iter()
        .enumerate()
    {
        // In the knob's own order, least accurate first.
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.setting.knob == knob)
            .map(|r| (r.seconds, error(r)))
            .collect();
        let colour = colours[i];
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
            .label(knob.name())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart.draw_series(
            points
                .into_iter()
                .map(|p| Circle::new(p, 4, colour.filled())),
        )?;
    }
    let front: Vec<(f64, f64)> = pareto(rows)
        .into_iter()
        .map(|r| (r.seconds, error(r)))
        .collect();
    chart
        .draw_series(LineSeries::new(front.clone(), BLACK.stroke_width(1)))?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    chart.draw_series(
        front
            .into_iter()
            .map(|p| Circle::new(p, 8, BLACK.stroke_width(2))),
    )?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// `raybook accuracy`: renders a scene at many settings and shows, measured,
/// what each accuracy setting costs in time and what it buys.
#[derive(clap::Args, Debug, Clone)]
pub struct AccuracyArgs {
    /// Scene file (TOML); default: the showcase.
    pub scene: Option<std::path::PathBuf>,

    /// Fewer settings, a smaller image (240×180 instead of 640×480): done in
    /// under 30 seconds. Use --runs 3 with it for the fastest look.
    #[arg(long)]
    pub quick: bool,

    /// Folder for accuracy.csv and accuracy.svg.
    #[arg(long, default_value = "accuracy")]
    pub out: std::path::PathBuf,

    /// Renders per setting; the median time counts.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u64).range(1..=50))]
    pub runs: u64,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Runs `raybook accuracy`.
pub fn main(args: &AccuracyArgs) -> std::process::ExitCode {
    use std::process::ExitCode;
    let loaded = match &args.scene {
        Some(path) => Scene::load(path),
        None => crate::CHAPTER.default_scene(),
    };
    let scene = match loaded {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let (width, height) = if args.quick { (240, 180) } else { (640, 480) };
    let options = Options {
        width,
        height,
        runs: args.runs as usize,
        quick: args.quick,
    };
    let bar = crate::toolkit::cli::progress_bar(0, args.quiet);
    let rows = run(&scene, options, &bar);
    bar.finish_and_clear();
    println!(
        "{width}×{height} pixels, median of {} runs per setting\n",
        args.runs
    );
    println!("{}", table(&rows));
    let csv_path = args.out.join("accuracy.csv");
    let svg_path = args.out.join("accuracy.svg");
    let written = crate::toolkit::image::write_atomically(&csv_path, csv(&rows).as_bytes())
        .map_err(|e| e.to_string())
        .and_then(|()| plot_atomically(&rows, &svg_path));
    match written {
        Ok(()) => {
            println!("wrote {} and {}", csv_path.display(), svg_path.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!(
                "error: cannot write the results to {}: {e}",
                args.out.display()
            );
            ExitCode::FAILURE
        }
    }
}

/// [`plot`] to a temporary file, renamed into place when complete.
fn plot_atomically(rows: &[Row], path: &Path) -> Result<(), String> {
    let temporary = path.with_extension("svg.partial");
    plot(rows, &temporary).map_err(|e| e.to_string())?;
    std::fs::rename(&temporary, path).map_err(|e| e.to_string())
}
