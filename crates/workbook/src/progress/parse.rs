//! Reading what `cargo test` printed: passes, failures, snapshots, panics.

/// What one `cargo test` run printed, in the parts that matter here.
#[derive(Debug, Default, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
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
    /// Each failed test's panic: the test and what it said (the message's
    /// first line, and an assertion's `left:` and `right:`), by test name.
    pub panics: Vec<(String, String)>,
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
///   by `  diff (expected | mask | actual): PATH` (see `workbench::snapshot`);
/// * `thread 'name' (id) panicked at file:line:col:` and the message below it;
/// * `error[E0308]: mismatched types` or `error: could not compile` from cargo.
///
/// In one pass, whatever the output holds: the names already seen are
/// looked up in sets, and the panics sorted once at the end (the grader
/// reads up to 16 MiB a student's tests printed, and a list searched and
/// sorted again for each of half a million made-up failures took hours).
pub fn parse(output: &str) -> TestOutput {
    let mut parsed = TestOutput::default();
    let mut seen = Seen::default();
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
            if seen.failed.insert(name) {
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
            if seen.snapshots.insert(name) {
                parsed.snapshots.push((name.to_owned(), diff));
            }
        } else if let Some(test) = panicking_test(line) {
            let message = panic_message(&mut lines);
            if seen.panics.insert(test) {
                parsed.panics.push((test.to_owned(), message));
            }
        } else if parsed.compile_error.is_none()
            && (line.starts_with("error[") || line.starts_with("error: could not compile"))
        {
            parsed.compile_error = Some(line.to_owned());
        }
    }
    parsed.panics.sort();
    parsed
}

/// The names [`parse`] has met: each is kept the first time only.
#[derive(Default)]
struct Seen<'a> {
    failed: std::collections::HashSet<&'a str>,
    snapshots: std::collections::HashSet<&'a str>,
    panics: std::collections::HashSet<&'a str>,
}

/// The test of a line `thread 'name' (id) panicked at file:line:col:`
/// (libtest names each test's thread after it).
fn panicking_test(line: &str) -> Option<&str> {
    let rest = line.strip_prefix("thread '")?;
    let (name, after) = rest.split_once('\'')?;
    after.contains(" panicked at ").then_some(name)
}

/// The panic message after its `panicked at` line: the first line, and
/// for a failed `assert_eq!` its `left:` and `right:` lines, joined (a
/// handout's `todo!` says `not yet implemented: ID: hint`). The lines read
/// are consumed.
fn panic_message(lines: &mut std::iter::Peekable<std::str::Lines>) -> String {
    let Some(first) = lines.peek().map(|l| l.trim().to_owned()) else {
        return String::new();
    };
    lines.next();
    let mut message = first;
    while let Some(side) = lines
        .peek()
        .map(|l| l.trim())
        .filter(|l| l.starts_with("left:") || l.starts_with("right:"))
    {
        message.push_str("; ");
        message.push_str(side);
        lines.next();
    }
    message
}

/// The number before `word` in `3 passed; 2 failed; ...`.
fn count(summary: &str, word: &str) -> usize {
    summary
        .split([';', '.'])
        .filter_map(|part| part.trim().strip_suffix(word))
        .find_map(|n| n.trim().parse().ok())
        .unwrap_or(0)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// What `cargo test -p ch03-lambert` prints with `lambert` taken out (shortened).
    pub const FAILING: &str = r#"
   Compiling ch03-lambert v0.1.0 (/w/chapters/03-lambert)
     Running tests/chapter03/main.rs (target/debug/deps/chapter03-1234)

running 3 tests
test spot_factor_is_one_inside_zero_outside_and_smooth_between ... ok
test cosine_law_head_on_versus_sixty_degrees ... FAILED
test snapshot_default ... FAILED

failures:

---- cosine_law_head_on_versus_sixty_degrees stdout ----

thread 'cosine_law_head_on_versus_sixty_degrees' panicked at chapters/03-lambert/src/lib.rs:52:5:
not yet implemented: ch03-lambert: the cosine law: what a matte surface of this albedo sends back of the incoming light

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
    fn a_flood_of_made_up_failures_is_read_in_one_pass() {
        let mut output = String::new();
        for i in 0..100_000 {
            output += &format!("thread 't{i}' panicked at x:1:1:\nm\ntest f{i} ... FAILED\n");
        }
        output += "thread 't7' panicked at x:1:1:\nagain\ntest f7 ... FAILED\n";
        let start = std::time::Instant::now();
        let parsed = parse(&output);
        // One pass takes a fraction of a second; a list searched (and
        // sorted) again for each took 12 s for a sixth of these.
        assert!(start.elapsed().as_secs() < 20, "{:?}", start.elapsed());
        assert_eq!(parsed.failed_tests.len(), 100_000, "each once");
        assert_eq!(parsed.panics.len(), 100_000);
        assert!(parsed.panics.is_sorted());
        let seventh = parsed.panics.iter().find(|(t, _)| t == "t7");
        assert_eq!(
            seventh.map(|(_, m)| m.as_str()),
            Some("m"),
            "the first kept"
        );
    }

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
        assert_eq!(
            parsed.panics,
            [(
                "cosine_law_head_on_versus_sixty_degrees".to_owned(),
                "not yet implemented: ch03-lambert: the cosine law: what a matte surface of this albedo sends back of the incoming light".to_owned()
            )]
        );
        assert_eq!(parsed.compile_error, None);
        assert!(!parsed.passed_all());
    }

    #[test]
    fn a_failed_assertion_is_read_with_its_sides() {
        let output = "thread 'the_lectures_worked_example' (1740) panicked at tests/chapter02/spheres.rs:14:5:\n\
                      assertion `left == right` failed: t² − 4t + 3 = 0 has the roots 1 and 3\n  \
                      left: Some((0.5, 1.5))\n right: Some((1.0, 3.0))\nstack backtrace:\n";
        let parsed = parse(output);
        assert_eq!(
            parsed.panics,
            [(
                "the_lectures_worked_example".to_owned(),
                "assertion `left == right` failed: t² − 4t + 3 = 0 has the roots 1 and 3; \
                 left: Some((0.5, 1.5)); right: Some((1.0, 3.0))"
                    .to_owned()
            )]
        );
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
}
