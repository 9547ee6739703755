//! Renders the closest hit of every pixel's ray, flat, as normals or as depth.

use ch02_hits::workbench::cli::{RenderArgs, run_or_explain};
use ch02_hits::{CHAPTER, Method, View, ray_tree, render_hits};
use clap::Parser;

/// Chapter 2: ray-plane, ray-sphere and ray-triangle intersection. Finds the
/// closest hit of each pixel's ray and shows it without any light: in its
/// material's colour, as its normal, or as its distance.
#[derive(Parser)]
#[command(version)]
struct Args {
    #[command(flatten)]
    render: RenderArgs,

    /// What to show of each hit.
    #[arg(long, value_enum, default_value_t)]
    view: View,

    /// Which tests find the hits: your lecture methods, or the robust forms
    /// that the later chapters use (the stable quadratic, the watertight
    /// triangle test). Compare them on scenes/far-sphere.toml.
    #[arg(long, value_enum, default_value_t)]
    method: Method,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    run_or_explain(
        &CHAPTER,
        &args.render,
        |scene, on_row| render_hits(scene, args.view, args.method, on_row),
        |scene, pixel| ray_tree::explain(scene, args.view, args.method, pixel),
    )
}
