//! `raybook accuracy`: what each accuracy setting costs in time, and what it
//! buys, measured.
//!
//! Four knobs are swept, one at a time, with the others held at their most
//! accurate values: the maximum depth, the weight threshold, the samples per
//! pixel, and the effects themselves, added a chapter at a time
//! (`settings.rs`). Each setting is rendered several times (the median wall
//! time counts) and compared with the knob's most accurate setting, the
//! reference (`measure.rs`). The results are a table and a CSV file
//! (`report.rs`) and a plot of error against time (`plot.rs`).

mod measure;
mod plot;
mod report;
mod settings;

use raybook::scene_files;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{HumanDuration, ProgressBar, ProgressStyle};

pub use measure::{Measurement, Options, run, sweep};
pub use plot::plot;
pub use report::{csv, pareto, table};
pub use settings::{Knob, Setting, all_settings, settings};

use raybook::toolkit::Scene;
use raybook::toolkit::image::write_atomically;

/// `raybook accuracy`: renders a scene at many settings and shows, measured,
/// what each accuracy setting costs in time and what it buys.
#[derive(clap::Args, Debug, Clone)]
pub struct AccuracyArgs {
    /// Scene file (TOML); default: the showcase.
    pub scene: Option<PathBuf>,

    /// Fewer settings, a smaller image (240×180 instead of 640×480): done in
    /// under 30 seconds. Use --runs 3 with it for the fastest look.
    #[arg(long)]
    pub quick: bool,

    /// Folder for accuracy.csv and accuracy.svg.
    #[arg(long, default_value = "accuracy")]
    pub out: PathBuf,

    /// Renders per setting; the median time counts.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u64).range(1..=50))]
    pub runs: u64,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

impl AccuracyArgs {
    /// How much to measure: the picture's size and the renders per setting.
    fn options(&self) -> Options {
        let (width, height) = if self.quick { (240, 180) } else { (640, 480) };
        Options {
            width,
            height,
            runs: self.runs as usize,
            quick: self.quick,
        }
    }
}

/// Runs `raybook accuracy`: measures, prints the table, writes the CSV and
/// the plot.
pub fn main(args: &AccuracyArgs) -> ExitCode {
    let scene = match load_scene(args.scene.as_deref()) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let options = args.options();
    let started = Instant::now();
    let bar = setting_progress(args.quiet);
    let measurements = run(&scene, options, &bar);
    bar.finish_and_clear();
    let Options { width, height, .. } = options;
    println!(
        "{width}×{height} pixels, median of {} runs per setting\n",
        args.runs
    );
    println!("{}", table(&measurements));
    println!(
        "measured {} settings in {}",
        measurements.len(),
        HumanDuration(started.elapsed())
    );
    match write_results(&measurements, &args.out) {
        Ok((csv, svg)) => {
            println!("wrote {} and {}", csv.display(), svg.display());
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

/// The scene file at `path`, or the showcase.
fn load_scene(path: Option<&Path>) -> Result<Scene, String> {
    let loaded = match path {
        Some(path) => scene_files::load(path),
        None => raybook::CHAPTER.default_scene(),
    };
    loaded.map_err(|e| e.to_string())
}

/// A progress bar over the settings, hidden when `quiet`; its length is
/// set when the settings are known.
fn setting_progress(quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let style =
        ProgressStyle::with_template("measuring [{bar:40}] {pos}/{len} settings, {eta} left")
            .expect("a valid template")
            .progress_chars("=> ");
    ProgressBar::new(0).with_style(style)
}

/// Writes accuracy.csv and accuracy.svg into `folder`, each atomically, and
/// returns their paths.
fn write_results(
    measurements: &[Measurement],
    folder: &Path,
) -> Result<(PathBuf, PathBuf), String> {
    let csv_path = folder.join("accuracy.csv");
    let svg_path = folder.join("accuracy.svg");
    write_atomically(&csv_path, csv(measurements).as_bytes()).map_err(|e| e.to_string())?;
    plot_atomically(measurements, &svg_path)?;
    Ok((csv_path, svg_path))
}

/// [`plot()`] to a temporary file, renamed into place when complete.
fn plot_atomically(measurements: &[Measurement], path: &Path) -> Result<(), String> {
    let temporary = path.with_extension("svg.partial");
    plot(measurements, &temporary).map_err(|e| e.to_string())?;
    std::fs::rename(&temporary, path).map_err(|e| e.to_string())
}
