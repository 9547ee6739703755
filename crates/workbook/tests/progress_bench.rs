//! The loop's benchmark (issue 28): in a handout where every chapter
//! passes, a one-line edit in a chapter, then `workbook progress` as the
//! student runs it, against `cargo test -p` of the chapters it re-tests.
//! A measurement, not a check: it asserts nothing about the time and runs
//! only when asked:
//!
//! ```text
//! RAYBOOK_PROGRESS_BENCH=1 cargo test -p workbook --test progress_bench -- --nocapture
//! ```
//!
//! `RAYBOOK_BENCH_EDITS` names the chapters edited (default
//! `01-rays,06-refraction`), `RAYBOOK_BENCH_ROUNDS` the rounds of each
//! (default 3; medians are shown), and `RAYBOOK_BENCH_HANDOUT` a handout to
//! reuse (made with `handout --solved-through 8` if it does not exist).
//!
//! Each round times, each from a build of every chapter and an edit of its
//! own:
//! * progress: when the edited chapter's row comes, and the whole table;
//! * `cargo test -p` of the edited chapter alone;
//! * `cargo test -p` of each chapter progress re-tested, one after the
//!   other after one edit (a student testing them in turn);
//! * the same, each after an edit of its own (each pays the rebuild of the
//!   chapters between the edited one and it), as the issue's 21.1 s was.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The chapters' folders and packages, in the table's order.
const CHAPTERS: [(&str, &str); 8] = [
    ("01-rays", "ch01-rays"),
    ("02-hits", "ch02-hits"),
    ("03-lambert", "ch03-lambert"),
    ("04-shadows", "ch04-shadows"),
    ("05-reflection", "ch05-reflection"),
    ("06-refraction", "ch06-refraction"),
    ("07-termination", "ch07-termination"),
    ("08-bvh", "ch08-bvh"),
];

#[test]
fn an_edit_then_progress_against_cargo_test() {
    if std::env::var_os("RAYBOOK_PROGRESS_BENCH").is_none() {
        eprintln!("progress_bench: a benchmark of minutes; set RAYBOOK_PROGRESS_BENCH=1 to run it");
        return;
    }
    let handout = prepared_handout();
    let edits =
        std::env::var("RAYBOOK_BENCH_EDITS").unwrap_or_else(|_| "01-rays,06-refraction".into());
    let rounds: usize = std::env::var("RAYBOOK_BENCH_ROUNDS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(3);
    let mut lines = vec![format!(
        "{:<15} {:>9} {:>9} {:>6} {:>9} {:>9} {:>6} {:>9} {:>6}  re-tested",
        "edited", "its row", "test -p", "ratio", "table", "Σ chain", "ratio", "Σ each", "ratio"
    )];
    for folder in edits.split(',') {
        let mut edit = Edit::new(&handout, folder);
        let mut samples = Vec::new();
        for _ in 0..rounds {
            samples.push(one_round(&handout, &mut edit));
        }
        edit.restore();
        lines.push(summary(folder, &samples));
    }
    eprintln!(
        "\nprogress after a one-line edit, medians of {rounds} rounds ({} cores), in {}:\n{}",
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        handout.display(),
        lines.join("\n")
    );
}

/// One round's times.
struct Sample {
    row: Duration,
    table: Duration,
    alone: Duration,
    chain: Duration,
    each: Duration,
    retested: Vec<String>,
}

fn one_round(handout: &Path, edit: &mut Edit) -> Sample {
    settle(handout);
    edit.once();
    let (row, table, retested) = progress(handout, edit.folder);
    settle(handout);
    edit.once();
    let alone = cargo_test(handout, package(edit.folder));
    settle(handout);
    edit.once();
    let chain = (retested.iter())
        .map(|f| cargo_test(handout, package(f)))
        .sum();
    let each = (retested.iter())
        .map(|f| {
            settle(handout);
            edit.once();
            cargo_test(handout, package(f))
        })
        .sum();
    Sample {
        row,
        table,
        alone,
        chain,
        each,
        retested,
    }
}

/// Builds every chapter's tests, untimed, so that each timed command
/// starts from the same state: everything built, then one edit. (Without
/// it, progress after the "each" runs, which leave the other chapters'
/// binaries built against older code, took 6.1 s where it took 4.1–5.0 s
/// after a run of its own.)
fn settle(handout: &Path) {
    for (_, package) in CHAPTERS {
        let status = student_cargo(handout)
            .args(["test", "-q", "--no-run", "-p", package])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .unwrap();
        assert!(
            status.success(),
            "cargo test --no-run -p {package} should build"
        );
    }
}

fn summary(folder: &str, samples: &[Sample]) -> String {
    let median = |f: fn(&Sample) -> Duration| {
        let mut all: Vec<f64> = samples.iter().map(|s| f(s).as_secs_f64()).collect();
        all.sort_by(f64::total_cmp);
        all[all.len() / 2]
    };
    let (row, alone) = (median(|s| s.row), median(|s| s.alone));
    let (table, chain, each) = (median(|s| s.table), median(|s| s.chain), median(|s| s.each));
    let retested = samples
        .last()
        .map(|s| s.retested.join(" "))
        .unwrap_or_default();
    // The machine is shared: every round's table shows how much it varies.
    let tables: Vec<String> = (samples.iter())
        .map(|s| format!("{:.2}", s.table.as_secs_f64()))
        .collect();
    format!(
        "{folder:<15} {row:>8.2}s {alone:>8.2}s {:>5.2}× {table:>8.2}s {chain:>8.2}s {:>5.2}× {each:>8.2}s {:>5.2}×  {retested}\n{:15} the table in each round: {} s",
        row / alone,
        table / chain,
        table / each,
        "",
        tables.join(", ")
    )
}

/// The handout to measure in, every chapter solved and built, and
/// progress's results of every chapter kept.
fn prepared_handout() -> PathBuf {
    let dir = std::env::var_os("RAYBOOK_BENCH_HANDOUT").map_or_else(
        || PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("progress-bench"),
        PathBuf::from,
    );
    if !dir.join("Cargo.toml").exists() {
        let root = workbook::workbench::snapshot::workspace_root();
        let made = Command::new(env!("CARGO_BIN_EXE_workbook"))
            .args(["handout", "--solved-through", "8"])
            .arg(&dir)
            .current_dir(root)
            .status()
            .unwrap();
        assert!(made.success(), "workbook handout failed");
    }
    let warm = student_cargo(&dir)
        .args(["run", "-q", "-p", "workbook", "--", "progress", "--fresh"])
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(
        warm.success(),
        "every chapter of {} should pass",
        dir.display()
    );
    dir
}

/// `cargo` in the handout, as a student's shell runs it: none of the
/// variables this test's own cargo set.
fn student_cargo(handout: &Path) -> Command {
    let mut command = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    command.current_dir(handout);
    for (var, _) in std::env::vars_os() {
        let name = var.to_string_lossy();
        if name.starts_with("CARGO_") && name != "CARGO_HOME" || name == "RUSTFLAGS" {
            command.env_remove(&var);
        }
    }
    command
}

/// `workbook progress` into a pipe: when the `edited` chapter's row came,
/// when the table was done, and the chapters it tested (not shown from
/// their last run).
fn progress(handout: &Path, edited: &str) -> (Duration, Duration, Vec<String>) {
    let start = Instant::now();
    let mut child = student_cargo(handout)
        .args(["run", "-q", "-p", "workbook", "--", "progress"])
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let (mut row, mut retested) = (None, Vec::new());
    for line in BufReader::new(child.stdout.take().unwrap()).lines() {
        let line = line.unwrap();
        let Some((folder, _)) = CHAPTERS.iter().find(|(f, _)| is_row_of(&line, f)) else {
            continue;
        };
        if *folder == edited {
            row = Some(start.elapsed());
        }
        if !line.contains("unchanged since the last run") {
            retested.push(folder.to_string());
        }
    }
    assert!(child.wait().unwrap().success(), "progress should pass");
    let table = start.elapsed();
    (row.expect("the edited chapter's row"), table, retested)
}

/// Is `line` the table's row of the chapter in `folder`?
fn is_row_of(line: &str, folder: &str) -> bool {
    line.trim_start_matches(['→', ' ']).starts_with(folder)
}

fn package(folder: &str) -> &'static str {
    (CHAPTERS.iter().find(|(f, _)| *f == folder))
        .expect("a chapter")
        .1
}

/// `cargo test -p package` in the handout: how long it took.
fn cargo_test(handout: &Path, package: &str) -> Duration {
    let start = Instant::now();
    let status = student_cargo(handout)
        .args(["test", "-q", "-p", package])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "cargo test -p {package} should pass");
    start.elapsed()
}

/// One-line edits of a chapter's lib.rs, each a new comment line, and the
/// file as it was at the end.
struct Edit<'a> {
    folder: &'a str,
    path: PathBuf,
    original: String,
    count: usize,
}

impl<'a> Edit<'a> {
    fn new(handout: &Path, folder: &'a str) -> Edit<'a> {
        let path = handout.join("chapters").join(folder).join("src/lib.rs");
        let original = std::fs::read_to_string(&path).unwrap();
        Edit {
            folder,
            path,
            original,
            count: 0,
        }
    }

    fn once(&mut self) {
        self.count += 1;
        let text = format!("{}// progress bench: edit {}\n", self.original, self.count);
        std::fs::write(&self.path, text).unwrap();
    }

    fn restore(&self) {
        std::fs::write(&self.path, &self.original).unwrap();
    }
}
