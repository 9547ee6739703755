//! `raybook accuracy`: what each accuracy setting costs, and what it buys,
//! measured against one truth.
//!
//! The study renders a grid of settings, maximum depth × weight threshold ×
//! sampling (one centre ray, or 1, 4, 16, … jittered rays per pixel), and
//! the effects added a chapter at a time (`settings.rs`). Every row is
//! compared with one reference, far more accurate than any row and
//! rendered twice so that its own error is known (`reference.rs`, cached
//! on disk). Each row is rendered with several seeds and timed
//! (`measure.rs`), its error measured on linear and 8-bit values
//! (`metrics.rs`) and split into bias² and variance, each with its
//! standard error (`estimate.rs`), which says what may be claimed about the
//! reference's floor (`summary.rs`).
//! The report ranks the settings from those numbers (`report.rs`,
//! `page.rs`) and draws them (`plot.rs`, `bars.rs`, `error_map.rs`).

mod bars;
mod error_map;
mod estimate;
mod measure;
mod metrics;
mod page;
mod plot;
mod reference;
mod report;
mod settings;
mod study;
mod summary;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{HumanDuration, ProgressBar, ProgressStyle};
use raybook::scene_files;
use raybook::toolkit::image::write_atomically;
use raybook::toolkit::{Image, Scene};
use raybook::tracer::Termination;
use raybook::workbench::cli::with_threads;

pub use estimate::{Estimate, Split, split};
pub use measure::{PerRay, Row, measure_rows, primary_rays, render_timed, scene_for, warm_up};
pub use metrics::{Errors, Psnr, errors};
pub use page::{BUDGETS, page};
pub use reference::{REFERENCE_SEEDS, Reference, reference};
pub use report::{
    best_within, bias_cell, by_efficiency, cost, csv, equal_rays_table, pareto, slope, table,
};
pub use settings::{Plan, REFERENCE_FACTOR, Sampling, Setting, Tracer, reference_setting};
pub use study::Study;
pub use summary::{
    FLOOR_FACTOR, Floor, Judged, NEGLIGIBLE_BIAS, STANDARD_ERRORS, Spread, Summary, Verdict,
    judge_at_most_rays,
};

/// `raybook accuracy`: renders a scene at many settings and shows, measured
/// against one reference, what each costs and what it buys.
#[derive(clap::Args, Debug, Clone)]
pub struct AccuracyArgs {
    /// Scene file (TOML); default: the showcase.
    pub scene: Option<PathBuf>,

    /// A smaller grid and picture (128×96, up to 16 rays per pixel, 8
    /// seeds): done in under a minute on two cores once its reference is
    /// cached (about one more to make it). Without it, the full study:
    /// 256×192, up to 64 rays per pixel, 6 seeds, well under an hour on
    /// two cores with no cached reference.
    #[arg(long)]
    pub quick: bool,

    /// Folder for accuracy.md, accuracy.csv, the plots and the error maps.
    #[arg(long, default_value = "accuracy")]
    pub out: PathBuf,

    /// Folder for the cached reference. Default: target/accuracy-reference
    /// in the workspace.
    #[arg(long)]
    pub cache: Option<PathBuf>,

    /// Renders per setting, each with its own seed where it is jittered
    /// (at least 4, for the standard errors). Default: 8 for --quick, 6
    /// for the full study, so that the bias² of the rows with the most
    /// rays per pixel is told from the floor (the report says whether it
    /// was, and how many seeds each other row would need).
    #[arg(long, value_parser = clap::value_parser!(u32).range(4..=64))]
    pub seeds: Option<u32>,

    /// The first seed: the rows use seeds N, N + 1, … (another N gives an
    /// independent run, to check that its conclusions agree). Below the
    /// reference's seeds, 1000001 and 1000002.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=999_000))]
    pub first_seed: u64,

    /// The tracer to measure: the complete one, or chapter 7's own (no BVH,
    /// so slower; it runs in a handout once chapters 1 to 7 are solved).
    #[arg(long, value_enum, default_value_t = Tracer::Complete)]
    pub tracer: Tracer,

    /// Picture width in pixels, instead of the study's (a small one keeps
    /// chapter 7's tracer fast); with --height.
    #[arg(long, requires = "height", value_parser = clap::value_parser!(u32).range(8..=4096))]
    pub width: Option<u32>,

    /// Picture height in pixels, instead of the study's; with --width.
    #[arg(long, requires = "width", value_parser = clap::value_parser!(u32).range(6..=4096))]
    pub height: Option<u32>,

    /// Threads to render with (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,

    /// Only make (or read from the cache) the study's reference, and write
    /// it into the output folder as reference.png and reference.pfm.gz
    /// (its linear values, gzipped): the file a handout carries, since a
    /// handout cannot render it with reference code. No rows, no report.
    #[arg(long)]
    pub reference_only: bool,
}

/// The name of the reference's linear values, gzipped PFM, in the output
/// folder: chapter 7's lab page measures against it.
pub const REFERENCE_PFM_GZ: &str = "reference.pfm.gz";

/// Runs `raybook accuracy`: announces the study, measures, prints the
/// report and writes it with the CSV, the plots and the error maps.
pub fn main(args: &AccuracyArgs) -> ExitCode {
    let scene = match load_scene(args.scene.as_deref()) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    if args.reference_only {
        return reference_only(&scene, args);
    }
    let run = || {
        let study = run_study(&scene, args);
        let written = write_results(&study, &args.out);
        (study, written)
    };
    let started = Instant::now();
    let Ok((study, written)) = with_threads(args.threads, run) else {
        eprintln!("error: cannot start {:?} rendering threads", args.threads);
        return ExitCode::FAILURE;
    };
    println!("{}", page(&study));
    println!("measured in {}", HumanDuration(started.elapsed()));
    match written {
        Ok(paths) => {
            let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
            println!("wrote {}", names.join(", "));
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

/// `--reference-only`: the plan's reference, from the cache or rendered,
/// written into the output folder.
fn reference_only(scene: &Scene, args: &AccuracyArgs) -> ExitCode {
    let plan = plan_of(scene, args);
    let scene = scene.clone().with_size(plan.width, plan.height);
    let cache = args.cache.clone().unwrap_or_else(default_cache);
    let made = with_threads(args.threads, || {
        reference(&scene, &plan.reference(), &cache, &|| {})
    });
    let Ok(made) = made else {
        eprintln!("error: cannot start {:?} rendering threads", args.threads);
        return ExitCode::FAILURE;
    };
    match write_reference(&made.image, &args.out) {
        Ok(paths) => {
            let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
            let from = if made.from_cache {
                "read from"
            } else {
                "made in"
            };
            println!(
                "reference {}×{} ({} jittered rays per pixel, twice), {from} {}; wrote {}",
                plan.width,
                plan.height,
                plan.reference_samples,
                made.cache.display(),
                names.join(", ")
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!(
                "error: cannot write the reference to {}: {e}",
                args.out.display()
            );
            ExitCode::FAILURE
        }
    }
}

/// The plan `args` ask for on `scene`.
fn plan_of(scene: &Scene, args: &AccuracyArgs) -> Plan {
    let mut plan = Plan::new(args.quick, Termination::of(scene));
    if let Some(seeds) = args.seeds {
        plan.seeds = seeds;
    }
    plan.first_seed = args.first_seed;
    plan.tracer = args.tracer;
    if let (Some(width), Some(height)) = (args.width, args.height) {
        (plan.width, plan.height) = (width, height);
    }
    plan
}

/// Writes the reference as reference.png and, its linear values gzipped,
/// [`REFERENCE_PFM_GZ`] into `folder`; returns their paths.
fn write_reference(image: &Image, folder: &Path) -> Result<Vec<PathBuf>, String> {
    use std::io::Write;
    let text = |e: std::io::Error| e.to_string();
    let png = folder.join("reference.png");
    image.save_png(&png).map_err(text)?;
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    gz.write_all(&raybook::workbench::pfm::encode(image))
        .map_err(text)?;
    let pfm = folder.join(REFERENCE_PFM_GZ);
    write_atomically(&pfm, &gz.finish().map_err(text)?).map_err(text)?;
    Ok(vec![png, pfm])
}

/// The picture in a gzipped PFM file, such as [`REFERENCE_PFM_GZ`].
pub fn read_pfm_gz(path: &Path) -> Result<Image, String> {
    use std::io::Read;
    let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut bytes = Vec::new();
    flate2::read::GzDecoder::new(file)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{}: not gzip: {e}", path.display()))?;
    raybook::workbench::pfm::decode(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The study of `scene` as `args` ask, announced, with a progress bar, its
/// error maps written.
fn run_study(scene: &Scene, args: &AccuracyArgs) -> Study {
    let plan = plan_of(scene, args);
    let cache = args.cache.clone().unwrap_or_else(default_cache);
    let quiet = args.quiet;
    let mut bar = ProgressBar::hidden();
    let (study, kept) = study(scene, plan, &cache, |plan, settings, seconds| {
        announce(plan, settings, &cache, seconds);
        bar = progress(quiet, (seconds * 1e6) as u64);
        bar.clone()
    });
    bar.finish_and_clear();
    if let Err(e) = error_map::write_maps(&kept, &study.reference.image, &args.out) {
        eprintln!("note: cannot write the error maps: {e}");
    }
    study
}

/// Measures `plan` on `scene` (at the plan's size) against the reference
/// cached in `cache` (made there if missing), and returns the study with
/// the first pictures of the rows that [`Plan::mapped`] names.
///
/// After the warm-up, `start(plan, settings, seconds)` is told what will be
/// rendered and the estimated seconds, and returns a progress bar, which
/// counts estimated microseconds.
pub fn study(
    scene: &Scene,
    plan: Plan,
    cache: &Path,
    start: impl FnOnce(&Plan, &[Setting], f64) -> ProgressBar,
) -> (Study, Vec<(Setting, Image)>) {
    let scene = scene.clone().with_size(plan.width, plan.height);
    let settings = plan.settings();
    let with_reference: Vec<Setting> = [plan.reference()]
        .into_iter()
        .chain(settings.iter().copied())
        .collect();
    let costs = warm_up(&scene, &with_reference);
    // A row of pixels of a setting costs its rays per pixel times its
    // termination's time per ray.
    let micros = |s: &Setting| {
        let per_ray = costs
            .iter()
            .find(|c| c.termination == s.termination)
            .map_or(0.0, |c| c.seconds);
        (1e6 * per_ray * f64::from(plan.width * s.sampling.samples())) as u64
    };
    let reference_micros = 2 * micros(&plan.reference()) * u64::from(plan.height);
    let rows_micros =
        u64::from(plan.seeds * plan.height) * settings.iter().map(micros).sum::<u64>();
    let bar = start(
        &plan,
        &settings,
        (reference_micros + rows_micros) as f64 / 1e6,
    );
    bar.set_message("reference");
    let reference = reference(&scene, &plan.reference(), cache, &|| {
        bar.inc(micros(&plan.reference()))
    });
    bar.set_position(reference_micros);
    bar.set_message("settings");
    let mapped = plan.mapped();
    let keep = |s: &Setting| mapped.contains(s);
    let (rows, kept) = measure_rows(
        &scene,
        &settings,
        plan.first_seed..plan.first_seed + u64::from(plan.seeds),
        &reference.image,
        keep,
        &|s| bar.inc(micros(s)),
    );
    let floor = Floor {
        mse: reference.floor_mse,
    };
    let pixels = (plan.width * plan.height) as usize;
    let mut summaries: Vec<Summary> = rows.iter().map(|r| Summary::of(r, floor, pixels)).collect();
    judge_at_most_rays(&mut summaries);
    let find = |s: &Setting| summaries.iter().find(|r| r.setting == *s).cloned();
    let effects = plan
        .effect_steps()
        .into_iter()
        .filter_map(|(n, s)| Some((n, find(&s)?)))
        .collect();
    let grid = plan.grid().iter().filter_map(find).collect();
    let study = Study {
        plan,
        reference,
        floor,
        grid,
        effects,
        threads: rayon::current_num_threads(),
    };
    (study, kept)
}

/// Says what the study will do and how long it should take, before it
/// starts.
fn announce(plan: &Plan, settings: &[Setting], cache: &Path, seconds: f64) {
    let full = if plan.width >= 256 {
        "full study"
    } else {
        "quick look"
    };
    println!(
        "raybook accuracy, {full}: {}×{} pixels, {} settings ({} depths × {} thresholds × {} samplings, \
         and the effects) × {} seeds, on {} threads.\nReference: 2 renders × {} jittered rays per pixel \
         at depth 64, threshold 0, cached in {}.\nExpect about {} if the reference is not cached yet \
         (from one untimed render of each setting with one ray per pixel, just now; the performance \
         page gives the times measured on two cores).",
        plan.width,
        plan.height,
        settings.len(),
        plan.depths.len(),
        plan.thresholds.len(),
        plan.samplings.len(),
        plan.seeds,
        rayon::current_num_threads(),
        plan.reference_samples,
        cache.display(),
        HumanDuration(std::time::Duration::from_secs_f64(seconds)),
    );
}

/// A progress bar over the study's estimated microseconds; hidden when
/// `quiet`.
fn progress(quiet: bool, total: u64) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template("{msg:>9} [{bar:40}] {percent}%, {eta} left")
        .expect("a valid template")
        .progress_chars("=> ");
    ProgressBar::new(total).with_style(style)
}

/// target/accuracy-reference in the workspace.
fn default_cache() -> PathBuf {
    raybook::workbench::snapshot::workspace_root()
        .join("target")
        .join("accuracy-reference")
}

/// The scene file at `path`, or the showcase.
fn load_scene(path: Option<&Path>) -> Result<Scene, String> {
    let loaded = match path {
        Some(path) => scene_files::load(path),
        None => raybook::CHAPTER.default_scene(),
    };
    loaded.map_err(|e| e.to_string())
}

/// Writes accuracy.md, accuracy.csv, the reference's picture and the plots
/// into `folder`, each atomically, and returns their paths.
fn write_results(study: &Study, folder: &Path) -> Result<Vec<PathBuf>, String> {
    let text = |e: std::io::Error| e.to_string();
    let md = folder.join("accuracy.md");
    write_atomically(&md, page(study).as_bytes()).map_err(text)?;
    let rows = study.grid.iter().map(|r| ("grid", r));
    let effects = study.effects.iter().map(|(_, r)| ("effects", r));
    let csv_path = folder.join("accuracy.csv");
    write_atomically(&csv_path, csv(rows.chain(effects), study.floor).as_bytes()).map_err(text)?;
    let mut written = vec![md, csv_path];
    written.extend(write_reference(&study.reference.image, folder)?);
    written.extend(plot::plot_all(study, folder)?);
    Ok(written)
}
