//! Renders a scene with the complete tracer and explicit termination criteria.

use ch07_termination::toolkit::Scene;
use ch07_termination::workbench::cli::{RenderArgs, run_or_explain};
use ch07_termination::{CHAPTER, Termination, ray_tree, render_terminated};
use clap::Parser;

/// Chapter 7: termination criteria. A path of rays ends when a ray hits
/// nothing, after the maximum number of bounces, or when the product of the
/// weights along it falls below a threshold. The statistics printed at the
/// end count the rays of each kind and the paths each criterion ended.
#[derive(Parser)]
#[command(version)]
struct Args {
    #[command(flatten)]
    render: RenderArgs,

    /// Maximum number of bounces (instead of the scene's [trace] max_depth).
    #[arg(long, value_parser = clap::value_parser!(u32).range(0..=64))]
    max_depth: Option<u32>,

    /// End a path when its weight falls below this (instead of the scene's
    /// [trace] min_weight); 0 never ends a path early.
    #[arg(long, value_parser = weight)]
    min_weight: Option<f32>,
}

/// A weight in [0, 1].
fn weight(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(w) if (0.0..=1.0).contains(&w) => Ok(w),
        _ => Err(format!("expected a number from 0 to 1, found {text:?}")),
    }
}

impl Args {
    /// The scene's criteria, with the command line's overrides.
    fn termination(&self, scene: &Scene) -> Termination {
        let scene_criteria = Termination::of(scene);
        Termination {
            max_depth: self.max_depth.unwrap_or(scene_criteria.max_depth),
            min_weight: self.min_weight.unwrap_or(scene_criteria.min_weight),
        }
    }
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    run_or_explain(
        &CHAPTER,
        &args.render,
        |scene, on_row| render_terminated(scene, args.termination(scene), on_row),
        |scene, pixel| ray_tree::explain(scene, args.termination(scene), pixel),
    )
}
