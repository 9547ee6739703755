//! The raybook command line.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use raybook::toolkit::cli::{RenderArgs, run};
use raybook::{CHAPTER, render};

/// raybook: a step-by-step ray tracer. Without a command, renders the
/// showcase scene with the complete tracer and writes raybook.png.
///
/// The chapters live in chapters/NN-name; run one with
/// `cargo run --release -p chNN-name -- --help`.
#[derive(Parser)]
#[command(version)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Renders a scene file (TOML) with the complete tracer.
    Render(RenderArgs),
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Some(Command::Render(args)) => run(&CHAPTER, &args, |scene, on_row| render(scene, on_row)),
        None => {
            let args = RenderArgs {
                output: Some("raybook.png".into()),
                ..RenderArgs::default()
            };
            run(&CHAPTER, &args, |scene, on_row| render(scene, on_row))
        }
    }
}
