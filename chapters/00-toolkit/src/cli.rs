//! The command line every chapter binary shares: parse, load, render, write, report.
//!
//! A chapter's `main.rs` names its chapter and its render function and hands
//! both to [`run`]; everything a student's binary needs besides the lesson
//! (arguments, errors, progress, atomic output, statistics) lives here.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};

use crate::{Image, Scene, SceneError, Stats};

/// One chapter of the workbook.
#[derive(Debug, Clone, Copy)]
pub struct Chapter {
    /// Its folder under `chapters/`, such as `02-hits`.
    pub folder: &'static str,
    /// What it teaches, in a few words.
    pub title: &'static str,
    /// Its default scene's path, for messages.
    pub default_scene_path: &'static str,
    /// Its default scene's text (built into the binary).
    pub default_scene: &'static str,
}

impl Chapter {
    /// Parses the chapter's default scene.
    pub fn default_scene(&self) -> Result<Scene, SceneError> {
        Scene::parse(self.default_scene, self.default_scene_path)
    }
}

/// Arguments every chapter binary takes.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct RenderArgs {
    /// Scene file to render (TOML, see the chapter's scenes/ folder).
    /// Without it, the chapter's default scene.
    pub scene: Option<PathBuf>,

    /// Where to write the PNG. Default: <chapter>.png in the current
    /// directory for the default scene, <scene name>.png for a scene file.
    #[arg(short, long, value_name = "OUT.png")]
    pub output: Option<PathBuf>,

    /// Image width in pixels, instead of the scene's [image] width.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub width: Option<u32>,

    /// Image height in pixels, instead of the scene's [image] height.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub height: Option<u32>,

    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

impl RenderArgs {
    /// The scene to render, with the size overrides applied, and a name for it.
    pub fn load_scene(&self, chapter: &Chapter) -> Result<(Scene, String), SceneError> {
        let (scene, name) = match &self.scene {
            Some(path) => (Scene::load(path)?, path.display().to_string()),
            None => (
                chapter.default_scene()?,
                chapter.default_scene_path.to_owned(),
            ),
        };
        let width = self.width.unwrap_or(scene.image.width);
        let height = self.height.unwrap_or(scene.image.height);
        Ok((scene.with_size(width, height), name))
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
            None => chapter.folder.to_owned(),
        };
        PathBuf::from(format!("{stem}.png"))
    }
}

/// A progress bar over the rows of a render; hidden when `quiet` (and by
/// indicatif itself when the output is not a terminal).
pub fn progress_bar(rows: u32, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(rows as u64);
    let style =
        ProgressStyle::with_template("{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left")
            .expect("a valid template")
            .progress_chars("=> ");
    bar.set_style(style);
    bar
}

/// What a render made.
pub struct Rendered {
    pub image: Image,
    pub stats: Stats,
    pub seconds: Duration,
}

/// Loads the scene, renders it with `render`, writes the PNG and reports.
/// `render(scene, on_row)` must call `on_row` once per finished row.
pub fn run(
    chapter: &Chapter,
    args: &RenderArgs,
    render: impl Fn(&Scene, &(dyn Fn() + Sync)) -> (Image, Stats),
) -> ExitCode {
    let (scene, name) = match args.load_scene(chapter) {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let bar = progress_bar(scene.image.height, args.quiet);
    let start = Instant::now();
    let (image, stats) = render(&scene, &|| bar.inc(1));
    let seconds = start.elapsed();
    bar.finish_and_clear();
    let out = args.output_path(chapter);
    if let Err(e) = image.save_png(&out) {
        eprintln!("error: cannot write {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    report(
        chapter,
        &name,
        &out,
        &Rendered {
            image,
            stats,
            seconds,
        },
    );
    ExitCode::SUCCESS
}

/// Prints what was rendered, where, how big, how long and how many rays.
pub fn report(chapter: &Chapter, scene: &str, out: &std::path::Path, r: &Rendered) {
    println!(
        "chapter {} ({}): rendered {scene}\nwrote {} ({}×{} pixels) in {:.3} s\n{}",
        chapter.folder,
        chapter.title,
        out.display(),
        r.image.width,
        r.image.height,
        r.seconds.as_secs_f64(),
        r.stats
    );
}
