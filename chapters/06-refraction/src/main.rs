//! Renders a scene with glass: refraction, total internal reflection, Fresnel.

use ch06_refraction::workbench::cli::{RenderArgs, run_or_explain};
use ch06_refraction::{CHAPTER, ray_tree, render_glass};
use clap::Parser;

/// Chapter 6: refraction. At a transparent material a second ray continues
/// through the surface, bent by Snell's law n₁ sin θ₁ = n₂ sin θ₂; where no
/// such ray exists (total internal reflection) its light goes to the mirror
/// ray instead. Materials with fresnel = true split the light by Schlick's
/// approximation.
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
        |scene, on_row| render_glass(scene, on_row),
        ray_tree::explain,
    )
}
