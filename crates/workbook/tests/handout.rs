//! The maintainers' check of the exercises (rustlings has one too): every
//! chapter with exercises has them, and each region is covered by a test
//! that fails in the handout until the student writes it. (That the
//! reference passes is the rest of `cargo test`.) What needs a second build
//! of the workbook runs outside `cargo test`: `workbook handout --check`
//! (the lecture's own methods pass, the whole handout compiles), which CI
//! runs after the tests, and `workbook handout --check-mistakes` (the
//! classic mistakes of the chapters' mistakes.toml are caught and named).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use workbook::handout::check;
use workbook::handout::take_out::ReferenceTests;
use workbook::handout::{Region, workspace_regions};
use workbook::workbench::chapters::{self, ChapterEntry};

#[path = "handout/leaks.rs"]
mod leaks;

/// `workbook ARGS` run at the workspace root: its exit status and stdout.
fn workbook(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(args)
        .current_dir(root())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    (out.status.success(), format!("{stdout}{stderr}"))
}

fn root() -> PathBuf {
    workbook::workbench::snapshot::workspace_root()
}

/// The chapters the handout takes exercises out of (chapters/chapters.toml).
fn exercise_chapters() -> Vec<&'static ChapterEntry> {
    chapters::all().iter().filter(|c| c.exercises).collect()
}

#[test]
fn every_chapter_with_exercises_has_some_and_the_workbook_at_least_22() {
    let regions = workspace_regions(&root()).unwrap();
    let numbers: Vec<u32> = exercise_chapters().iter().map(|c| c.number()).collect();
    assert_eq!(numbers, (1..=7).collect::<Vec<_>>());
    for chapter in numbers {
        let ids: Vec<&str> = regions
            .iter()
            .filter(|(_, _, r)| r.chapter() == Some(chapter))
            .map(|(_, _, r)| r.id.as_str())
            .collect();
        assert!((2..=6).contains(&ids.len()), "chapter {chapter}: {ids:?}");
    }
    assert!(regions.len() >= 22, "only {} exercises", regions.len());
    for (file, line, region) in &regions {
        let folder = format!("chapters/{:02}-", region.chapter().unwrap());
        assert!(
            file.starts_with("chapters") && file.to_string_lossy().starts_with(&folder),
            "{}:{line}: {} is not in its chapter's folder",
            file.display(),
            region.id
        );
        assert!(
            !region.is_open(),
            "{}: the reference has the solution",
            region.id
        );
        assert!(!region.hint.is_empty(), "{}: no hint", region.id);
        let seam = format!(
            "crate::workbench::exercise::solution_begins({:?});",
            region.id
        );
        assert_eq!(
            region.body.first().map(|l| l.trim()),
            Some(seam.as_str()),
            "{}:{line}: the solution of {} starts with the call that lets the check take it out",
            file.display(),
            region.id
        );
        assert!(
            region
                .message()
                .starts_with(&format!("not yet implemented: {}: ", region.id)),
            "the handout's todo! and the check's panic say the same"
        );
    }
    let ids: BTreeSet<&str> = regions.iter().map(|(_, _, r)| r.id.as_str()).collect();
    assert_eq!(ids.len(), regions.len(), "exercise ids are unique");
}

#[test]
fn every_recorded_mistake_and_lecture_solution_names_an_exercise() {
    let regions = workspace_regions(&root()).unwrap();
    let ids: BTreeSet<&str> = regions.iter().map(|(_, _, r)| r.id.as_str()).collect();
    let files = check::mistakes_files(&root()).unwrap();
    for (chapter, file) in &files {
        let named = file
            .mistake
            .iter()
            .map(|m| &m.exercise)
            .chain(file.lecture.iter().map(|l| &l.exercise));
        for id in named {
            assert!(
                ids.contains(id.as_str()),
                "{}: no exercise {id}",
                chapter.folder
            );
            assert!(
                id.starts_with(&format!("ch{:02}-", chapter.number())),
                "{}: {id} belongs to another chapter",
                chapter.folder
            );
        }
    }
}

/// Each chapter's exercises taken out: its own tests fail, and each
/// exercise's todo! is among the panics. The reference's test binaries are
/// run with the solutions taken out at run time (`workbench::exercise`), so
/// nothing is built again.
#[test]
fn each_exercise_makes_a_test_of_its_chapter_fail() {
    let start = Instant::now();
    let tests = ReferenceTests::build(&root()).unwrap();
    let regions = workspace_regions(&root()).unwrap();
    for entry in exercise_chapters() {
        each_exercise_makes_a_test_fail(&tests, entry, &regions);
    }
    eprintln!(
        "every exercise is reached by a test ({:.0?})",
        start.elapsed()
    );
}

/// A chapter's exercises taken out alone: its own tests must fail, and each
/// exercise's todo! must be among the panics.
fn each_exercise_makes_a_test_fail(
    tests: &ReferenceTests,
    entry: &ChapterEntry,
    regions: &[(PathBuf, usize, Region)],
) {
    let step = Instant::now();
    let chapter = entry.number();
    let package = entry.package();
    let mine: Vec<_> = regions
        .iter()
        .filter(|(_, _, r)| r.chapter() == Some(chapter))
        .collect();
    let ids: Vec<&str> = mine.iter().map(|(_, _, r)| r.id.as_str()).collect();
    let (ok, output, parsed) = tests.run_taken_out(&root(), entry, &ids).unwrap();
    assert!(
        !ok && parsed.failed > 0,
        "{package} with its exercises taken out must fail its tests:\n{output}"
    );
    for (file, line, region) in mine {
        let panic = format!("not yet implemented: {}: ", region.id);
        assert!(
            output.contains(&panic),
            "{}:{line}: no test of {package} reaches exercise {} (expected the panic {panic:?}):\n{output}",
            file.display(),
            region.id,
        );
    }
    eprintln!(
        "{package}: {} tests fail with its exercises taken out ({:.0?})",
        parsed.failed,
        step.elapsed()
    );
}

#[test]
fn workbook_handout_writes_a_copy_and_refuses_a_folder_in_use() {
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("handout-cli");
    let _ = std::fs::remove_dir_all(&base);
    let handout = |dir: &Path| {
        Command::new(env!("CARGO_BIN_EXE_workbook"))
            .arg("handout")
            .arg(dir)
            .current_dir(root().join("chapters/03-lambert"))
            .output()
            .unwrap()
    };

    let dir = base.join("student");
    let out = handout(&dir);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout.contains("ch03-lambert") && stdout.contains("next: cd "),
        "{stdout}"
    );
    let lambert = std::fs::read_to_string(dir.join("chapters/03-lambert/src/lib.rs")).unwrap();
    assert!(lambert.contains("todo!(\"ch03-lambert: "), "{lambert}");
    // No line of the solution comes along. The lines are read from the
    // workbook's own source, not written here: this file is in the handout
    // too, and a literal solution in it would give the exercise away. (Run
    // in a handout, the source's region is the todo! itself: nothing to check.)
    let solved = std::fs::read_to_string(root().join("chapters/03-lambert/src/lib.rs")).unwrap();
    assert!(
        solved.contains("// EXERCISE(ch03-lambert)"),
        "the region of ch03-lambert is gone"
    );
    let region = solved
        .lines()
        .skip_while(|line| !line.contains("// EXERCISE(ch03-lambert)"))
        .skip(1)
        .take_while(|line| !line.contains("// END EXERCISE"));
    for line in region.map(str::trim) {
        if !line.is_empty() && !line.starts_with("todo!(") {
            assert!(
                !lambert.contains(line),
                "the handout keeps the solution's line {line}"
            );
        }
    }
    assert_eq!(
        std::fs::read(dir.join("snapshots/03-lambert/default.snap.png")).unwrap(),
        std::fs::read(root().join("snapshots/03-lambert/default.snap.png")).unwrap(),
        "the references come along"
    );
    assert!(!dir.join(".git").exists());
    only_registry_builds_copied(&dir.join("target"));

    // The same folder again: it is not empty now.
    let again = handout(&dir);
    assert!(!again.status.success());
    assert!(String::from_utf8_lossy(&again.stderr).contains("is not empty"));

    // --files-only: nothing compiled comes along.
    let bare = base.join("files-only");
    let out = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["handout", "--files-only"])
        .arg(&bare)
        .current_dir(root())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(bare.join("chapters/01-rays/src/lib.rs").exists());
    assert!(!bare.join("target").exists());
}

/// The handout's `target/` holds at most the registry crates' compiled
/// files that `handout` copied from the workspace's build (so that its
/// first build compiles only the workspace's own crates): none of the
/// workspace's own crates, nothing outside `debug/deps`, `.fingerprint`
/// and `build`, and copies only, never a file shared with the clone's.
fn only_registry_builds_copied(target: &Path) {
    use std::os::unix::fs::MetadataExt;
    let ours: Vec<String> = ["chapters", "crates"]
        .iter()
        .flat_map(|folder| std::fs::read_dir(root().join(folder)).unwrap())
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .map(|name| match name.split_once('-') {
            Some((n, rest)) if n.len() == 2 || n == "04b" => format!("ch{n}_{rest}"),
            _ => name,
        })
        .map(|name| name.replace('-', "_"))
        .chain(["raybook".to_owned()])
        .collect();
    let Ok(debug) = std::fs::read_dir(target.join("debug")) else {
        return; // nothing compiled to copy (a fresh clone's first run)
    };
    for entry in debug {
        let entry = entry.unwrap();
        let folder = entry.file_name().to_string_lossy().to_string();
        assert!(
            ["deps", ".fingerprint", "build"].contains(&folder.as_str()),
            "target/debug/{folder} came along"
        );
        for file in test_support::files_under(&entry.path()) {
            let name = file
                .file_name()
                .unwrap()
                .to_string_lossy()
                .replace('-', "_");
            let name = name.strip_prefix("lib").unwrap_or(&name).to_owned();
            assert!(
                !ours
                    .iter()
                    .any(|crate_| name.starts_with(&format!("{crate_}_"))),
                "the workspace's own crate came along: {}",
                file.display()
            );
            assert_eq!(file.metadata().unwrap().nlink(), 1, "{}", file.display());
        }
    }
}

#[test]
fn a_handout_can_leave_the_first_chapters_solved() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("handout-solved");
    let _ = std::fs::remove_dir_all(&dir);
    let (ok, out) = workbook(&["handout", dir.to_str().unwrap(), "--solved-through", "3"]);
    assert!(ok, "{out}");
    let source = |file: &str| std::fs::read_to_string(dir.join(file)).unwrap();
    assert!(!source("chapters/03-lambert/src/lib.rs").contains("todo!(\"ch03-"));
    assert!(!source("chapters/01-rays/src/lib.rs").contains("todo!(\"ch01-"));
    assert!(source("chapters/04-shadows/src/lib.rs").contains("todo!(\"ch04-shadow-ray: "));
    assert!(!dir.join("chapters/03-lambert/mistakes.toml").exists());
}
