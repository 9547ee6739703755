//! Renders what the camera sees of an empty world: one ray per pixel.

use ch01_rays::workbench::cli::{RenderArgs, run_or_explain};
use ch01_rays::{CHAPTER, ray_tree, render_sky};
use clap::Parser;

/// Chapter 1: rays and a pinhole camera. Casts one ray per pixel, backwards
/// from the eye, and colours each pixel by the ray's direction (a sky above
/// the horizon, ground below), so you can see where your rays go.
#[derive(Parser)]
#[command(version)]
struct Args {
    #[command(flatten)]
    render: RenderArgs,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    run_or_explain(
        &CHAPTER,
        &args.render,
        |scene, on_row| render_sky(scene, on_row),
        ray_tree::explain,
    )
}
