//! The command line every chapter binary shares: parse, load, render, write, report.
//!
//! A chapter's `main.rs` names its chapter and its render function and hands
//! both to [`run_or_explain`]; everything a student's binary needs besides the lesson
//! (arguments, errors, progress, atomic output, statistics) lives here.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use indicatif::ProgressDrawTarget;

use crate::chapters::{self, ChapterEntry, Criterion};
use crate::ray_tree::{RayNode, TracerInfo};
use ch00_toolkit::{Image, Scene, Stats};
use scene_files::SceneError;
use scene_files::{Effect, Effects};

mod output;
mod pixel;
mod values;

pub use output::{end_quietly_when_output_closes, progress_bar, report};

pub use pixel::{Pixel, TreeView};
use pixel::{explain_pixel, pixel};
use values::{samples, weight};

/// A chapter binary: which chapter it is, and its default scene.
///
/// Everything else about the chapter (folder, title, the effects it can
/// simulate) comes from the list of chapters, `chapters/chapters.toml`.
#[derive(Debug, Clone, Copy)]
pub struct Chapter {
    /// Its package, such as `ch02-hits`: `env!("CARGO_PKG_NAME")`.
    pub package: &'static str,
    /// Its default scene's text, `scenes/default.toml` (built into the binary).
    pub default_scene: &'static str,
}

impl Chapter {
    /// Its entry in `chapters/chapters.toml`.
    pub fn entry(&self) -> &'static ChapterEntry {
        chapters::find(self.package)
            .unwrap_or_else(|| panic!("{} is not in chapters/chapters.toml", self.package))
    }

    /// The effects its tracer can simulate.
    pub fn effects(&self) -> Effects {
        self.entry().effects()
    }

    /// Parses the chapter's default scene.
    pub fn default_scene(&self) -> Result<Scene, SceneError> {
        scene_files::parse(self.default_scene, &self.entry().default_scene_path())
    }
}

/// Arguments every chapter binary takes.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct RenderArgs {
    /// Scene file to render: TOML (see the chapter's scenes/ folder), or
    /// NFF (the SPD scenes' format) if its name ends in .nff. Without it,
    /// the chapter's default scene.
    pub scene: Option<PathBuf>,

    /// Where to write the PNG. Default: <chapter>.png in the current
    /// directory for the default scene, <scene name>.png for a scene file.
    #[arg(short, long, value_name = "OUT.png")]
    pub output: Option<PathBuf>,

    /// Image width in pixels, instead of the scene's [image] width.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=scene_files::MAX_IMAGE_SIDE as i64))]
    pub width: Option<u32>,

    /// Image height in pixels, instead of the scene's [image] height.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=scene_files::MAX_IMAGE_SIDE as i64))]
    pub height: Option<u32>,

    /// Rays per pixel, instead of the scene's [image] samples: a square
    /// number (1, 4, 9, 16, ...); more rays smooth the jagged edges.
    #[arg(long, value_parser = samples)]
    pub samples: Option<u32>,

    /// Draw the rays' positions inside each pixel from the seed N: every
    /// ray at a random point of its cell, even with one sample per pixel.
    /// Another seed gives another, independent picture; the same seed, scene
    /// and size give the same bytes on any number of threads. Without it,
    /// the positions depend on the pixel alone and one sample goes through
    /// the pixel's centre (chapter 1, "More rays per pixel").
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,

    /// Bounces a path may make, instead of the scene's [trace] max_depth:
    /// more show mirrors in mirrors, fewer render faster (chapter 5 on).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=64))]
    pub max_depth: Option<u32>,

    /// End a path when its weight (the product of the weights along it)
    /// falls below W in every channel, instead of the scene's [trace]
    /// min_weight; 0 never ends a path early (chapter 7 on).
    #[arg(long, value_name = "W", value_parser = weight)]
    pub min_weight: Option<f32>,

    /// Also write the picture's linear values, as the tracer computed them
    /// (f32, before the PNG clamps them to [0, 1] and rounds them to 8
    /// bits), to FILE.pfm: what `raybook accuracy` and the lab's chapter-7
    /// page measure error on.
    #[arg(long, value_name = "FILE.pfm", conflicts_with = "pixel")]
    pub linear: Option<PathBuf>,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,

    /// Switch an effect off for a fast preview (repeat for more).
    #[arg(long, value_enum, value_name = "EFFECT")]
    pub without: Vec<Effect>,

    /// Refuse a scene that calls for an effect this chapter cannot simulate
    /// yet, instead of rendering what it can.
    #[arg(long)]
    pub strict: bool,

    /// Number of threads to render with (default: one per core). The
    /// picture is the same bytes whatever the number.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,

    /// Instead of rendering, print the rays of the pixel X,Y (counted from
    /// 0,0 at the top-left corner) as a tree, as this chapter traces them:
    /// each ray's kind, origin and direction; what it hits (object, t,
    /// point, normal, front or back); what each light adds and whether a
    /// shadow ray finds it blocked; the secondary rays with their weights;
    /// the colour each ray brings back; and why each path ends. It follows
    /// one ray through the pixel's centre, whatever the samples, and writes
    /// no PNG. The tree is short unless --full is given. No --release:
    /// `cargo run -p chNN-name -- --pixel X,Y` answers at once from the
    /// debug build that the tests made (--release first builds for minutes).
    #[arg(long, value_name = "X,Y", value_parser = pixel)]
    pub pixel: Option<Pixel>,

    /// With --pixel: write the tree as JSON instead of text, to compare with
    /// your own tracer's (book/appendix/ray-tree.md has the schema).
    #[arg(long, requires = "pixel")]
    pub json: bool,

    // --full, --fold-depth, --fold-weight and --svg (pixel.rs).
    #[command(flatten)]
    pub view: TreeView,
}

impl RenderArgs {
    /// The scene to render and a name for it: the scene file (TOML, or NFF
    /// when its name ends in `.nff`) or else the chapter's default scene,
    /// with the size and sample overrides applied.
    pub fn load_scene(&self, chapter: &Chapter) -> Result<(Scene, String), SceneError> {
        use scene_files::nff;
        let (scene, name) = match &self.scene {
            Some(path) if nff::is_nff(path) => (nff::load(path)?, path.display().to_string()),
            Some(path) => (scene_files::load(path)?, path.display().to_string()),
            None => (
                chapter.default_scene()?,
                chapter.entry().default_scene_path(),
            ),
        };
        let width = self.width.unwrap_or(scene.image.width);
        let height = self.height.unwrap_or(scene.image.height);
        let mut scene = scene.with_size(width, height);
        scene.image.samples = self.samples.unwrap_or(scene.image.samples);
        scene.image.seed = self.seed.or(scene.image.seed);
        scene.trace.max_depth = self.max_depth.unwrap_or(scene.trace.max_depth);
        scene.trace.min_weight = self.min_weight.unwrap_or(scene.trace.min_weight);
        Ok((scene, name))
    }

    /// Refuses `--max-depth` and `--min-weight` where the chapter's tracer
    /// has no such criterion: before chapter 5 no path goes on after its
    /// first hit, and before chapter 7 no weight ends one.
    pub fn check_criteria(&self, chapter: &Chapter) -> Result<(), String> {
        let given = [
            (Criterion::MaxDepth, "--max-depth", self.max_depth.is_some()),
            (
                Criterion::MinWeight,
                "--min-weight",
                self.min_weight.is_some(),
            ),
        ];
        for (criterion, option, given) in given {
            if given && !chapter.entry().ends_paths_by(criterion) {
                let first = ChapterEntry::introducing_criterion(criterion);
                return Err(format!(
                    "{option}: chapter {} ({}) ends no path by it; chapter {} ({}) introduces it",
                    chapter.entry().number(),
                    chapter.entry().folder,
                    first.number(),
                    first.path().display()
                ));
            }
        }
        Ok(())
    }

    /// Writes `image`'s linear values to `--linear FILE.pfm`, if asked.
    pub fn write_linear(&self, image: &Image) -> Result<(), String> {
        let Some(path) = &self.linear else {
            return Ok(());
        };
        crate::pfm::save(image, path).map_err(|e| format!("cannot write {}: {e}", path.display()))
    }

    /// Where the picture goes.
    pub fn output_path(&self, chapter: &Chapter) -> PathBuf {
        if let Some(output) = &self.output {
            return output.clone();
        }
        let stem = match &self.scene {
            Some(path) => path
                .file_stem()
                .map_or("render".into(), |s| s.to_string_lossy().into_owned()),
            None => chapter.entry().folder.clone(),
        };
        PathBuf::from(format!("{stem}.png"))
    }
}

/// Which effects a chapter simulates for a scene, and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EffectPlan {
    /// What the scene needs (see [`Scene::calls_for`]).
    pub calls_for: Effects,
    /// What the scene's `[trace] effects` and `--without` leave on.
    pub switched_on: Effects,
    /// What will be simulated: called for, switched on and known to the chapter.
    pub simulated: Effects,
    /// Called for and switched on, but introduced by a later chapter.
    pub later: Effects,
}

impl EffectPlan {
    pub fn new(chapter: &Chapter, scene: &Scene, without: &[Effect]) -> EffectPlan {
        let calls_for = scene.calls_for();
        let switched_on = scene.switched_on().minus(Effects::of(without));
        let wanted = calls_for.and(switched_on);
        EffectPlan {
            calls_for,
            switched_on,
            simulated: wanted.and(chapter.effects()),
            later: wanted.minus(chapter.effects()),
        }
    }

    /// The scene to render: the effects the chapter knows but that are
    /// switched off are taken out of it, so nothing is computed for them.
    pub fn apply(&self, chapter: &Chapter, scene: Scene) -> Scene {
        scene.without(chapter.effects().minus(self.switched_on))
    }

    /// One line for each effect called for but left to a later chapter.
    pub fn notes(&self) -> Vec<String> {
        self.later
            .iter()
            .map(|effect| {
                let chapter = chapters::introducing(effect);
                format!(
                    "this scene calls for {effect}, introduced in chapter {} ({})",
                    chapter.number(),
                    chapter.path().display()
                )
            })
            .collect()
    }
}

impl std::fmt::Display for EffectPlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "effects called for: {}; simulated: {}",
            self.calls_for, self.simulated
        )?;
        let off = self.calls_for.minus(self.switched_on);
        if !off.is_empty() {
            write!(f, " (switched off: {off})")?;
        }
        Ok(())
    }
}

/// What a render made.
pub struct Rendered {
    pub image: Image,
    pub stats: Stats,
    pub seconds: Duration,
}

/// Loads the scene, renders it with `render`, writes the PNG and reports;
/// `render(scene, on_row)` must call `on_row` once per finished row. Or,
/// with `--pixel X,Y`, prints the pixel's ray tree instead of a picture:
/// `explain(scene, pixel)` traces the pixel's ray as the chapter does and
/// says what its tracer does and what it saw.
pub fn run_or_explain(
    chapter: &Chapter,
    args: &RenderArgs,
    render: impl Fn(&Scene, &(dyn Fn() + Sync)) -> (Image, Stats) + Sync,
    explain: impl Fn(&Scene, Pixel) -> (TracerInfo, RayNode),
) -> ExitCode {
    end_quietly_when_output_closes();
    if let Err(e) = args.check_criteria(chapter) {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let loaded = args.load_scene(chapter);
    match args.pixel {
        None => run_loaded(chapter, args, loaded, render),
        Some(pixel) => explain_pixel(chapter, args, loaded, pixel, explain),
    }
}

/// The loaded scene, its name, its effect plan and the scene with the plan
/// applied; prints a note for each effect left to a later chapter. `None`
/// (after saying why) when the scene did not load or `--strict` refuses it.
fn planned(
    chapter: &Chapter,
    args: &RenderArgs,
    loaded: Result<(Scene, String), SceneError>,
) -> Option<(EffectPlan, Scene, String)> {
    let (scene, name) = match loaded {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("error: {e}");
            return None;
        }
    };
    let plan = EffectPlan::new(chapter, &scene, &args.without);
    for note in plan.notes() {
        if args.strict {
            eprintln!("error: {note}; --strict refuses to render without it");
            return None;
        }
        eprintln!("note: {note}; this chapter renders without it");
    }
    let scene = plan.apply(chapter, scene);
    Some((plan, scene, name))
}

/// [`run_or_explain`] once the scene is loaded (or failed to load): `loaded` is the
/// scene and its name.
fn run_loaded(
    chapter: &Chapter,
    args: &RenderArgs,
    loaded: Result<(Scene, String), SceneError>,
    render: impl Fn(&Scene, &(dyn Fn() + Sync)) -> (Image, Stats) + Sync,
) -> ExitCode {
    let Some((plan, scene, name)) = planned(chapter, args, loaded) else {
        return ExitCode::FAILURE;
    };
    println!("{plan}");
    let start = Instant::now();
    let rendered = render_with_bar(args, &scene, |on_row| render(&scene, on_row));
    let Ok((image, stats)) = rendered else {
        eprintln!("error: cannot start {:?} rendering threads", args.threads);
        return ExitCode::FAILURE;
    };
    let seconds = start.elapsed();
    let out = args.output_path(chapter);
    if let Err(e) = image.save_png(&out) {
        eprintln!("error: cannot write {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    if let Err(e) = args.write_linear(&image) {
        eprintln!("error: {e}");
        return ExitCode::FAILURE;
    }
    let rendered = Rendered {
        image,
        stats,
        seconds,
    };
    report(chapter, &name, &out, &rendered);
    ExitCode::SUCCESS
}

/// Renders on `--threads` threads, `render` calling its callback once a row,
/// with a progress bar once a render has taken a second (unless `--quiet`).
pub fn render_with_bar<T: Send>(
    args: &RenderArgs,
    scene: &Scene,
    render: impl FnOnce(&(dyn Fn() + Sync)) -> T + Send,
) -> Result<T, String> {
    let bar = progress_bar(scene.image.height, args.quiet);
    bar.set_draw_target(ProgressDrawTarget::hidden());
    let shown = std::sync::Once::new();
    let start = Instant::now();
    let on_row = || {
        bar.inc(1);
        if !args.quiet && start.elapsed() > Duration::from_secs(1) {
            shown.call_once(|| bar.set_draw_target(ProgressDrawTarget::stderr()));
        }
    };
    let rendered = with_threads(args.threads, || render(&on_row));
    bar.finish_and_clear();
    rendered.map_err(|_| format!("cannot start {:?} rendering threads", args.threads))
}

/// Runs `work` on a pool of `threads` threads, so that every parallel loop
/// inside it uses that many; on rayon's global pool (one thread per core)
/// when `None`.
pub fn with_threads<T: Send>(
    threads: Option<u32>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, rayon::ThreadPoolBuildError> {
    let Some(n) = threads else {
        return Ok(work());
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(n as usize)
        .build()?;
    Ok(pool.install(work))
}
