//! The maintainers' check of the exercises (rustlings has one too): every
//! chapter from 1 to 7 has exercise regions, the handout compiles, and each
//! region is covered by a test that fails in the handout until the student
//! writes it. (That the reference passes is the rest of `cargo test`.)
//!
//! The handout is built with cargo inside `target/handout-check/`, with its
//! own CARGO_TARGET_DIR: the `cargo test` running this file holds the lock on
//! the main target folder. Dependencies compile there once and are reused by
//! later runs; the variants below are written into one folder, file by file
//! only where they differ, so cargo rebuilds only the chapter that changed.
//! That target folder belongs to this check alone: cargo names a workspace
//! member's artifacts by its path inside the workspace, so building another
//! copy of the workbook there would leave artifacts that cargo takes for
//! this copy's.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use raybook::handout::{Region, workspace_files, workspace_regions, write_tree};
use raybook::progress::parse;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// cargo in `dir`, building into the check's own target folder, offline (the
/// handout's Cargo.lock is the reference's, whose dependencies are already
/// fetched: this test is running).
fn cargo(dir: &Path, args: &[&str]) -> (bool, String) {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .args(args)
        .current_dir(dir)
        .env(
            "CARGO_TARGET_DIR",
            root().join("target/handout-check/target"),
        )
        .env_remove("CARGO_MAKEFLAGS")
        .output()
        .expect("cargo runs");
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.success(), text)
}

/// Removes the files under `dir` that are not in `keep` (left over from an
/// earlier run: deleted sources, snapshot failures, insta's .snap.new files).
fn prune(dir: &Path, relative: &Path, keep: &BTreeSet<PathBuf>) {
    for entry in std::fs::read_dir(dir.join(relative)).unwrap() {
        let entry = entry.unwrap();
        let path = relative.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            prune(dir, &path, keep);
        } else if !keep.contains(&path) {
            std::fs::remove_file(dir.join(&path)).unwrap();
        }
    }
}

/// Writes the workspace into `work` with the selected regions taken out.
fn write_variant(work: &Path, select: impl Fn(&Region) -> bool) {
    let written = write_tree(&root(), work, select).unwrap();
    let keep: BTreeSet<PathBuf> = workspace_files(&root()).unwrap().into_iter().collect();
    prune(work, Path::new(""), &keep);
    assert_eq!(written.files, keep.len());
}

#[test]
fn every_chapter_from_1_to_7_has_one_to_three_exercises() {
    let regions = workspace_regions(&root()).unwrap();
    for chapter in 1..=7 {
        let ids: Vec<&str> = regions
            .iter()
            .filter(|(_, _, r)| r.chapter() == Some(chapter))
            .map(|(_, _, r)| r.id.as_str())
            .collect();
        assert!((1..=3).contains(&ids.len()), "chapter {chapter}: {ids:?}");
    }
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
fn the_handout_compiles_and_each_exercise_has_a_failing_test() {
    let start = Instant::now();
    let work = root().join("target/handout-check/work");
    std::fs::create_dir_all(&work).unwrap();
    let regions = workspace_regions(&root()).unwrap();
    let chapters: BTreeSet<u32> = regions.iter().filter_map(|(_, _, r)| r.chapter()).collect();

    // Each chapter's exercises taken out alone: its own tests must fail,
    // and each exercise's todo! must be among the panics.
    for &chapter in &chapters {
        let step = Instant::now();
        write_variant(&work, |r| r.chapter() == Some(chapter));
        let folder = std::fs::read_dir(root().join("chapters"))
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .find(|f| f.starts_with(&format!("{chapter:02}-")))
            .unwrap();
        let package = format!("ch{folder}");
        let (ok, output) = cargo(
            &work,
            &[
                "test",
                "--offline",
                "-p",
                &package,
                "--no-fail-fast",
                "--color",
                "never",
                "--",
                "--nocapture",
            ],
        );
        let parsed = parse(&output);
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

    // The handout itself, every exercise taken out: it compiles, tests and all.
    let step = Instant::now();
    write_variant(&work, |_| true);
    let (ok, output) = cargo(
        &work,
        &[
            "build",
            "--offline",
            "--workspace",
            "--tests",
            "--color",
            "never",
        ],
    );
    assert!(ok, "the handout does not compile:\n{output}");
    eprintln!("the whole handout builds ({:.0?})", step.elapsed());
    eprintln!("handout check: {:.0?} in all", start.elapsed());
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
