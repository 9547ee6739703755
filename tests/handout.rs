//! The maintainers' check of the exercises (rustlings has one too): every
//! chapter from 1 to 7 has exercise regions, the handout compiles, and each
//! region is covered by a test that fails in the handout until the student
//! writes it. (That the reference passes is the rest of `cargo test`.)
//!
//! The handout is built with cargo inside `target/handout-check/`, with its
//! own CARGO_TARGET_DIR: cargo names a workspace member's artifacts by its
//! path inside the workspace, so building another copy of the workbook in
//! the main target folder would leave artifacts that cargo takes for the
//! reference's. The registry dependencies are another matter: their
//! artifacts are the same in both, so the check's target folder starts with
//! hard links to those the main build has compiled already, and the check
//! compiles only the workbook's own crates. The variants below are written
//! into one folder, file by file only where they differ, so cargo rebuilds
//! only the chapter that changed.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use raybook::handout::{Region, workspace_files, workspace_regions, write_tree};
use raybook::progress::parse;
use raybook::toolkit::chapters::{self, ChapterEntry};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The check's own target folder.
fn check_target() -> PathBuf {
    root().join("target/handout-check/target")
}

/// Links the registry dependencies that the main build (the `cargo test`
/// running this file) has compiled into the check's target folder, where
/// they are not there yet: their artifacts, fingerprints and build-script
/// outputs. The workbook's own crates are left out; cargo builds them anew.
fn share_dependencies() {
    // CARGO_TARGET_TMPDIR is <target>/tmp; the tests are built in <target>/debug.
    let main = Path::new(env!("CARGO_TARGET_TMPDIR")).join("../debug");
    let metadata = cargo_metadata::MetadataCommand::new()
        .current_dir(root())
        .exec()
        .expect("cargo metadata runs");
    let registry: Vec<_> = metadata
        .packages
        .iter()
        .filter(|p| p.source.is_some())
        .collect();
    let packages: BTreeSet<String> = registry.iter().map(|p| p.name.to_string()).collect();
    let crates: BTreeSet<String> = registry
        .iter()
        .flat_map(|p| p.targets.iter().map(|t| t.name.replace('-', "_")))
        .collect();
    // deps/lib<crate>-<hash>.rlib and <crate>-<hash>.d; .fingerprint/ and
    // build/ hold <package>-<hash> folders.
    let stem = |name: &str| {
        let name = name.strip_prefix("lib").unwrap_or(name);
        name.rsplit_once('-').map(|(stem, _)| stem.to_owned())
    };
    link_matching(
        &main.join("deps"),
        &check_target().join("debug/deps"),
        |n| stem(n).is_some_and(|s| crates.contains(&s)),
    );
    for folder in [".fingerprint", "build"] {
        link_matching(
            &main.join(folder),
            &check_target().join("debug").join(folder),
            |n| {
                n.rsplit_once('-')
                    .is_some_and(|(s, _)| packages.contains(s))
            },
        );
    }
}

/// Hard-links each entry of `from` whose name is chosen (folders with all
/// they hold) into `to`, unless it is there already.
fn link_matching(from: &Path, to: &Path, chosen: impl Fn(&str) -> bool) {
    let Ok(entries) = std::fs::read_dir(from) else {
        return;
    };
    std::fs::create_dir_all(to).unwrap();
    for entry in entries {
        let entry = entry.unwrap();
        let name = entry.file_name().into_string().unwrap();
        if chosen(&name) {
            link_tree(&entry.path(), &to.join(&name));
        }
    }
}

fn link_tree(from: &Path, to: &Path) {
    if from.is_dir() {
        std::fs::create_dir_all(to).unwrap();
        for entry in std::fs::read_dir(from).unwrap() {
            let entry = entry.unwrap();
            link_tree(&entry.path(), &to.join(entry.file_name()));
        }
    } else if !to.exists() && std::fs::hard_link(from, to).is_err() {
        std::fs::copy(from, to).unwrap();
    }
}

/// cargo in `dir`, building into the check's own target folder, offline (the
/// handout's Cargo.lock is the reference's, whose dependencies are already
/// fetched: this test is running).
fn cargo(dir: &Path, args: &[&str]) -> (bool, String) {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .args(args)
        .current_dir(dir)
        .env("CARGO_TARGET_DIR", check_target())
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

/// The chapters the handout takes exercises out of (chapters/chapters.toml).
fn exercise_chapters() -> Vec<&'static ChapterEntry> {
    chapters::all().iter().filter(|c| c.exercises).collect()
}

#[test]
fn every_chapter_with_exercises_has_one_to_three() {
    let regions = workspace_regions(&root()).unwrap();
    let numbers: Vec<u32> = exercise_chapters().iter().map(|c| c.number()).collect();
    assert_eq!(numbers, (1..=7).collect::<Vec<_>>());
    for chapter in numbers {
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
    share_dependencies();
    eprintln!("dependencies shared ({:.0?})", start.elapsed());
    let regions = workspace_regions(&root()).unwrap();

    // Each chapter's exercises taken out alone: its own tests must fail,
    // and each exercise's todo! must be among the panics.
    for entry in exercise_chapters() {
        let step = Instant::now();
        let chapter = entry.number();
        write_variant(&work, |r| r.chapter() == Some(chapter));
        let package = entry.package();
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

    // The handout itself, every exercise taken out: every crate and binary
    // compiles (each chapter's tests compiled above, with its own exercises
    // out; taking out the others' changes no signature).
    let step = Instant::now();
    write_variant(&work, |_| true);
    let (ok, output) = cargo(
        &work,
        &[
            "build",
            "--offline",
            "--workspace",
            "--lib",
            "--bins",
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
