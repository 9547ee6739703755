//! The raybook command line.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use raybook::toolkit::Scene;
use raybook::workbench::cli::{Pixel, RenderArgs, run_or_explain};
use raybook::workbench::ray_tree::{RayNode, TracerInfo};
use raybook::{CHAPTER, render};

/// raybook: a step-by-step ray tracer. Without a command, renders the
/// showcase scene with the complete tracer and writes raybook.png.
///
/// The chapters live in chapters/NN-name; run one with
/// `cargo run --release -p chNN-name -- --help`. The student's tools
/// (progress, verify, handout) are the workbook's:
/// `cargo run -p workbook -- --help`.
#[derive(Parser)]
#[command(version)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Renders a scene file (TOML, or NFF if it ends in .nff) with the
    /// complete tracer.
    #[command(mut_arg("output", |arg| arg.value_name("OUT.png").help(OUTPUT_HELP)))]
    Render(RenderArgs),
    /// Times the SPD scenes, against POV-Ray where it is installed (with
    /// --primary: primary rays per thread, against Embree).
    Bench(measure::bench::BenchArgs),
    /// Measures what accuracy costs and buys: depth, threshold, samples per
    /// pixel and effects against one reference, each error with its
    /// standard error, ranked by rays traced (tables, a CSV and plots).
    Accuracy(measure::accuracy::AccuracyArgs),
}

/// `raybook render -o`: what the chapter binaries' `-o` says, and the
/// formats that `render.rs` writes besides PNG.
const OUTPUT_HELP: &str = "Where to write the picture, in the format its extension names: \
    .png, .ppm (or .pnm), .bmp or .tga. Only a regular file is written over, replaced whole; \
    a directory, a pipe or a device (even /dev/null) is refused. Default: <scene name>.png \
    for a scene file, <chapter>.png for the default scene";

fn main() -> ExitCode {
    raybook::workbench::cli::end_quietly_when_output_closes();
    match Cli::parse().command {
        Some(Command::Render(args)) => render_or_explain(&args),
        Some(Command::Bench(args)) => measure::bench::run(&args),
        Some(Command::Accuracy(args)) => measure::accuracy::main(&args),
        None => {
            let args = RenderArgs {
                output: Some("raybook.png".into()),
                ..RenderArgs::default()
            };
            render_or_explain(&args)
        }
    }
}

/// Renders with the complete tracer and writes the picture in the format
/// that `-o` names (`render.rs`), or with `--pixel X,Y` prints that pixel's
/// ray tree as chapter 8 traces it (the complete tracer's rays).
fn render_or_explain(args: &RenderArgs) -> ExitCode {
    if args.pixel.is_none() {
        return measure::render::run(args);
    }
    run_or_explain(
        &CHAPTER,
        args,
        |scene, on_row| render(scene, on_row),
        explain,
    )
}

fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let termination = raybook::tracer::Termination::of(scene);
    ch08_bvh::ray_tree::explain(scene, termination, pixel)
}
