//! Renders a scene with the complete tracer, against a BVH.

use std::time::Instant;

use ch08_bvh::toolkit::Scene;
use ch08_bvh::workbench::cli::{RenderArgs, run_or_explain};
use ch08_bvh::{Bvh, CHAPTER, Termination, Tracer, ray_tree, render_whitted};
use clap::Parser;

/// Chapter 8 (bonus): a bounding volume hierarchy. The tracer is chapter
/// 7's; the rays are traced against a tree of boxes built with the surface
/// area heuristic, so a ray tests a few dozen boxes and primitives instead
/// of every object. Prints the time the tree took to build.
#[derive(Parser)]
#[command(version)]
struct Args {
    #[command(flatten)]
    render: RenderArgs,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let render = |scene: &Scene, on_row: &(dyn Fn() + Sync)| {
        let start = Instant::now();
        let bvh = Bvh::build(&scene.objects);
        println!(
            "{} built in {:.3} s",
            bvh.summary(),
            start.elapsed().as_secs_f64()
        );
        let termination = Termination::of(scene);
        render_whitted(&Tracer { termination }, scene, &bvh, on_row)
    };
    run_or_explain(&CHAPTER, &args.render, render, |scene, pixel| {
        ray_tree::explain(scene, Termination::of(scene), pixel)
    })
}
