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
//! After an edit, the chapter edited (the one whose content changed last
//! since progress last ran, or, in watch mode, the one just saved) is tested
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
mod lesson;
mod order;
mod parse;
mod report;
mod run;
pub use run::read_all;
mod table;
pub mod watch;

use std::collections::{BTreeMap, VecDeque};
use std::ffi::OsStr;
use std::path::Path;
use std::process::ExitCode;
use std::sync::mpsc;

pub use parse::{TestOutput, parse};
pub use report::{ChapterResult, here, next_step, report};

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
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    progress_in(&current_workspace()?, &cargo, args, saved)
}

/// [`progress`] in the workspace at `root`, testing with the program `cargo`.
fn progress_in(
    root: &Path,
    cargo: &OsStr,
    args: &ProgressArgs,
    saved: Option<&Path>,
) -> Result<bool, String> {
    Ok(tested(root, cargo, args, saved, true)?.finish())
}

/// What `progress` finds, as a library call that prints nothing (the lab
/// shows it): each chapter's row, in order, the rows not run included.
/// `saved` is the file whose save started this run, if any: its chapter is
/// tested first.
pub fn results(
    root: &Path,
    args: &ProgressArgs,
    saved: Option<&Path>,
) -> Result<Vec<ChapterResult>, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    Ok(tested(root, &cargo, args, saved, false)?.results())
}

/// Tests the chapters, filling a table (printed as it fills if `printed`).
fn tested(
    root: &Path,
    cargo: &OsStr,
    args: &ProgressArgs,
    saved: Option<&Path>,
    printed: bool,
) -> Result<Table, String> {
    let steps: Vec<&'static ChapterEntry> =
        chapters::all().iter().filter(|c| is_a_step(c)).collect();
    if !root.join("target/workbook/results").exists() {
        eprintln!("{FIRST_RUN}");
    }
    let edited = match saved {
        Some(file) => edited::chapter_of(root, &steps, file),
        None => edited::last_run(root).and_then(|t| edited::last_changed(root, &steps, t)),
    };
    edited::stamp(root, &steps);
    let run = Run {
        args,
        cargo,
        root,
        steps: &steps,
    };
    let mut table = Table::new(&steps, root, printed);
    // The chapters before the first that changed: their last results.
    let inputs = cache::Inputs::scan(root);
    let mut to_test = Vec::new();
    for (i, chapter) in steps.iter().enumerate() {
        let last = (!args.fresh && to_test.is_empty())
            .then(|| inputs.unchanged_result(root, chapter))
            .flatten();
        match last {
            Some(output) => table.done(i, run.row(i, Some(output), true)?),
            None => to_test.push(i),
        }
    }
    let edited = edited.and_then(|e| steps.iter().position(|c| c.folder == e.folder));
    run.test(&mut table, &run_order(&to_test, edited), edited)?;
    Ok(table)
}

/// What progress says as it starts in a workspace where it never ran: the
/// one long wait, and why. Measured on a quiet 2-core machine (issue 39):
/// about 40 s in a handout that got its compiled dependencies from the
/// clone it was written from, about 80 s in one that did not.
pub const FIRST_RUN: &str = "progress: first run here: cargo builds chapter 1's tests and the \
crates they use, once (a minute or so on a 2-core machine, a few where the handout has no \
compiled dependencies yet; every later run answers in seconds)...";

/// How many chapters' `cargo test` may run at once: one builds (cargo
/// builds one at a time) while the tests of another run.
const AT_ONCE: usize = 2;

/// What a run of progress tests with.
struct Run<'a> {
    args: &'a ProgressArgs,
    /// The program to run for `cargo test`.
    cargo: &'a OsStr,
    root: &'a Path,
    /// The chapters, in the table's order.
    steps: &'a [&'static ChapterEntry],
}

impl Run<'_> {
    /// Tests the chapters `order` (rows of the table) in that order, the
    /// `edited` one alone; each row is shown when its chapter and those
    /// started before it are done, and its result kept for the next run.
    fn test(
        &self,
        table: &mut Table,
        order: &[usize],
        edited: Option<usize>,
    ) -> Result<(), String> {
        let (done, finished) = mpsc::channel();
        let mut queue: VecDeque<usize> = order.iter().copied().collect();
        // Started and not shown yet, in the order they started; those ended.
        let mut started: VecDeque<usize> = VecDeque::new();
        let mut ended: BTreeMap<usize, TestOutput> = BTreeMap::new();
        loop {
            while let Some(&i) = queue.front() {
                let running = started.len() - ended.len();
                if !started.is_empty() && !self.early(&started, running, edited) {
                    break;
                }
                queue.pop_front();
                if table.fails_before(i) && !self.args.all {
                    table.done(i, self.row(i, None, false)?);
                    continue;
                }
                table.running(i);
                run::start(self.cargo, self.root, self.steps[i], i, done.clone())?;
                started.push_back(i);
            }
            if started.is_empty() {
                return Ok(());
            }
            let end = (finished.recv()).map_err(|_| "a chapter's tests were lost".to_owned())?;
            let output = end.output?;
            cache::save(self.root, self.steps[end.row], end.started, &output);
            ended.insert(end.row, output);
            // Shown in the order they started.
            while let Some(&i) = started.front() {
                let Some(output) = ended.remove(&i) else {
                    break;
                };
                started.pop_front();
                // Started early, after a chapter that has now failed: not shown.
                let output = (self.args.all || !table.fails_before(i)).then_some(output);
                table.done(i, self.row(i, output, false)?);
            }
        }
    }

    /// May the next chapter start while the chapters `started` (of which
    /// `running` still run) are not shown yet? Yes if fewer than
    /// [`AT_ONCE`] run, none of them is the `edited` one (its verdict comes
    /// first, alone), and they passed last time (so that it will likely be
    /// run) or every chapter is to be run.
    fn early(&self, started: &VecDeque<usize>, running: usize, edited: Option<usize>) -> bool {
        let passed = |i: &usize| cache::passed_last_time(self.root, self.steps[*i]);
        running < AT_ONCE
            && !started.contains(&edited.unwrap_or(usize::MAX))
            && (self.args.all || started.iter().all(passed))
    }

    /// Row `i`: its `output` (None if not run, `reused` if that of its
    /// last run), and its exercises, counted now so that exercises written
    /// during the run count.
    fn row(
        &self,
        i: usize,
        output: Option<TestOutput>,
        reused: bool,
    ) -> Result<ChapterResult, String> {
        let chapter = self.steps[i];
        let exercises = workspace_regions(self.root)?
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
mod tests;
