//! `raybook bench`: times the SPD scenes, and POV-Ray on the same scenes.
//!
//! Each scene is rendered by running this very binary (`raybook render
//! SCENE.nff`) as a new process, so the time includes starting, parsing,
//! building the BVH, rendering and writing the PNG, as POV-Ray's does
//! (`spd.rs`, with POV-Ray's side in `povray.rs`). `--scaling` instead renders
//! in this process and reports the BVH's build time and the render time
//! against the number of primitives (`scaling.rs`), for the SPD scenes and for
//! larger sphereflakes and Sierpinski tetrahedra made here (`fractals.rs`).
//! `--primary` times only the tracing of the primary rays, per thread,
//! against Embree 4 on the same rays (`primary/`).
//!
//! The measuring helpers, [`median`] and the Markdown [`table`], serve
//! `raybook accuracy` and `cargo bench` too.

mod fractals;
mod povray;
mod primary;
mod scaling;
mod spd;
pub mod table;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use indicatif::{HumanDuration, ProgressBar, ProgressStyle};

pub use fractals::{with_sphereflake, with_tetrahedron};
pub use primary::{Agreement, PYTHON_VAR, agreement, hit_distances, primary_rays, primary_world};

use raybook::scene_files::MAX_IMAGE_SIDE;

/// The SPD scenes that come with this repository (`scenes/spd`, see its
/// README.md), found wherever the command is run from.
pub const SPD_SCENES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/spd");

/// Arguments of `raybook bench`.
#[derive(clap::Args, Debug, Clone)]
pub struct BenchArgs {
    /// Folder of scenes: NAME.nff, and NAME.pov for POV-Ray. The default is
    /// this repository's scenes/spd: Eric Haines's Standard Procedural
    /// Databases (public domain; see the README.md there).
    #[arg(long, default_value = SPD_SCENES)]
    pub scenes: PathBuf,

    /// Only the scenes whose names contain one of these (default: all).
    /// tinyraytracer's row comes whenever its binary is given;
    /// `--only tinyraytracer` times it alone.
    #[arg(long)]
    pub only: Vec<String>,

    /// Width and height of the pictures.
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_IMAGE_SIDE)))]
    pub size: u32,

    /// Timed runs per scene; the median is reported.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub runs: u32,

    /// Threads for both tracers (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,

    /// Do not run POV-Ray even if it is installed.
    #[arg(long)]
    pub no_povray: bool,

    /// tinyraytracer's binary, to time against raybook on its scene (a row
    /// of its own, at its fixed 1024×768). Build it from
    /// github.com/ssloy/tinyraytracer: `g++ -O3 -fopenmp tinyraytracer.cpp`.
    /// raybook renders the same scene written as TOML:
    /// scenes/peers/tinyraytracer.toml.
    #[arg(long, value_name = "PROGRAM")]
    pub tinyraytracer: Option<PathBuf>,

    /// Report BVH build and render time against primitive count instead.
    #[arg(long)]
    pub scaling: bool,

    /// Report primary-ray throughput instead: each scene's rays (one per
    /// pixel, through its centre) traced to their closest hit against
    /// the complete tracer's wide BVH on one thread and on --threads
    /// threads (and against chapter 8's on one, for comparison), and by
    /// Embree 4 on one thread and in --threads processes at once (so that
    /// both sides' threads share the cores alike), with how far the two
    /// agree. Only the tracing is timed. Embree runs through the Python package embreex,
    /// in $RAYBOOK_PYTHON (else python3); where it cannot be imported, or
    /// the scene has spheres (embreex traces triangles only), the table
    /// says so.
    #[arg(long, conflicts_with = "scaling")]
    pub primary: bool,

    /// With --primary: do not run Embree even if it is installed.
    #[arg(long, requires = "primary")]
    pub no_embree: bool,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Runs the benchmark and prints its Markdown table.
pub fn run(args: &BenchArgs) -> ExitCode {
    let threads = args.threads.unwrap_or_else(one_per_core);
    let started = Instant::now();
    let report =
        spd_scenes(&args.scenes, &args.only, only_tinyraytracer(args)).and_then(|scenes| {
            if args.scaling {
                scaling::report(args, threads, &scenes)
            } else if args.primary {
                primary::report(args, threads, &scenes)
            } else {
                spd::report(args, threads, &scenes)
            }
        });
    match report {
        Ok(report) => {
            println!("{report}");
            println!("measured in {}", HumanDuration(started.elapsed()));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// One thread per core, or one if that cannot be told.
fn one_per_core() -> u32 {
    std::thread::available_parallelism().map_or(1, |n| n.get() as u32)
}

/// Is tinyraytracer's row all that is asked for (`--only tinyraytracer`,
/// with its binary given, and no other table)? Then no .nff scene need match.
fn only_tinyraytracer(args: &BenchArgs) -> bool {
    args.tinyraytracer.is_some()
        && !args.scaling
        && !args.primary
        && args
            .only
            .iter()
            .any(|o| "tinyraytracer".contains(o.as_str()))
}

/// The .nff files of a folder whose names contain one of `only`, sorted; an
/// error if there are none, unless `may_be_none`.
fn spd_scenes(dir: &Path, only: &[String], may_be_none: bool) -> Result<Vec<PathBuf>, String> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    let mut scenes: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "nff"))
        .filter(|p| only.is_empty() || only.iter().any(|o| p.to_string_lossy().contains(o)))
        .collect();
    if scenes.is_empty() && !may_be_none {
        return Err(format!("no matching .nff scenes in {}", dir.display()));
    }
    scenes.sort();
    Ok(scenes)
}

/// A scene's name: its file name without the extension.
fn scene_name(path: &Path) -> String {
    path.file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned()
}

/// A progress bar over `len` scenes, hidden when `quiet`. It shows the
/// scene being timed as its message, and is only redrawn when it moves (no
/// ticking thread competes with the renders for a core).
fn scene_progress(len: usize, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template("timing [{bar:30}] {pos}/{len} scenes, now {msg}")
        .expect("a valid template")
        .progress_chars("=> ");
    ProgressBar::new(len as u64).with_style(style)
}

/// The median of some numbers: the middle one in order, or the mean of the
/// middle two if their count is even. NaN sorts after every number.
///
/// # Panics
///
/// If there are no numbers.
pub fn median(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut values: Vec<f64> = values.into_iter().collect();
    assert!(!values.is_empty(), "the median of no numbers");
    values.sort_by(f64::total_cmp);
    let middle = values.len() / 2;
    if values.len() % 2 == 1 {
        values[middle]
    } else {
        (values[middle - 1] + values[middle]) / 2.0
    }
}

#[cfg(test)]
mod tests {
    use super::{BenchArgs, SPD_SCENES, median, only_tinyraytracer, spd_scenes};

    #[test]
    fn the_median_is_the_middle_value_in_order() {
        assert_eq!(median([3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median([5.0]), 5.0);
        assert_eq!(median([4.0, 1.0, 3.0, 2.0]), 2.5, "the middle two's mean");
        assert_eq!(median([1.0, 100.0, 2.0, 3.0, 1e9]), 3.0, "not the mean");
    }

    #[test]
    fn only_tinyraytracer_needs_no_nff_scene() {
        #[derive(clap::Parser)]
        struct Cli {
            #[command(flatten)]
            bench: BenchArgs,
        }
        let args = |words: &[&str]| {
            let words = ["bench"].iter().chain(words);
            <Cli as clap::Parser>::parse_from(words).bench
        };
        let trt = [
            "--tinyraytracer",
            "./tinyraytracer",
            "--only",
            "tinyraytracer",
        ];
        assert!(only_tinyraytracer(&args(&trt)));
        assert!(!only_tinyraytracer(&args(&trt[2..])), "no binary given");
        let primary = [&trt[..], &["--primary"]].concat();
        assert!(
            !only_tinyraytracer(&args(&primary)),
            "--primary has no such row"
        );
        let spd = SPD_SCENES.as_ref();
        let none = spd_scenes(spd, &["tinyraytracer".into()], false);
        assert!(none.unwrap_err().contains("no matching .nff scenes"));
        assert_eq!(spd_scenes(spd, &["tinyraytracer".into()], true), Ok(vec![]));
    }

    #[test]
    #[should_panic(expected = "no numbers")]
    fn there_is_no_median_of_nothing() {
        median([]);
    }
}
