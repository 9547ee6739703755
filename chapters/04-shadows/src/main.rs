//! Renders a scene with Lambert shading and shadow rays.

use ch04_shadows::workbench::cli::{RenderArgs, run_or_explain};
use ch04_shadows::{CHAPTER, ShadowStart, ray_tree, render_shadows};
use clap::Parser;

/// Chapter 4: shadow rays. Before a light adds to a point, a ray from the
/// point towards the light asks whether anything is in between.
#[derive(Parser)]
#[command(version)]
struct Args {
    #[command(flatten)]
    render: RenderArgs,

    /// Start shadow rays exactly at the hit point, without moving them off
    /// the surface: see the speckles of "shadow acne" this causes.
    #[arg(long)]
    no_offset: bool,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let origin = if args.no_offset {
        ShadowStart::HitPoint
    } else {
        ShadowStart::Offset
    };
    run_or_explain(
        &CHAPTER,
        &args.render,
        |scene, on_row| render_shadows(scene, origin, on_row),
        |scene, pixel| ray_tree::explain(scene, pixel, origin),
    )
}
