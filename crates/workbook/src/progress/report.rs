//! The table of where a student is, and the advice of its last line.

use std::path::{Path, PathBuf};

use super::{TestOutput, lesson};
use crate::regions::Region;
use crate::workbench::chapters::ChapterEntry;

/// A chapter's outcome in the table.
#[derive(Debug, Clone)]
pub struct ChapterResult {
    pub chapter: &'static ChapterEntry,
    /// None if it was not run (a chapter before it fails).
    pub output: Option<TestOutput>,
    /// Its exercise regions: file, line, region.
    pub exercises: Vec<(PathBuf, usize, Region)>,
    /// Is `output` that of its last run (none of its files changed since)?
    pub reused: bool,
}

impl ChapterResult {
    fn open_exercises(&self) -> impl Iterator<Item = &(PathBuf, usize, Region)> {
        self.exercises.iter().filter(|(_, _, r)| r.is_open())
    }

    /// The exercise to write next (see [`lesson::next_exercise`]): the
    /// advice names it, and the row's first failure is a test of it.
    pub fn next_exercise(&self, root: &Path) -> Option<&(PathBuf, usize, Region)> {
        let open: Vec<_> = self.open_exercises().collect();
        let order = lesson::lesson_order(root, self.chapter);
        lesson::next_exercise(&open, &order, self.output.as_ref())
    }

    /// The row's first failure, in a few words, as the table shows it
    /// (empty for a chapter that passes, `not run` for one not run).
    pub fn first_failure(&self, root: &Path) -> String {
        match &self.output {
            None => "not run".to_owned(),
            Some(o) => first_failure(o, self.next_exercise(root).map(|e| &*e.2.id), root),
        }
    }

    /// Exercises written out of all: `1/2`, or `-` for a chapter without.
    pub fn exercises_done(&self) -> String {
        let total = self.exercises.len();
        let done = total - self.open_exercises().count();
        if total == 0 {
            "-".to_owned()
        } else {
            format!("{done}/{total}")
        }
    }
}

/// The failure a chapter's row and the advice both lead with: a compile
/// error; else the first failed test (in the chapter's order) whose own
/// message explains it; else the first picture that differs; else the
/// first failed test.
enum Lead<'a> {
    Compile(&'a str),
    Told {
        test: &'a str,
        message: &'a str,
    },
    Snapshot {
        name: &'a str,
        diff: Option<&'a str>,
    },
    Failed(&'a str),
    NoTests,
    Passed,
}

///
/// A test that ran into the `todo!` of the exercise `next` (the one the
/// advice names) leads before the others, so that the row and the advice
/// speak of the same exercise. Of the others, a test of one function leads
/// before one of a whole picture (a chapter's `pictures` module: "max_depth
/// = 2 follows exactly 2 bounces" says less than the test of the weight
/// that broke it).
fn lead<'a>(output: &'a TestOutput, next: Option<&str>) -> Lead<'a> {
    let told = |(test, _): &&(String, String)| !is_snapshot(test);
    let precise = |(test, _): &&(String, String)| !is_snapshot(test) && !of_pictures(test);
    let of_next =
        |(_, message): &&(String, String)| next.is_some_and(|id| lesson::names(message, id));
    let told = (output.panics.iter().filter(told).find(of_next))
        .or_else(|| output.panics.iter().find(precise))
        .or_else(|| output.panics.iter().find(told));
    match (&output.compile_error, told, output.snapshots.first()) {
        (Some(error), _, _) => Lead::Compile(error),
        (None, Some((test, message)), _) => Lead::Told { test, message },
        (None, None, Some((name, diff))) => Lead::Snapshot {
            name,
            diff: diff.as_deref(),
        },
        (None, None, None) => match output.failed_tests.first() {
            Some(test) => Lead::Failed(test),
            None if output.passed == 0 => Lead::NoTests,
            None => Lead::Passed,
        },
    }
}

/// Is `test` (`snapshot_bubble`, or with its module, `pictures::snapshot_flat`)
/// a snapshot test, whose message is a count of pixels?
fn is_snapshot(test: &str) -> bool {
    test.rsplit("::")
        .next()
        .unwrap_or(test)
        .starts_with("snapshot")
}

/// Is `test` one of a chapter's whole-picture tests (its `pictures` module)?
fn of_pictures(test: &str) -> bool {
    test.starts_with("pictures::")
}

/// The first thing that went wrong in a chapter's run, in a few words;
/// paths relative to the workspace `root`.
fn first_failure(output: &TestOutput, next: Option<&str>, root: &Path) -> String {
    let relative = |p: &str| {
        Path::new(p)
            .strip_prefix(root)
            .map_or(p.to_owned(), |r| r.display().to_string())
    };
    match lead(output, next) {
        Lead::Compile(error) => format!("does not compile: {error}"),
        Lead::Told { test, .. } | Lead::Failed(test) => format!("test {test}"),
        Lead::Snapshot {
            name,
            diff: Some(diff),
        } => format!("snapshot {name}: {}", relative(diff)),
        Lead::Snapshot { name, diff: None } => format!("snapshot {name}"),
        Lead::NoTests => "no tests ran".to_owned(),
        Lead::Passed => String::new(),
    }
}

/// The table's header line.
pub fn header() -> String {
    line([
        "",
        "chapter",
        "passed",
        "failed",
        "written",
        "first failure",
    ])
}

/// One line of the table, in fixed columns (so that rows printed one at a
/// time, as their chapters finish, line up): the marker, the chapter, the
/// counts right-aligned, the exercises, the first failure.
fn line([marker, chapter, passed, failed, exercises, failure]: [&str; 6]) -> String {
    let text =
        format!("{marker:<3}{chapter:<16}{passed:>6}  {failed:>6}  {exercises:<9}  {failure}");
    text.trim_end().to_owned()
}

/// The line of a chapter still waiting for its tests (or running them).
pub fn waiting_line(chapter: &ChapterEntry, running: bool) -> String {
    let what = if running { "testing…" } else { "waiting" };
    line(["", &chapter.folder, "", "", "", what])
}

/// The table's line for one chapter; `here` marks where the student is.
pub fn row_line(result: &ChapterResult, here: bool, root: &Path) -> String {
    let (passed, failed) = match &result.output {
        None => ("-".into(), "-".into()),
        Some(o) => (o.passed.to_string(), o.failed.to_string()),
    };
    let failure = result.first_failure(root);
    let failure = match (result.reused, failure.is_empty()) {
        (false, _) => failure,
        (true, true) => "unchanged since the last run".to_owned(),
        (true, false) => format!("{failure} (unchanged since the last run)"),
    };
    let marker = if here { "→" } else { "" };
    let exercises = result.exercises_done();
    line([
        marker,
        &result.chapter.folder,
        &passed,
        &failed,
        &exercises,
        &failure,
    ])
}

/// Where the student is: the first chapter run that fails.
pub fn here(results: &[ChapterResult]) -> Option<usize> {
    results
        .iter()
        .position(|r| r.output.as_ref().is_some_and(|o| !o.passed_all()))
}

/// The table and the advice, as text.
pub fn report(results: &[ChapterResult], root: &Path) -> String {
    let here = here(results);
    let mut lines = vec![header()];
    for (i, result) in results.iter().enumerate() {
        lines.push(row_line(result, Some(i) == here, root));
    }
    format!(
        "{}\n\n{}\n",
        lines.join("\n"),
        next_step(results, here, root)
    )
}

/// The advice of the last line.
pub fn next_step(results: &[ChapterResult], here: Option<usize>, root: &Path) -> String {
    let Some(i) = here else {
        return "next: every chapter passes: you have written a ray tracer. Try the \
                Extend and Explore exercises at the end of each chapter's README, render \
                a scene of your own (`cargo run --release -p ch07-termination -- my.toml`) \
                and read \"Where ray tracing goes next\" in chapters/07-termination/README.md."
            .to_owned();
    };
    let row = &results[i];
    let chapter = row.chapter;
    let readme = format!("chapters/{}/README.md", chapter.folder);
    let command = format!("cargo test -p {}", chapter.package());
    let output = row.output.as_ref().expect("a failing row was run");
    let next = row.next_exercise(root);
    if let Some(error) = &output.compile_error {
        return format!(
            "next: chapter {} does not compile ({error}); run `{command}` to see the whole message",
            chapter.number()
        );
    }
    // The exercise not written yet that the text asks for first (of those
    // whose todo! a test met, if any did).
    match next {
        Some((file, line, region)) => {
            // A test that fails other than at a todo! fails in code
            // already written: its answer is there too.
            let written_fails = (output.panics.iter())
                .any(|(_, message)| !message.starts_with("not yet implemented: "));
            let answers = match written_fails {
                true => answers_line(&row.exercises),
                false => String::new(),
            };
            format!(
                "next: chapter {}: exercise {} in {}:{line}: {}\n      \
                 read {readme}, write it, then run `{command}`{answers}",
                chapter.number(),
                region.id,
                file.display(),
                region.hint
            )
        }
        None => {
            let answers = answers_line(&row.exercises);
            let what = match lead(output, None) {
                Lead::Told { test, message } => {
                    return format!(
                        "next: chapter {}: the test {test} fails:\n      {message}\n      \
                         run `{command}` and compare with {readme}{answers}",
                        chapter.number()
                    );
                }
                Lead::Snapshot { name, .. } => format!("the snapshot {name} differs"),
                Lead::Failed(test) => format!("the test {test} fails"),
                _ => "no test ran".to_owned(),
            };
            format!(
                "next: chapter {}: {what}; run `{command}` and compare with {readme}{answers}",
                chapter.number()
            )
        }
    }
}

/// The line that says the answers of a chapter's written exercises are
/// there, now that they were tried (`workbook hint ID --level 4`); empty
/// if none is written.
fn answers_line(exercises: &[(PathBuf, usize, Region)]) -> String {
    let written: Vec<&str> = (exercises.iter())
        .filter(|(_, _, r)| !r.is_open())
        .map(|(_, _, r)| r.id.as_str())
        .collect();
    match written.as_slice() {
        [] => String::new(),
        [id] => {
            format!("\n      you have tried it: `workbook hint {id} --level 4` shows the answer")
        }
        ids => format!(
            "\n      you have tried them: `workbook hint ID --level 4` shows the answer \
             (ID: {})",
            ids.join(", ")
        ),
    }
}

#[cfg(test)]
mod tests;
