//! Renders a scene with Lambert shading: ambient, point and spot lights.

use ch03_lambert::workbench::cli::{RenderArgs, run_or_explain};
use ch03_lambert::{CHAPTER, ray_tree, render_lambert};
use clap::Parser;

/// Chapter 3: Lambert shading. Each hit is lit by every light as if nothing
/// stood in between: ambient light everywhere, point lights falling off with
/// 1/r², spot lights within their cone; each by Lambert's cosine law.
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
        |scene, on_row| render_lambert(scene, on_row),
        ray_tree::explain,
    )
}
