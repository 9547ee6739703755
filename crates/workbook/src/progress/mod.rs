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
//! finishes. A chapter none of whose inputs changed since its last run is
//! not tested again: its last result is shown (see `cache`). While one
//! chapter's tests run, the next one's build goes on, if that chapter
//! passed last time (so that it is likely to be needed).
//!
//! It works the same in the reference workspace (every chapter passes) and in
//! a handout from `workbook handout`.

mod cache;
mod edited;
mod order;
mod parse;
mod report;
mod run;
mod table;
mod watch;

use std::collections::VecDeque;
use std::path::Path;
use std::process::ExitCode;

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

    /// Test every chapter again, also those none of whose files changed
    /// since their last run (whose last result is shown otherwise).
    #[arg(long)]
    pub fresh: bool,
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
    // The chapters before the first that changed: their last results.
    let inputs = cache::Inputs::scan(&root);
    let mut to_test = Vec::new();
    for (i, chapter) in steps.iter().enumerate() {
        let last = (!args.fresh && to_test.is_empty())
            .then(|| inputs.unchanged_result(&root, chapter))
            .flatten();
        match last {
            Some(output) => table.done(i, chapter_result(&root, chapter, Some(output), true)?),
            None => to_test.push(i),
        }
    }
    let edited = edited.and_then(|e| steps.iter().position(|c| c.folder == e.folder));
    let order = run_order(&to_test, edited);
    test_chapters(args, &root, &steps, &mut table, &order, edited)?;
    Ok(table.finish())
}

/// Tests the chapters `order` (indices in `steps` and the table) in that
/// order, the `edited` one alone; each row is shown when its chapter is
/// done, and its result kept for the next run.
fn test_chapters(
    args: &ProgressArgs,
    root: &Path,
    steps: &[&'static ChapterEntry],
    table: &mut Table,
    order: &[usize],
    edited: Option<usize>,
) -> Result<(), String> {
    let mut running: VecDeque<(usize, run::Started)> = VecDeque::new();
    let mut next = order.iter().copied().peekable();
    loop {
        // Start the next chapter: at once if nothing runs, early if the
        // ones running passed last time (so it will likely be run).
        while let Some(&i) = next.peek() {
            let alone = running.front().is_some_and(|(r, _)| Some(*r) == edited);
            let likely = (running.iter()).all(|(r, _)| cache::passed_last_time(root, steps[*r]));
            if !running.is_empty() && (running.len() >= 2 || alone || !(likely || args.all)) {
                break;
            }
            next.next();
            if table.fails_before(i) && !args.all {
                table.done(i, chapter_result(root, steps[i], None, false)?);
                continue;
            }
            table.running(i);
            running.push_back((i, run::start(root, steps[i])?));
        }
        let Some((i, started)) = running.pop_front() else {
            return Ok(());
        };
        let at = started.at;
        let output = started.finish(root)?;
        cache::save(root, steps[i], at, &output);
        // Started early, after a chapter that has now failed: not shown.
        let output = (args.all || !table.fails_before(i)).then_some(output);
        table.done(i, chapter_result(root, steps[i], output, false)?);
    }
}

/// A chapter's row: its `output` (None if not run, `reused` if that of
/// its last run), and its exercises, counted now so that exercises written
/// during the run count.
fn chapter_result(
    root: &Path,
    chapter: &'static ChapterEntry,
    output: Option<TestOutput>,
    reused: bool,
) -> Result<ChapterResult, String> {
    let exercises = workspace_regions(root)?
        .into_iter()
        .filter(|(file, _, _)| file.starts_with(chapter.path()))
        .collect();
    Ok(ChapterResult {
        chapter,
        output,
        exercises,
        reused,
    })
}

/// The order to test the chapters `to_test` (indices in the table, in
/// order) in: the `edited` one first, if it is to be tested, then the
/// others in order.
fn run_order(to_test: &[usize], edited: Option<usize>) -> Vec<usize> {
    let first = edited.filter(|e| to_test.contains(e));
    (first.into_iter())
        .chain(to_test.iter().copied().filter(|i| Some(*i) != first))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_edited_chapter_is_tested_first_then_the_others_in_order() {
        let all: Vec<usize> = (0..8).collect();
        assert_eq!(run_order(&all, Some(2))[..4], [2, 0, 1, 3]);
        assert_eq!(run_order(&all, None), all);
        // Chapters 1 and 2 unchanged: shown, not tested.
        assert_eq!(run_order(&all[2..], Some(4)), [4, 2, 3, 5, 6, 7]);
        assert_eq!(run_order(&all[5..], Some(2)), [5, 6, 7]);
    }
}
