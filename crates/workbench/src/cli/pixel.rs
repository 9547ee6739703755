//! `--pixel X,Y`: a pixel's ray tree instead of a picture.

use std::process::ExitCode;

use super::{Chapter, RenderArgs, planned};
use crate::ray_tree::{RayNode, RayTree, TracerInfo};
use ch00_toolkit::Scene;
use scene_files::SceneError;

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

/// Prints the ray tree of one pixel to stdout (text, or JSON with
/// `--json`); the effects line and any notes go to stderr, so that stdout
/// holds the tree alone.
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
    if args.json {
        println!("{}", tree.to_json());
    } else {
        print!("{}", tree.to_text());
    }
    ExitCode::SUCCESS
}
