//! Renders a scene with the complete tracer and explicit termination criteria.

use ch07_termination::workbench::cli::{RenderArgs, run_or_explain};
use ch07_termination::{CHAPTER, Termination, ray_tree, render_terminated};
use clap::Parser;

/// Chapter 7: termination criteria. A path of rays ends when a ray hits
/// nothing, after the maximum number of bounces (--max-depth), or when the
/// product of the weights along it falls below a threshold (--min-weight).
/// The statistics printed at the end count the rays of each kind and the
/// paths each criterion ended.
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
        |scene, on_row| render_terminated(scene, Termination::of(scene), on_row),
        |scene, pixel| ray_tree::explain(scene, Termination::of(scene), pixel),
    )
}
