//! Renders a scene with mirrors, highlights, shadows and Lambert shading.

use ch05_reflection::workbench::cli::{RenderArgs, run_or_explain};
use ch05_reflection::{CHAPTER, ray_tree, render_mirrors};
use clap::Parser;

/// Chapter 5: specular reflection. At a mirror, the reflected ray (the
/// mirror law: the angle out equals the angle in) is traced in turn and
/// its colour, weighted by the material's reflectance, is added; shiny
/// materials get highlights. The recursion stops after the scene's [trace]
/// max_depth bounces.
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
        |scene, on_row| render_mirrors(scene, on_row),
        ray_tree::explain,
    )
}
