//! `raybook progress`: where a student is in the workbook.
//!
//! Runs each chapter's tests in order (`cargo test -p chNN-name
//! --no-fail-fast`), reads what libtest prints, and shows a table: the
//! chapter, how many tests pass and fail, its exercises written so far, and
//! its first failure (a snapshot's diff picture if a picture differs). The
//! first chapter that fails is where you are; by default the chapters after
//! it are not run (they build on it, so they would fail too), `--all` runs
//! them anyway. The last line says what to do next.
//!
//! It works the same in the reference workspace (every chapter passes) and in
//! a handout from `raybook handout`.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use crate::handout::{Region, current_workspace, workspace_regions};

/// What one `cargo test` run printed, in the parts that matter here.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct TestOutput {
    /// Tests passed, summed over every test binary and the doctests.
    pub passed: usize,
    /// Tests failed, likewise.
    pub failed: usize,
    /// The names of the failed tests, in the order they were reported.
    pub failed_tests: Vec<String>,
    /// Snapshots that differ from their reference: `chapter/name` and the
    /// path of the diff picture, if it was written.
    pub snapshots: Vec<(String, Option<String>)>,
    /// Exercise ids named by `todo!` panics (`not yet implemented: chNN-...:`).
    pub todos: Vec<String>,
    /// The first compile error, if the code does not build.
    pub compile_error: Option<String>,
}

impl TestOutput {
    /// Did everything build and pass, with at least one test run?
    pub fn passed_all(&self) -> bool {
        self.compile_error.is_none() && self.failed == 0 && self.passed > 0
    }
}

/// Reads the output (stdout and stderr together) of `cargo test`.
///
/// It relies on lines libtest, cargo and our snapshot helper print:
/// * `test result: FAILED. 3 passed; 2 failed; 0 ignored; ...` once per test binary;
/// * `test some::name ... FAILED` for each failed test;
/// * `snapshot 03-lambert/default differs from its reference: ...`, followed
///   by `  diff (expected | mask | actual): PATH` (see `toolkit::snapshot`);
/// * `not yet implemented: ch03-lambert: hint` from a handout's `todo!`;
/// * `error[E0308]: mismatched types` or `error: could not compile` from cargo.
pub fn parse(output: &str) -> TestOutput {
    let mut parsed = TestOutput::default();
    let mut lines = output.lines().peekable();
    while let Some(line) = lines.next() {
        let line = line.trim_end();
        if let Some(rest) = line.trim_start().strip_prefix("test result: ") {
            parsed.passed += count(rest, "passed");
            parsed.failed += count(rest, "failed");
        } else if let Some(name) = line
            .strip_prefix("test ")
            .and_then(|rest| rest.strip_suffix(" ... FAILED"))
        {
            if !parsed.failed_tests.iter().any(|t| t == name) {
                parsed.failed_tests.push(name.to_owned());
            }
        } else if let Some(rest) = line.trim_start().strip_prefix("snapshot ")
            && let Some((name, _)) = rest.split_once(" differs")
        {
            // The diff path follows within the next few lines of the report.
            let mut diff = None;
            for _ in 0..4 {
                let Some(next) = lines.peek() else { break };
                if let Some((_, path)) = next.split_once("diff (expected | mask | actual): ") {
                    diff = Some(path.trim().to_owned());
                    break;
                }
                lines.next();
            }
            if !parsed.snapshots.iter().any(|(n, _)| n == name) {
                parsed.snapshots.push((name.to_owned(), diff));
            }
        } else if let Some((_, rest)) = line.split_once("not yet implemented: ") {
            let id = rest.split(':').next().unwrap_or("").trim();
            if id.starts_with("ch") && !parsed.todos.iter().any(|t| t == id) {
                parsed.todos.push(id.to_owned());
            }
        } else if parsed.compile_error.is_none()
            && (line.starts_with("error[") || line.starts_with("error: could not compile"))
        {
            parsed.compile_error = Some(line.to_owned());
        }
    }
    parsed
}

/// The number before `word` in `3 passed; 2 failed; ...`.
fn count(summary: &str, word: &str) -> usize {
    summary
        .split([';', '.'])
        .filter_map(|part| part.trim().strip_suffix(word))
        .find_map(|n| n.trim().parse().ok())
        .unwrap_or(0)
}

/// One chapter of the workspace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Chapter {
    /// Its folder under chapters/, such as `03-lambert`.
    pub folder: String,
    /// Its package, such as `ch03-lambert`.
    pub package: String,
}

impl Chapter {
    /// Its number (3 for `03-lambert`).
    pub fn number(&self) -> u32 {
        self.folder[..2].parse().unwrap_or(0)
    }
}

/// The chapters under `root/chapters`, in order: the folders `NN-name` with
/// a Cargo.toml. Each folder's package is `chNN-name`.
pub fn chapters(root: &Path) -> Result<Vec<Chapter>, String> {
    let dir = root.join("chapters");
    let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut found: Vec<Chapter> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.path().join("Cargo.toml").is_file())
        .filter_map(|e| e.file_name().into_string().ok())
        .filter(|name| name.len() > 3 && name.as_bytes()[..2].iter().all(u8::is_ascii_digit))
        .map(|folder| Chapter {
            package: format!("ch{folder}"),
            folder,
        })
        .collect();
    found.sort_by(|a, b| a.folder.cmp(&b.folder));
    Ok(found)
}

/// A chapter's outcome in the table.
#[derive(Debug, Clone)]
pub struct Row {
    pub chapter: Chapter,
    /// None if it was not run (a chapter before it fails).
    pub output: Option<TestOutput>,
    /// Its exercise regions: file, line, region.
    pub exercises: Vec<(PathBuf, usize, Region)>,
}

impl Row {
    fn open_exercises(&self) -> impl Iterator<Item = &(PathBuf, usize, Region)> {
        self.exercises.iter().filter(|(_, _, r)| r.is_open())
    }
}

/// The table and the advice, as text.
pub fn report(rows: &[Row], root: &Path) -> String {
    let relative = |p: &str| {
        Path::new(p)
            .strip_prefix(root)
            .map_or(p.to_owned(), |r| r.display().to_string())
    };
    let here = rows
        .iter()
        .position(|r| r.output.as_ref().is_some_and(|o| !o.passed_all()));
    let mut table = vec![[
        String::new(),
        "chapter".into(),
        "passed".into(),
        "failed".into(),
        "exercises".into(),
        "first failure".into(),
    ]];
    for (i, row) in rows.iter().enumerate() {
        let marker = if Some(i) == here { "→" } else { "" };
        let total = row.exercises.len();
        let done = total - row.open_exercises().count();
        let exercises = if total == 0 {
            "-".to_owned()
        } else {
            format!("{done}/{total}")
        };
        let (passed, failed, failure) = match &row.output {
            None => ("-".into(), "-".into(), "not run".to_owned()),
            Some(o) => {
                let failure = if let Some(error) = &o.compile_error {
                    format!("does not compile: {error}")
                } else if let Some((name, diff)) = o.snapshots.first() {
                    match diff {
                        Some(diff) => format!("snapshot {name}: {}", relative(diff)),
                        None => format!("snapshot {name}"),
                    }
                } else if let Some(test) = o.failed_tests.first() {
                    format!("test {test}")
                } else if o.passed == 0 {
                    "no tests ran".to_owned()
                } else {
                    String::new()
                };
                (o.passed.to_string(), o.failed.to_string(), failure)
            }
        };
        table.push([
            marker.into(),
            row.chapter.folder.clone(),
            passed,
            failed,
            exercises,
            failure,
        ]);
    }
    let mut widths = [0; 6];
    for line in &table {
        for (w, cell) in widths.iter_mut().zip(line) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    for line in &table {
        let mut text = String::new();
        for (k, (cell, w)) in line.iter().zip(widths).enumerate() {
            let pad = w - cell.chars().count();
            if k == 2 || k == 3 {
                text.push_str(&" ".repeat(pad));
                text.push_str(cell);
            } else {
                text.push_str(cell);
                text.push_str(&" ".repeat(pad));
            }
            text.push_str("  ");
        }
        out.push_str(text.trim_end());
        out.push('\n');
    }
    out.push('\n');
    out.push_str(&next_step(rows, here));
    out.push('\n');
    out
}

/// The advice of the last line.
fn next_step(rows: &[Row], here: Option<usize>) -> String {
    let Some(i) = here else {
        return "next: every chapter passes. Well done! Try the exercises marked \
                \"extend\" and \"explore\" in the chapters' READMEs."
            .to_owned();
    };
    let row = &rows[i];
    let chapter = &row.chapter;
    let readme = format!("chapters/{}/README.md", chapter.folder);
    let test = format!("cargo test -p {}", chapter.package);
    let output = row.output.as_ref().expect("a failing row was run");
    let open: Vec<_> = row.open_exercises().collect();
    if let Some(error) = &output.compile_error {
        return format!(
            "next: chapter {} does not compile ({error}); run `{test}` to see the whole message",
            chapter.number()
        );
    }
    // The exercise a failing test named, else the first one not written yet.
    let named = output
        .todos
        .iter()
        .find_map(|id| open.iter().find(|(_, _, r)| &r.id == id));
    match named.or(open.first()) {
        Some((file, line, region)) => format!(
            "next: chapter {}: exercise {} in {}:{line}: {}\n      \
             read {readme}, write it, then run `{test}`",
            chapter.number(),
            region.id,
            file.display(),
            region.hint
        ),
        None => {
            let what = match output.snapshots.first() {
                Some((name, _)) => format!("the snapshot {name} differs"),
                None => match output.failed_tests.first() {
                    Some(test) => format!("the test {test} fails"),
                    None => "no test ran".to_owned(),
                },
            };
            format!(
                "next: chapter {}: {what}; run `{test}` and compare with {readme}",
                chapter.number()
            )
        }
    }
}

/// `raybook progress`: runs each chapter's tests in order and shows where you are.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct ProgressArgs {
    /// Run every chapter, not only those up to the first that fails.
    #[arg(long)]
    pub all: bool,
}

/// Runs the tests of one chapter with cargo, from the workspace root, and
/// reads their output.
pub fn run_chapter(root: &Path, chapter: &Chapter) -> Result<TestOutput, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .args([
            "test",
            "-p",
            &chapter.package,
            "--no-fail-fast",
            "--color",
            "never",
        ])
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
    Ok(parsed)
}

/// Runs `raybook progress`.
pub fn main(args: &ProgressArgs) -> ExitCode {
    match progress(args) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Prints the table; true if every chapter run passed.
fn progress(args: &ProgressArgs) -> Result<bool, String> {
    let root = current_workspace()?;
    let regions = workspace_regions(&root)?;
    let mut rows = Vec::new();
    let mut failing = false;
    for chapter in chapters(&root)? {
        let prefix = Path::new("chapters").join(&chapter.folder);
        let exercises = regions
            .iter()
            .filter(|(file, _, _)| file.starts_with(&prefix))
            .cloned()
            .collect();
        let output = if failing && !args.all {
            None
        } else {
            eprintln!("testing {} ...", chapter.folder);
            let output = run_chapter(&root, &chapter)?;
            failing |= !output.passed_all();
            Some(output)
        };
        rows.push(Row {
            chapter,
            output,
            exercises,
        });
    }
    print!("{}", report(&rows, &root));
    Ok(!failing)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `cargo test -p ch03-lambert` prints with `lambert` taken out (shortened).
    const FAILING: &str = r#"
   Compiling ch03-lambert v0.1.0 (/w/chapters/03-lambert)
     Running tests/chapter03.rs (target/debug/deps/chapter03-1234)

running 3 tests
test spot_factor_is_one_inside_zero_outside_and_smooth_between ... ok
test cosine_law_head_on_versus_sixty_degrees ... FAILED
test snapshot_default ... FAILED

failures:

---- cosine_law_head_on_versus_sixty_degrees stdout ----

thread 'cosine_law_head_on_versus_sixty_degrees' panicked at chapters/03-lambert/src/lib.rs:52:5:
not yet implemented: ch03-lambert: albedo × radiance × max(0, n·l)

---- snapshot_default stdout ----
snapshot 03-lambert/default differs from its reference: 19200 of 19200 pixels differ by more than the tolerance; largest channel difference 255/255
(tolerance: 2 steps per channel, 19 pixels)
  actual: /w/target/snapshot-failures/03-lambert/default.actual.png
  diff (expected | mask | actual): /w/target/snapshot-failures/03-lambert/default.diff.png

failures:
    cosine_law_head_on_versus_sixty_degrees
    snapshot_default

test result: FAILED. 1 passed; 2 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.21s

   Doc-tests ch03_lambert

running 1 test
test chapters/03-lambert/src/../README.md - (line 37) ... ok

test result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.30s
"#;

    #[test]
    fn counts_failures_snapshots_and_exercises_over_all_binaries() {
        let parsed = parse(FAILING);
        assert_eq!((parsed.passed, parsed.failed), (2, 2));
        assert_eq!(
            parsed.failed_tests,
            [
                "cosine_law_head_on_versus_sixty_degrees",
                "snapshot_default"
            ]
        );
        assert_eq!(
            parsed.snapshots,
            [(
                "03-lambert/default".to_owned(),
                Some("/w/target/snapshot-failures/03-lambert/default.diff.png".to_owned())
            )]
        );
        assert_eq!(parsed.todos, ["ch03-lambert"]);
        assert_eq!(parsed.compile_error, None);
        assert!(!parsed.passed_all());
    }

    #[test]
    fn a_passing_run_passes_and_a_compile_error_is_found() {
        let ok = "test result: ok. 12 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 1.0s\n";
        assert!(parse(ok).passed_all());
        assert_eq!(parse(ok).passed, 12);
        assert!(!parse("").passed_all(), "no tests is not a pass");
        let broken = "   Compiling ch02-hits v0.1.0\nerror[E0308]: mismatched types\n --> src/plane.rs:3:5\nerror: could not compile `ch02-hits` (lib) due to 1 previous error\n";
        let parsed = parse(broken);
        assert_eq!(
            parsed.compile_error.as_deref(),
            Some("error[E0308]: mismatched types")
        );
        assert!(!parsed.passed_all());
    }

    fn row(folder: &str, output: Option<&str>, exercises: &str) -> Row {
        let source = format!("fn f() {{\n{exercises}}}\n");
        let regions = crate::handout::regions(&source).unwrap();
        Row {
            chapter: Chapter {
                folder: folder.into(),
                package: format!("ch{folder}"),
            },
            output: output.map(parse),
            exercises: regions
                .into_iter()
                .map(|r| {
                    (
                        PathBuf::from(format!("chapters/{folder}/src/lib.rs")),
                        r.start + 1,
                        r,
                    )
                })
                .collect(),
        }
    }

    #[test]
    fn the_report_marks_the_first_failing_chapter_and_names_the_next_exercise() {
        let ok = "test result: ok. 5 passed; 0 failed; 0 ignored\n";
        let open = "    // EXERCISE(ch03-lambert): albedo × radiance × max(0, n·l)\n    todo!(\"...\")\n    // END EXERCISE\n";
        let rows = [
            row("02-hits", Some(ok), ""),
            row("03-lambert", Some(FAILING), open),
            row("04-shadows", None, ""),
        ];
        let text = report(&rows, Path::new("/w"));
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].contains("chapter") && lines[0].contains("first failure"));
        assert!(lines[1].starts_with("   02-hits") && lines[1].trim_end().ends_with('-'));
        assert!(lines[2].starts_with("→  03-lambert"), "{text}");
        assert!(lines[2].contains(" 0/1 "), "{text}");
        assert!(
            lines[2].ends_with(
                "  snapshot 03-lambert/default: target/snapshot-failures/03-lambert/default.diff.png"
            ),
            "{text}"
        );
        assert!(lines[3].contains("not run"));
        assert!(
            text.contains(
                "next: chapter 3: exercise ch03-lambert in chapters/03-lambert/src/lib.rs:2"
            ),
            "{text}"
        );
        assert!(text.contains("`cargo test -p ch03-lambert`"));
    }

    #[test]
    fn when_everything_passes_the_report_says_so() {
        let ok = "test result: ok. 5 passed; 0 failed; 0 ignored\n";
        let done = "    // EXERCISE(ch03-lambert): x\n    1.0\n    // END EXERCISE\n";
        let rows = [row("03-lambert", Some(ok), done)];
        let text = report(&rows, Path::new("/w"));
        assert!(text.contains("1/1"), "{text}");
        assert!(!text.contains('→'));
        assert!(text.contains("next: every chapter passes"));
    }

    #[test]
    fn the_chapters_are_found_in_order() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let found = chapters(root).unwrap();
        assert_eq!(found[0].folder, "00-toolkit");
        assert_eq!(found[3].package, "ch03-lambert");
        assert_eq!(found[3].number(), 3);
        assert!(found.windows(2).all(|w| w[0].folder < w[1].folder));
    }
}
