//! `workbook progress`: where a student is in the workbook.
//!
//! Runs each chapter's tests in order, from chapter 1, with `cargo test -p
//! chNN-name`: like the command it stands for, that stops at the chapter's
//! first failing test binary, so progress is no slower than it. It reads
//! what libtest prints and shows a table: the chapter, how many tests pass
//! and fail, its exercises written so far, and its first failure (a
//! snapshot's diff picture if a picture differs). The first chapter that
//! fails is where you are; by default the chapters after it are not run
//! (they build on it, so they would fail too), `--all` runs them anyway.
//! The last line says what to do next.
//!
//! After an edit, the chapter edited (the first whose files changed since
//! progress last ran, or, in watch mode, the one just saved) is tested
//! first, so that its verdict comes about as fast as `cargo test -p` of it
//! alone; the others follow, in order, and each row is shown as its chapter
//! finishes.
//!
//! It works the same in the reference workspace (every chapter passes) and in
//! a handout from `workbook handout`.

mod edited;
mod order;
mod parse;
mod report;
mod table;
mod watch;

use std::path::Path;
use std::process::{Command, ExitCode};

pub use parse::{TestOutput, parse};
pub use report::{ChapterResult, report};

use crate::workbench::chapters::{self, ChapterEntry};
use crate::workspace::{current_workspace, workspace_regions};
use table::Table;

/// `workbook progress`: runs each chapter's tests in order and shows where you are.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ProgressArgs {
    /// Run every chapter, not only those up to the first that fails.
    #[arg(long)]
    pub all: bool,

    /// Keep running: clear the screen and show the table again on every
    /// save of a .rs or .toml file under chapters/. Ctrl-C stops.
    #[arg(long)]
    pub watch: bool,
}

/// Runs the tests of one chapter with cargo, from the workspace root, and
/// reads their output.
pub fn run_chapter(root: &Path, chapter: &ChapterEntry) -> Result<TestOutput, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .args(["test", "-p", &chapter.package(), "--color", "never"])
        .current_dir(root)
        .output()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let mut parsed = parse(&text);
    if !out.status.success() && parsed.failed == 0 && parsed.compile_error.is_none() {
        // cargo failed before any test ran, and said why on its last line.
        let last = text.lines().rev().find(|l| l.starts_with("error"));
        parsed.compile_error = Some(last.unwrap_or("cargo test failed").to_owned());
    }
    let order = order::test_order(&root.join(chapter.path()).join("tests"));
    order::in_chapter_order(&mut parsed, &order);
    Ok(parsed)
}

/// Runs `workbook progress`.
pub fn main(args: &ProgressArgs) -> ExitCode {
    let result = if args.watch {
        current_workspace()
            .and_then(|root| watch::watch(&root, |saved| progress(args, saved)).map(|()| true))
    } else {
        progress(args, None)
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Is this chapter a step of the student's chain? The toolkit (chapter 0)
/// has nothing to write and its tests take a second of every run (their
/// doctests are compiled each time); a companion (chapter 4's forward
/// tracer) is an aside, not a step.
fn is_a_step(chapter: &ChapterEntry) -> bool {
    chapter.number() > 0 && !chapter.companion
}

/// Prints the table, row by row as the chapters finish; true if every
/// chapter run passed. `saved` is the file whose save started this run
/// (watch mode).
fn progress(args: &ProgressArgs, saved: Option<&Path>) -> Result<bool, String> {
    let root = current_workspace()?;
    let steps: Vec<&'static ChapterEntry> =
        chapters::all().iter().filter(|c| is_a_step(c)).collect();
    let edited = match saved {
        Some(file) => edited::chapter_of(&root, &steps, file),
        None => edited::last_run(&root).and_then(|t| edited::first_changed(&root, &steps, t)),
    };
    edited::stamp(&root);
    let mut table = Table::new(&steps, &root);
    for i in run_order(&steps, edited) {
        let chapter = steps[i];
        let output = if table.fails_before(i) && !args.all {
            None
        } else {
            table.running(i);
            Some(run_chapter(&root, chapter)?)
        };
        // Counted now, so that exercises written during the run count.
        let exercises = workspace_regions(&root)?
            .into_iter()
            .filter(|(file, _, _)| file.starts_with(chapter.path()))
            .collect();
        let result = ChapterResult {
            chapter,
            output,
            exercises,
        };
        table.done(i, result);
    }
    Ok(table.finish())
}

/// The order to test `steps` in: the `edited` one first, then the others
/// in the chapters' order.
fn run_order(steps: &[&ChapterEntry], edited: Option<&ChapterEntry>) -> Vec<usize> {
    let first = edited.and_then(|e| steps.iter().position(|c| c.folder == e.folder));
    first
        .into_iter()
        .chain((0..steps.len()).filter(|i| Some(*i) != first))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_edited_chapter_is_tested_first_then_the_others_in_order() {
        let steps: Vec<_> = chapters::all().iter().filter(|c| is_a_step(c)).collect();
        let third = steps[2];
        assert_eq!(run_order(&steps, Some(third))[..4], [2, 0, 1, 3]);
        assert_eq!(
            run_order(&steps, None),
            (0..steps.len()).collect::<Vec<_>>()
        );
    }
}
