//! The reference the class is graded against: its files, its version and
//! commit, its base copy (the reference as a handout with every exercise
//! solved, built once: the dependencies every student shares), and the
//! tests of each exercise.

use std::collections::BTreeMap;
use std::hash::Hash;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use crate::build::cargo::{Place, TestBinary, cargo_test, test_binaries};
use crate::build::digest::Digest;
use crate::build::share::Shared;
use crate::judging::exercise_tests::{ExerciseTests, Tests, exercise_tests};
use crate::judging::probe::{self, Expected};
use crate::sandbox::bwrap::Setup;
use crate::sandbox::limits::{Limits, run};
use workbench::chapters::{self, ChapterEntry};
use workbook::handout::record::Record;
use workbook::workspace::{teacher_only, workspace_files, workspace_regions};

/// How to prepare the reference and grade the students.
#[derive(Debug, Clone)]
pub struct Settings {
    /// The chapters graded (their tests run, their exercises scored).
    pub chapters: Vec<&'static ChapterEntry>,
    /// The limits of a build (cargo test --no-run).
    pub build: Limits,
    /// The limits of a chapter's tests.
    pub test: Limits,
    /// Compiler processes per build.
    pub cargo_jobs: usize,
    /// Students (and reference runs) side by side.
    pub jobs: usize,
    /// The grading cache folder (`<out>/.cache`).
    pub cache: PathBuf,
    /// Folders never read as part of the reference (the class, the output).
    pub exclude: Vec<PathBuf>,
    /// The seed the probe draws the exercises' inputs and scenes from.
    pub seed: u64,
    /// How the students' runs are confined (`sandbox/bwrap.rs`).
    pub sandbox: Arc<Setup>,
}

/// The reference, prepared.
pub struct Reference {
    /// Its version and commit.
    pub record: Record,
    /// Its folder.
    pub root: PathBuf,
    /// A hash of its files: a new one grades everyone again.
    pub hash: String,
    /// The tests of the chapters graded and of their exercises.
    pub tests: Tests,
    /// Its base copy, built.
    pub base: Place,
    /// What students' target folders share of the base build.
    pub shared: Shared,
    /// The probe's files (teacher-only, so in no handout), relative to
    /// `root`: copied into every copy, as the tests are.
    pub probe_files: Vec<PathBuf>,
    /// The values and scenes the reference's probe computed with the seed.
    pub expected: Expected,
    /// Its files (a handout's: without the teacher's), relative to `root`.
    files: BTreeMap<PathBuf, ()>,
    /// The folders whose files are the students' own: each exercise
    /// chapter's `src/`.
    students: Vec<PathBuf>,
}

impl Reference {
    /// Reads the reference at `root`, writes and builds its base copy, and
    /// finds the tests of each exercise (or reads them from the cache).
    /// `say` hears what it is doing.
    pub fn prepare(root: &Path, settings: &Settings, say: &dyn Fn(&str)) -> Result<Self, String> {
        same_manifest(root)?;
        let files = reference_files(root, &settings.exclude)?;
        let (probe_files, hashed) = with_probe(root, &files)?;
        let hash = hash_of(root, &hashed)?;
        let record = Record::of_workspace(root);
        say(&format!("reference {}: {}", record.label(), root.display()));
        let base_dir = settings.cache.join("base");
        let base = write_base(root, &hashed, (&base_dir, &settings.sandbox), &hash)?;
        let students = students_folders();
        let shared = Shared::of_workspace(&base.copy, &students)?;
        seed_dependencies(root, &base, &shared);
        let mut binaries = BTreeMap::new();
        for chapter in &settings.chapters {
            say(&format!("building the reference's {}", chapter.package()));
            binaries.insert(chapter.folder.clone(), build(&base, chapter, settings)?);
        }
        say(&format!("probing the reference (seed {})", settings.seed));
        let expected = probe::expected(
            &base,
            &settings.chapters,
            settings.seed,
            (&settings.build, settings.cargo_jobs),
        )?;
        say("finding the tests of each exercise (cached for this reference)");
        let regions: Vec<(String, _)> = workspace_regions(root)?
            .into_iter()
            .filter_map(|(file, _, r)| Some((chapter_of(&file)?, r)))
            .collect();
        let limits = Limits {
            time: settings.test.time * 4,
            ..settings.test
        };
        let cache = settings.cache.join("exercise-tests.json");
        let tests = exercise_tests(
            &base,
            &binaries,
            &regions,
            (&limits, settings.jobs),
            (&cache, &hash),
        )?;
        Ok(Reference {
            record,
            root: root.to_owned(),
            hash,
            tests,
            base,
            shared,
            probe_files,
            expected,
            files,
            students,
        })
    }

    /// The reference at `root` as the outputs need it, read but not built:
    /// for joining the slices of a class graded against it (`class/merge.rs`),
    /// with the `tests` they recorded. Its pictures are read from `root`
    /// itself, whose files the base copy holds.
    pub fn read(root: &Path, exclude: &[PathBuf], tests: Tests) -> Result<Self, String> {
        same_manifest(root)?;
        let files = reference_files(root, exclude)?;
        let (probe_files, hashed) = with_probe(root, &files)?;
        Ok(Reference {
            record: Record::of_workspace(root),
            root: root.to_owned(),
            hash: hash_of(root, &hashed)?,
            tests,
            base: Place::of(root, &Arc::new(Setup::none())),
            shared: Shared::default(),
            probe_files,
            expected: Expected::default(),
            files,
            students: students_folders(),
        })
    }

    /// Is `path` (relative to a handout's root) one of the student's own
    /// files, which grading takes from them?
    pub fn is_students(&self, path: &Path) -> bool {
        self.students.iter().any(|dir| path.starts_with(dir))
    }

    /// The reference's copy of `path`, if it has one: in the base copy,
    /// which does not change while the class is graded.
    pub fn file(&self, path: &Path) -> Option<PathBuf> {
        self.files
            .contains_key(path)
            .then(|| self.base.copy.join(path))
    }

    /// The reference's files, relative to its root.
    pub fn files(&self) -> impl Iterator<Item = &PathBuf> {
        self.files.keys()
    }

    /// The exercises of chapter `folder`.
    pub fn exercises_of<'a>(&'a self, folder: &'a str) -> impl Iterator<Item = &'a ExerciseTests> {
        self.tests
            .exercises
            .iter()
            .filter(move |e| e.chapter == folder)
    }
}

/// The probe's files (teacher-only, so not among a handout's `files`),
/// and `files` with them: what the reference's hash covers, since the
/// probe decides the points.
fn with_probe(
    root: &Path,
    files: &BTreeMap<PathBuf, ()>,
) -> Result<(Vec<PathBuf>, BTreeMap<PathBuf, ()>), String> {
    let probe_files = probe::files(root)?;
    let mut hashed = files.clone();
    hashed.extend(probe_files.iter().map(|f| (f.clone(), ())));
    Ok((probe_files, hashed))
}

/// The folders whose files are the students' own: each exercise
/// chapter's `src/`.
fn students_folders() -> Vec<PathBuf> {
    (chapters::all().iter())
        .filter(|c| c.exercises)
        .map(|c| c.path().join("src"))
        .collect()
}

/// The chapter folder of a file under `chapters/`.
fn chapter_of(file: &Path) -> Option<String> {
    let folder = file.strip_prefix("chapters").ok()?.components().next()?;
    Some(folder.as_os_str().to_string_lossy().into_owned())
}

/// The reference's manifest must be the one this workbook was built with,
/// since the chapters graded and their packages come from it.
fn same_manifest(root: &Path) -> Result<(), String> {
    let path = root.join("chapters/chapters.toml");
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("{} is not a raybook workspace: {e}", root.display()))?;
    let built_in: &str = include_str!("../../../../chapters/chapters.toml");
    if text != built_in {
        return Err(format!(
            "{} differs from the manifest this workbook was built with: run the \
             reference's own `cargo run -p workbook -- grade`",
            path.display()
        ));
    }
    Ok(())
}

/// The reference's files as a handout holds them (without the teacher's),
/// leaving out the `exclude`d folders.
fn reference_files(root: &Path, exclude: &[PathBuf]) -> Result<BTreeMap<PathBuf, ()>, String> {
    let files = workspace_files(root)?;
    Ok(files
        .into_iter()
        .filter(|f| !teacher_only(f) && !exclude.iter().any(|x| root.join(f).starts_with(x)))
        .map(|f| (f, ()))
        .collect())
}

/// A hash of the files' names and contents.
fn hash_of(root: &Path, files: &BTreeMap<PathBuf, ()>) -> Result<String, String> {
    let mut digest = Digest::default();
    for file in files.keys() {
        file.hash(&mut digest);
        let bytes = std::fs::read(root.join(file))
            .map_err(|e| format!("cannot read {}: {e}", file.display()))?;
        bytes.hash(&mut digest);
    }
    Ok(digest.hex())
}

/// Writes the base copy at `dir`: the reference's `files` (every exercise
/// solved, without the teacher's files). A file it holds already is left
/// as it is, so that cargo finds it unchanged. A new reference (another
/// `hash`) gets a fresh copy, so that no file of the old one lingers; its
/// target folder stays, and cargo rebuilds what changed.
fn write_base(
    root: &Path,
    files: &BTreeMap<PathBuf, ()>,
    (dir, sandbox): (&Path, &Arc<Setup>),
    hash: &str,
) -> Result<Place, String> {
    let stamp = dir.join("target/reference-hash");
    if std::fs::read_to_string(&stamp).ok().as_deref() != Some(hash) && dir.exists() {
        for entry in std::fs::read_dir(dir).map_err(|e| e.to_string())?.flatten() {
            if entry.file_name() != "target" {
                let path = entry.path();
                let removed = if path.is_dir() {
                    std::fs::remove_dir_all(&path)
                } else {
                    std::fs::remove_file(&path)
                };
                removed.map_err(|e| format!("cannot clear {}: {e}", path.display()))?;
            }
        }
    }
    for file in files.keys() {
        let bytes = std::fs::read(root.join(file))
            .map_err(|e| format!("cannot read {}: {e}", file.display()))?;
        write_if_changed(&dir.join(file), &bytes)?;
    }
    std::fs::create_dir_all(dir.join("target")).map_err(|e| e.to_string())?;
    std::fs::write(&stamp, hash).map_err(|e| format!("cannot write {}: {e}", stamp.display()))?;
    let dir = dir.canonicalize().map_err(|e| e.to_string())?;
    Ok(Place::of(&dir, sandbox))
}

/// Writes `bytes` to `to` unless it holds them already.
fn write_if_changed(to: &Path, bytes: &[u8]) -> Result<(), String> {
    if std::fs::read(to).ok().as_deref() == Some(bytes) {
        return Ok(());
    }
    if let Some(parent) = to.parent() {
        std::fs::create_dir_all(parent)
            .map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    }
    std::fs::write(to, bytes).map_err(|e| format!("cannot write {}: {e}", to.display()))
}

/// Before the first build of the base copy, its target folder gets copies
/// of the registry dependencies compiled already by the reference's own
/// build and by the build this workbook comes from (cargo rebuilds any it
/// does not find fresh): copies, never links, so that nothing built later
/// writes into the teacher's own target folder. Best effort. The workspace's crates are left out: they are
/// built from the base copy's files.
fn seed_dependencies(root: &Path, base: &Place, shared: &Shared) {
    if base.target.join("debug").exists() {
        return;
    }
    let registry = shared.registry_only();
    for target in seed_targets(root) {
        let _ = registry.put(&target, &base.target);
    }
}

/// The target folders of the reference's build and of this workbook's
/// (`<target>/debug/workbook`).
fn seed_targets(root: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let metadata = cargo_metadata::MetadataCommand::new()
        .current_dir(root)
        .no_deps()
        .exec();
    if let Ok(metadata) = metadata {
        found.push(metadata.target_directory.into_std_path_buf());
    }
    let exe = std::env::current_exe().ok();
    if let Some(target) = exe.as_ref().and_then(|e| e.parent()?.parent()) {
        found.push(target.to_owned());
    }
    found
}

/// Builds the tests of `chapter` in the base copy; its test binaries.
fn build(
    base: &Place,
    chapter: &ChapterEntry,
    settings: &Settings,
) -> Result<Vec<TestBinary>, String> {
    let command = cargo_test(base, &chapter.package(), true, settings.cargo_jobs);
    let limits = Limits {
        time: settings.build.time.max(Duration::from_secs(3600)),
        ..settings.build
    };
    let ran = run(command, &limits)?;
    if !ran.success {
        let tail: Vec<&str> = ran.text.lines().rev().take(30).collect();
        return Err(format!(
            "the reference's {} does not build in {}:\n{}",
            chapter.package(),
            base.copy.display(),
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        ));
    }
    Ok(test_binaries(&ran.text, &base.copy.join(chapter.path())))
}
