//! `raybook render`: as every chapter binary renders (the workbench's
//! `run_or_explain`: load, plan the effects, render with a progress bar,
//! report), but the picture is written in the format that `-o` names, and
//! only where it may go ([`Output`]). Both are checked before the scene is
//! loaded, so that a name that cannot be written costs no rendering.
//!
//! The workbench's own loop writes PNG whatever the name; `--pixel`, which
//! writes no picture, is left to it.

use std::process::ExitCode;
use std::time::Instant;

use raybook::CHAPTER;
use raybook::toolkit::Scene;
use raybook::workbench::cli::end_quietly_when_output_closes;
use raybook::workbench::cli::{EffectPlan, RenderArgs, Rendered, render_with_bar, report};

use crate::output::Output;

/// Renders the scene of `args` with the complete tracer and writes the
/// picture; says what went wrong otherwise.
pub fn run(args: &RenderArgs) -> ExitCode {
    end_quietly_when_output_closes();
    match render_and_write(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

/// The steps of [`run`]; an error is the message to print.
fn render_and_write(args: &RenderArgs) -> Result<(), String> {
    let output = Output::new(&args.output_path(&CHAPTER))?;
    args.check_criteria(&CHAPTER)?;
    let (plan, scene, name) = planned(args)?;
    println!("{plan}");
    let start = Instant::now();
    let (image, stats) = rendered(args, &scene)?;
    let seconds = start.elapsed();
    output.write(&image)?;
    args.write_linear(&image)?;
    let rendered = Rendered {
        image,
        stats,
        seconds,
    };
    report(&CHAPTER, &name, &output.path, &rendered);
    Ok(())
}

/// The scene with its effect plan applied, its plan and its name; prints a
/// note for each effect left to a later chapter (refused with `--strict`).
fn planned(args: &RenderArgs) -> Result<(EffectPlan, Scene, String), String> {
    let (scene, name) = args.load_scene(&CHAPTER).map_err(|e| e.to_string())?;
    let plan = EffectPlan::new(&CHAPTER, &scene, &args.without);
    for note in plan.notes() {
        if args.strict {
            return Err(format!("{note}; --strict refuses to render without it"));
        }
        eprintln!("note: {note}; this chapter renders without it");
    }
    let scene = plan.apply(&CHAPTER, scene);
    Ok((plan, scene, name))
}

/// The picture and its statistics, on `--threads` threads, with the
/// chapters' progress bar.
fn rendered(
    args: &RenderArgs,
    scene: &Scene,
) -> Result<(raybook::toolkit::Image, raybook::toolkit::Stats), String> {
    render_with_bar(args, scene, |on_row| raybook::render(scene, on_row))
}
