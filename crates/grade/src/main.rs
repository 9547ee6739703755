//! `cargo run -p grade -- CLASS`: the teacher grades a class of handouts.

use clap::Parser;
use std::process::ExitCode;

/// Grades a class of handouts against the reference: a CSV gradebook,
/// Gradescope results, JUnit XML and an HTML report.
#[derive(Parser, Debug)]
#[command(name = "grade", version)]
struct Cli {
    #[command(flatten)]
    args: grade::GradeArgs,
}

fn main() -> ExitCode {
    grade::main(&Cli::parse().args)
}
