//! The maintainers' check of the exercises (rustlings has one too): every
//! chapter with exercises has them, the handout compiles, each region is
//! covered by a test that fails in the handout until the student writes it,
//! and the lecture's own methods, written as a student would, pass. (That
//! the reference passes is the rest of `cargo test`.) The variants are
//! built as `raybook::handout::check` describes; the classic mistakes of the
//! chapters' mistakes.toml are replayed by `raybook handout --check-mistakes`,
//! which CI runs after the tests.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use raybook::handout::check::{self, Check};
use raybook::handout::{Region, workspace_regions};
use raybook::toolkit::chapters::{self, ChapterEntry};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
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

/// Builds and tests each chapter with its exercises taken out, then the
/// lecture's methods, then the whole handout: one test, since the variants
/// share one folder.
#[test]
fn the_handout_compiles_each_exercise_has_a_failing_test_and_the_lectures_methods_pass() {
    let start = Instant::now();
    let check = Check::new(&root()).unwrap();
    eprintln!("dependencies shared ({:.0?})", start.elapsed());
    let regions = workspace_regions(&root()).unwrap();
    for entry in exercise_chapters() {
        each_exercise_makes_a_test_fail(&check, entry, &regions);
    }
    the_lectures_methods_pass(&check);
    the_whole_handout_builds(&check);
    eprintln!("handout check: {:.0?} in all", start.elapsed());
}

/// A chapter's exercises taken out alone: its own tests must fail, and each
/// exercise's todo! must be among the panics.
fn each_exercise_makes_a_test_fail(
    check: &Check,
    entry: &ChapterEntry,
    regions: &[(PathBuf, usize, Region)],
) {
    let step = Instant::now();
    let chapter = entry.number();
    check
        .write_variant(|r| (r.chapter() == Some(chapter)).then(|| r.todo_line()))
        .unwrap();
    let package = entry.package();
    let (ok, output, parsed) = check.test(&package).unwrap();
    assert!(
        !ok && parsed.failed > 0 && parsed.compile_error.is_none(),
        "{package} with its exercises taken out must build and fail its tests:\n{output}"
    );
    for (file, line, region) in regions
        .iter()
        .filter(|(_, _, r)| r.chapter() == Some(chapter))
    {
        assert!(
            output.contains(&region.message()),
            "{}:{line}: no test of {package} reaches exercise {} (expected the panic {:?}):\n{output}",
            file.display(),
            region.id,
            region.message()
        );
    }
    eprintln!(
        "{package}: {} tests fail with its exercises taken out ({:.0?})",
        parsed.failed,
        step.elapsed()
    );
}

/// The lecture's own methods (the chapters' `[[lecture]]` solutions), all
/// written in at once: every test of their chapters passes.
fn the_lectures_methods_pass(check: &Check) {
    let step = Instant::now();
    let files = check::mistakes_files(&root()).unwrap();
    let solutions: Vec<_> = files.iter().flat_map(|(_, f)| f.lecture.iter()).collect();
    if solutions.is_empty() {
        return;
    }
    check
        .write_variant(|r| {
            solutions
                .iter()
                .find(|s| s.exercise == r.id)
                .map(|s| s.body.clone())
        })
        .unwrap();
    for (chapter, file) in files.iter().filter(|(_, f)| !f.lecture.is_empty()) {
        let (ok, output, _) = check.test(&chapter.package()).unwrap();
        let ids: Vec<&str> = file.lecture.iter().map(|l| l.exercise.as_str()).collect();
        assert!(
            ok,
            "{}: the lecture's method for {ids:?} fails a test:\n{output}",
            chapter.folder
        );
    }
    eprintln!(
        "{} lecture solutions pass ({:.0?})",
        solutions.len(),
        step.elapsed()
    );
}

/// The handout itself, every exercise taken out: every crate and binary
/// compiles (each chapter's tests compiled above, with its own exercises
/// out; taking out the others' changes no signature).
fn the_whole_handout_builds(check: &Check) {
    let step = Instant::now();
    check.write_variant(|r| Some(r.todo_line())).unwrap();
    let (ok, output) = check
        .cargo(&[
            "build",
            "--offline",
            "--workspace",
            "--lib",
            "--bins",
            "--color",
            "never",
        ])
        .unwrap();
    assert!(ok, "the handout does not compile:\n{output}");
    eprintln!("the whole handout builds ({:.0?})", step.elapsed());
}

#[test]
fn raybook_handout_writes_a_copy_and_refuses_a_folder_in_use() {
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("handout-cli");
    let _ = std::fs::remove_dir_all(&base);
    let raybook = |dir: &Path| {
        Command::new(env!("CARGO_BIN_EXE_raybook"))
            .arg("handout")
            .arg(dir)
            .current_dir(root().join("chapters/03-lambert"))
            .output()
            .unwrap()
    };

    let dir = base.join("student");
    let out = raybook(&dir);
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
    assert!(!lambert.contains("surface.material.color * incoming.radiance * cos_theta"));
    assert_eq!(
        std::fs::read(dir.join("snapshots/03-lambert/default.snap.png")).unwrap(),
        std::fs::read(root().join("snapshots/03-lambert/default.snap.png")).unwrap(),
        "the references come along"
    );
    assert!(!dir.join("target").exists() && !dir.join(".git").exists());

    // The same folder again: it is not empty now.
    let again = raybook(&dir);
    assert!(!again.status.success());
    assert!(String::from_utf8_lossy(&again.stderr).contains("is not empty"));
}
