//! The workbook's tools: `cargo run -p workbook -- progress`, and the rest.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// The raybook workbook's tools. They build once, on the toolkit alone, and
/// never again when you edit a chapter.
#[derive(Parser)]
#[command(version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Runs each chapter's tests in order and shows where you are: passed,
    /// failed, the first failing snapshot, and what to do next.
    Progress(workbook::progress::ProgressArgs),
    /// Helps with an exercise, never with its code: a nudge (--level 1),
    /// the section of the text that derives it (2), the tests that check
    /// it (3).
    Hint(workbook::hint::HintArgs),
    /// Checks a picture made by your own tracer, in any language, against a
    /// chapter's reference picture.
    Verify(workbook::verify::VerifyArgs),
    /// Writes a copy of the workbook for a student, with the exercises'
    /// solutions replaced by todo!("hint"); or runs the maintainers' checks.
    Handout(workbook::handout::HandoutArgs),
}

fn main() -> ExitCode {
    workbook::workbench::cli::end_quietly_when_output_closes();
    match Cli::parse().command {
        Command::Progress(args) => workbook::progress::main(&args),
        Command::Hint(args) => workbook::hint::main(&args),
        Command::Verify(args) => workbook::verify::main(&args),
        Command::Handout(args) => workbook::handout::main(&args),
    }
}
