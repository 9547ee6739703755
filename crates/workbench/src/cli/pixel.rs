//! `--pixel X,Y`: a pixel's ray tree instead of a picture, short or in
//! full, and its picture (`--svg`).

use std::path::PathBuf;
use std::process::ExitCode;

use super::{Chapter, RenderArgs, planned};
use crate::ray_tree::{Fold, RayNode, RayTree, TracerInfo, to_svg};
use ch00_toolkit::Scene;
use ch00_toolkit::image::write_atomically;
use scene_files::SceneError;

/// How `--pixel` shows the tree: short or full, and as a picture.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct TreeView {
    /// With --pixel: print every ray and every detail. By default the text
    /// tree is short: the primary ray in full, the secondary rays in brief,
    /// and the rays that matter little to the pixel folded, each group into
    /// one line that counts them and says what they add to the pixel's
    /// colour (see --fold-depth, --fold-weight). --json always writes
    /// every ray.
    #[arg(long, requires = "pixel", conflicts_with_all = ["fold_depth", "fold_weight"])]
    pub full: bool,

    /// With --pixel: fold the rays deeper than N bounces (default 3). This
    /// changes only what the text tree and the --svg picture show, never
    /// what is traced (--max-depth ends paths).
    #[arg(long, value_name = "N", requires = "pixel")]
    pub fold_depth: Option<u32>,

    /// With --pixel: fold the rays whose path weight is below W in every
    /// channel (default 0.01, 1% of the pixel's light; 0 folds none). This
    /// changes only what the text tree and the --svg picture show, never
    /// what is traced (--min-weight ends paths, from chapter 7 on).
    #[arg(long, value_name = "W", requires = "pixel", value_parser = super::weight)]
    pub fold_weight: Option<f32>,

    /// With --pixel: also write a picture of the pixel's rays to FILE.svg:
    /// the rays seen from the side, in the plane of the primary ray and the
    /// camera's up vector, over the objects they hit, each labelled with
    /// its kind and path weight; the folded rays thin and grey.
    #[arg(long, value_name = "FILE.svg", requires = "pixel")]
    pub svg: Option<PathBuf>,
}

impl TreeView {
    /// The folds the text and the picture show: none with --full.
    pub fn fold(&self) -> Fold {
        if self.full {
            return Fold::NONE;
        }
        Fold {
            depth: self.fold_depth.unwrap_or(Fold::DEFAULT.depth),
            weight: self.fold_weight.unwrap_or(Fold::DEFAULT.weight),
        }
    }
}

/// A pixel of the picture, counted from (0, 0) at the top-left corner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pixel {
    pub x: u32,
    pub y: u32,
}

/// Parses `--pixel X,Y`.
pub(super) fn pixel(text: &str) -> Result<Pixel, String> {
    let parsed = text
        .split_once(',')
        .and_then(|(x, y)| Some((x.trim().parse().ok()?, y.trim().parse().ok()?)));
    match parsed {
        Some((x, y)) => Ok(Pixel { x, y }),
        None => Err(format!(
            "expected two whole numbers X,Y such as 160,120 (from 0,0 at the top-left corner), found {text:?}"
        )),
    }
}

/// Prints the ray tree of one pixel to stdout (text, short or full, or
/// JSON with `--json`) and writes its picture with `--svg`; the effects
/// line and any notes go to stderr, so that stdout holds the tree alone.
pub(super) fn explain_pixel(
    chapter: &Chapter,
    args: &RenderArgs,
    loaded: Result<(Scene, String), SceneError>,
    pixel: Pixel,
    explain: impl Fn(&Scene, Pixel) -> (TracerInfo, RayNode),
) -> ExitCode {
    let Some((plan, scene, name)) = planned(chapter, args, loaded) else {
        return ExitCode::FAILURE;
    };
    eprintln!("{plan}");
    let (width, height) = (scene.image.width, scene.image.height);
    if pixel.x >= width || pixel.y >= height {
        eprintln!(
            "error: pixel ({}, {}) is outside the image, which is {width}×{height} pixels: x goes from 0 to {} and y from 0 to {}",
            pixel.x,
            pixel.y,
            width - 1,
            height - 1
        );
        return ExitCode::FAILURE;
    }
    let (tracer, primary) = explain(&scene, pixel);
    let tree = RayTree {
        chapter: chapter.entry().folder.clone(),
        scene: name,
        pixel: [pixel.x, pixel.y],
        image: [width, height],
        samples: scene.image.samples,
        tracer,
        primary,
    };
    let view = &args.view;
    if args.json {
        println!("{}", tree.to_json());
    } else if view.full {
        print!("{}", tree.to_text());
    } else {
        print!("{}", tree.to_short_text(view.fold()));
    }
    let Some(path) = &view.svg else {
        return ExitCode::SUCCESS;
    };
    let svg = to_svg(&tree, &scene, view.fold());
    if let Err(e) = write_atomically(path, svg.as_bytes()) {
        eprintln!("error: cannot write {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    eprintln!("wrote {}", path.display());
    ExitCode::SUCCESS
}
