//! The maintainers' check of the exercises, as rustlings has one: variants
//! of the workbook with some exercise bodies replaced (by `todo!`, by a
//! classic mistake, by the lecture's own method), built and tested.
//!
//! The variants are built with cargo inside `target/handout-check/`, with
//! their own target folder: cargo names a workspace member's artifacts by its
//! path inside the workspace, so building another copy of the workbook in
//! the main target folder would leave artifacts that cargo takes for the
//! reference's. The registry dependencies are another matter: their
//! artifacts are the same in both, so the check's target folder starts with
//! hard links to those the main build has compiled already, and the check
//! compiles only the workbook's own crates. Variants are written into one
//! folder, file by file only where they differ, so cargo rebuilds only the
//! chapter that changed.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use serde::Deserialize;

use crate::progress::{TestOutput, parse};
use crate::regions::Region;
use crate::workbench::chapters::{self, ChapterEntry};
use crate::workspace::{workspace_files, write_tree_with};

/// Where the variants are written and built.
pub struct Check {
    root: PathBuf,
    work: PathBuf,
    target: PathBuf,
}

impl Check {
    /// A check of the workspace at `root`, its registry dependencies linked
    /// from the main build (`cargo test` or `cargo build` has run there).
    pub fn new(root: &Path) -> Result<Check, String> {
        Check::in_folder(root, &root.join("target/handout-check"))
    }

    /// A check that writes and builds its variants under `base` (its
    /// `work/` and `target/`): two checks at once need two folders, or
    /// each overwrites the other's variants.
    pub fn in_folder(root: &Path, base: &Path) -> Result<Check, String> {
        let check = Check {
            root: root.to_owned(),
            work: base.join("work"),
            target: base.join("target"),
        };
        std::fs::create_dir_all(&check.work)
            .map_err(|e| format!("cannot create {}: {e}", check.work.display()))?;
        check.share_dependencies()?;
        Ok(check)
    }

    /// Writes the workspace into the work folder with the regions' bodies
    /// that `body` gives (None keeps the reference's), and removes what an
    /// earlier variant left behind.
    pub fn write_variant(&self, body: impl Fn(&Region) -> Option<String>) -> Result<(), String> {
        write_tree_with(&self.root, &self.work, body)?;
        let keep: BTreeSet<PathBuf> = workspace_files(&self.root)?.into_iter().collect();
        prune(&self.work, Path::new(""), &keep).map_err(|e| format!("cannot prune: {e}"))
    }

    /// cargo in the work folder, building into the check's own target
    /// folder, offline (the variant's Cargo.lock is the reference's, whose
    /// dependencies are fetched already). Success, and what it printed.
    pub fn cargo(&self, args: &[&str]) -> Result<(bool, String), String> {
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .args(args)
            .current_dir(&self.work)
            .env("CARGO_TARGET_DIR", &self.target)
            .env_remove("CARGO_MAKEFLAGS")
            .output()
            .map_err(|e| format!("cannot run cargo: {e}"))?;
        let text = format!(
            "{}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        Ok((out.status.success(), text))
    }

    /// `cargo test -p <package>` on the current variant: success, what it
    /// printed, and that read as test results.
    pub fn test(&self, package: &str) -> Result<(bool, String, TestOutput), String> {
        let (ok, text) = self.cargo(&[
            "test",
            "--offline",
            "-p",
            package,
            "--no-fail-fast",
            "--color",
            "never",
            "--",
            "--nocapture",
        ])?;
        let parsed = parse(&text);
        Ok((ok, text, parsed))
    }

    /// Links the registry dependencies that the main build has compiled
    /// into the check's target folder (`share::registry_builds`).
    fn share_dependencies(&self) -> Result<(), String> {
        super::share::registry_builds(&self.root, &self.target, super::share::How::Link).map(|_| ())
    }
}

/// Removes the files under `dir` that are not in `keep` (left over from an
/// earlier variant: deleted sources, snapshot failures, insta's .snap.new).
fn prune(dir: &Path, relative: &Path, keep: &BTreeSet<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir.join(relative))? {
        let entry = entry?;
        let path = relative.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            prune(dir, &path, keep)?;
        } else if !keep.contains(&path) {
            std::fs::remove_file(dir.join(&path))?;
        }
    }
    Ok(())
}

/// A classic mistake in an exercise, from a chapter's `mistakes.toml`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mistake {
    /// The exercise's id.
    pub exercise: String,
    /// The mistake, in a few words.
    pub what: String,
    /// A piece of the failing test's output that names the mistake.
    pub expect: String,
    /// The region's body with the mistake in it.
    pub body: String,
    /// Messages that would send the student to another exercise, which no
    /// test may print for this mistake (a misdirection once seen).
    #[serde(default)]
    pub not_said: Vec<String>,
}

/// The lecture's own method for an exercise, written as a student would.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LectureSolution {
    pub exercise: String,
    pub body: String,
}

/// A chapter's `mistakes.toml`.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MistakesFile {
    #[serde(default)]
    pub mistake: Vec<Mistake>,
    #[serde(default)]
    pub lecture: Vec<LectureSolution>,
}

/// Every chapter's `mistakes.toml` (those that have one), with its chapter.
pub fn mistakes_files(root: &Path) -> Result<Vec<(&'static ChapterEntry, MistakesFile)>, String> {
    let mut found = Vec::new();
    for chapter in chapters::all() {
        let path = root.join(chapter.path()).join("mistakes.toml");
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let file = toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        found.push((chapter, file));
    }
    Ok(found)
}

/// What replaying one mistake showed.
#[derive(Debug)]
pub enum Caught {
    /// A test failed and its output names the mistake.
    Named,
    /// Tests failed, but none said `expect`.
    Unnamed,
    /// A test blamed another exercise, one that the mistake left right
    /// (through `workbench::exercise::builds_on`): these ids.
    Misblamed(Vec<String>),
    /// Every test passed: the mistake goes unnoticed.
    Missed,
    /// The mistaken body does not compile (the entry is wrong).
    NoBuild(String),
}

/// Writes `mistake` into its exercise and runs the chapter's tests.
pub fn replay(check: &Check, chapter: &ChapterEntry, mistake: &Mistake) -> Result<Caught, String> {
    check.write_variant(|r| (r.id == mistake.exercise).then(|| mistake.body.clone()))?;
    let (ok, text, parsed) = check.test(&chapter.package())?;
    Ok(if let Some(error) = parsed.compile_error {
        Caught::NoBuild(error)
    } else if ok {
        Caught::Missed
    } else if let Some(wrong) = blamed_elsewhere(&text, &mistake.exercise) {
        Caught::Misblamed(wrong)
    } else if let Some(said) = mistake.not_said.iter().find(|m| text.contains(m.as_str())) {
        Caught::Misblamed(vec![format!("another exercise (a test said {said:?})")])
    } else if text.contains(&mistake.expect) {
        Caught::Named
    } else {
        Caught::Unnamed
    })
}

/// The exercises other than `exercise` that a failing test's message blames
/// as the earlier exercise it builds on, if any: a mistake in `exercise`
/// alone must make no test blame another one.
fn blamed_elsewhere(output: &str, exercise: &str) -> Option<Vec<String>> {
    let mut wrong: Vec<String> = crate::workbench::exercise::blamed_by_builds_on(output)
        .into_iter()
        .filter(|id| *id != exercise)
        .map(str::to_owned)
        .collect();
    wrong.dedup();
    (!wrong.is_empty()).then_some(wrong)
}

/// Writes the lecture's methods (the `[[lecture]]` solutions) into their
/// exercises and runs their chapters' tests, which must all pass. An
/// exercise with several such solutions is tried once with each: round k
/// takes every exercise's k-th. A line per round says what passed.
pub fn lectures_pass(check: &Check, root: &Path) -> Result<Vec<String>, String> {
    let files = mistakes_files(root)?;
    // rounds[k]: the k-th solution of each exercise that has that many.
    let mut rounds: Vec<Vec<(&ChapterEntry, &LectureSolution)>> = Vec::new();
    let mut tried: std::collections::BTreeMap<&str, usize> = Default::default();
    for (chapter, file) in &files {
        for solution in &file.lecture {
            let k = tried.entry(solution.exercise.as_str()).or_default();
            if rounds.len() == *k {
                rounds.push(Vec::new());
            }
            rounds[*k].push((*chapter, solution));
            *k += 1;
        }
    }
    let mut lines = Vec::new();
    for (round, chosen) in rounds.iter().enumerate() {
        check.write_variant(|r| {
            let solution = chosen.iter().find(|(_, s)| s.exercise == r.id);
            solution.map(|(_, s)| s.body.clone())
        })?;
        let ids: Vec<&str> = chosen.iter().map(|(_, s)| s.exercise.as_str()).collect();
        let mut packages: Vec<String> = chosen.iter().map(|(c, _)| c.package()).collect();
        packages.dedup();
        for package in &packages {
            let (ok, output, _) = check.test(package)?;
            if !ok {
                return Err(format!(
                    "{package}: the lecture's method for {ids:?} fails a test:\n{output}"
                ));
            }
        }
        lines.push(format!(
            "round {}: the lecture's methods for {} pass every test of {}",
            round + 1,
            ids.join(", "),
            packages.join(", ")
        ));
    }
    Ok(lines)
}

/// The handout itself, every exercise taken out: every crate and binary
/// compiles (taking a body out changes no signature, so the tests compile
/// as they do against the reference).
pub fn whole_handout_builds(check: &Check) -> Result<(), String> {
    check.write_variant(|r| Some(r.todo_line()))?;
    let (ok, output) = check.cargo(&[
        "build",
        "--offline",
        "--workspace",
        "--lib",
        "--bins",
        "--color",
        "never",
    ])?;
    if ok {
        Ok(())
    } else {
        let output = without_linker_commands(&output);
        Err(format!("the handout does not compile:\n{output}"))
    }
}

/// cargo's output with each linker command rustc quotes in a failed link
/// (one line of thousands of characters) shortened, so that the linker's
/// own message after it, the reason, is what a reader and a CI log see.
fn without_linker_commands(output: &str) -> String {
    let shortened = output
        .lines()
        .map(|line| match line.split_once("= note:  \"") {
            Some((indent, _)) if line.len() > 300 => {
                format!(
                    "{indent}= note: (the linker's command, {} characters, left out)",
                    line.len()
                )
            }
            _ => line.to_owned(),
        });
    shortened.collect::<Vec<_>>().join("\n")
}

#[cfg(test)]
mod tests {
    use super::{blamed_elsewhere, without_linker_commands};

    #[test]
    fn a_test_that_blames_an_exercise_left_right_is_found() {
        let output = "panicked: this test builds on exercise ch03-spot, and ch03-spot is wrong: x";
        assert_eq!(blamed_elsewhere(output, "ch03-spot"), None);
        assert_eq!(
            blamed_elsewhere(output, "ch03-light-loop"),
            Some(vec!["ch03-spot".to_owned()])
        );
    }

    #[test]
    fn a_failed_link_shows_the_linkers_reason_not_its_command() {
        let command = format!("  = note:  \"cc\" \"-m64\" {}", "\"x.rlib\" ".repeat(100));
        let output = format!(
            "error: linking with `cc` failed: exit status: 1\n  |\n{command}\n  \
             = note: ld: final link failed: No space left on device"
        );
        let shown = without_linker_commands(&output);
        assert!(!shown.contains("x.rlib"), "{shown}");
        assert!(
            shown.contains("the linker's command, 923 characters, left out"),
            "{shown}"
        );
        assert!(shown.contains("No space left on device"), "{shown}");
        assert!(
            shown.starts_with("error: linking with `cc` failed"),
            "{shown}"
        );
    }
}
