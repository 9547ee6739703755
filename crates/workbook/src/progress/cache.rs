//! Each chapter's last result, kept in `target/workbook/results/`, so that
//! a chapter none of whose inputs changed since its last run is shown, not
//! built and tested again.
//!
//! A chapter's inputs are the Cargo files and every file and folder in the
//! workspace's folders (outside `target/`, hidden ones left out, `.cargo/`
//! kept) except the folders of the chapters after it, under `chapters/` and
//! `snapshots/`: its own code, tests and snapshots, the chapters it builds
//! on, the toolkit, the workbench. (A picture rendered into the workspace's
//! top folder is no input.) A result is
//! reused only if all of them are older than the moment its run started,
//! so an edit made while the tests ran counts as an edit. Judging by
//! modification times is what cargo does too; `progress --fresh` tests
//! every chapter again whatever the times say.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use serde::{Deserialize, Serialize};

use super::TestOutput;
use crate::workbench::chapters::{self, ChapterEntry};

/// A chapter's result as saved: when its run started, and what it printed.
#[derive(Serialize, Deserialize)]
struct Saved {
    /// The run's start, in milliseconds since the Unix epoch.
    started_ms: u64,
    output: TestOutput,
}

/// The file that keeps `chapter`'s last result.
fn saved_path(root: &Path, chapter: &ChapterEntry) -> PathBuf {
    (root.join("target/workbook/results")).join(format!("{}.json", chapter.folder))
}

fn millis(time: SystemTime) -> u64 {
    let since = time.duration_since(SystemTime::UNIX_EPOCH);
    since.map_or(0, |d| d.as_millis() as u64)
}

/// Keeps `output` as `chapter`'s last result, from a run started at
/// `started` (written whole or not at all; silently skipped if it cannot).
pub fn save(root: &Path, chapter: &ChapterEntry, started: SystemTime, output: &TestOutput) {
    let saved = Saved {
        started_ms: millis(started),
        output: output.clone(),
    };
    let path = saved_path(root, chapter);
    let Ok(json) = serde_json::to_vec(&saved) else {
        return;
    };
    let _ = fs::create_dir_all(path.parent().unwrap_or(root));
    let partial = path.with_extension("json.partial");
    if fs::write(&partial, json).is_ok() {
        let _ = fs::rename(&partial, &path);
    }
}

/// `chapter`'s last result and when its run started, if there is one.
fn load(root: &Path, chapter: &ChapterEntry) -> Option<(SystemTime, TestOutput)> {
    let text = fs::read(saved_path(root, chapter)).ok()?;
    let saved: Saved = serde_json::from_slice(&text).ok()?;
    let started = SystemTime::UNIX_EPOCH + Duration::from_millis(saved.started_ms);
    Some((started, saved.output))
}

/// Did `chapter` pass the last time it ran (whatever changed since)?
pub fn passed_last_time(root: &Path, chapter: &ChapterEntry) -> bool {
    load(root, chapter).is_some_and(|(_, output)| output.passed_all())
}

/// How much older than a run's start an input must be to count as older.
/// A file's modification time comes from the kernel's coarse clock, up to
/// a tick (1 to 4 ms) behind the clock a run's start is read from, and the
/// start is kept to the millisecond: a file saved within a few
/// milliseconds after the start could otherwise look older, and its edit
/// be missed. An input written within this margin of a start counts as
/// written after it (tested again: the safe side).
const CLOCK_MARGIN: Duration = Duration::from_millis(10);

/// The files of the workspace's top folder that are inputs: what cargo
/// builds with.
const BUILD_FILES: [&str; 4] = [
    "Cargo.toml",
    "Cargo.lock",
    "rust-toolchain",
    "rust-toolchain.toml",
];

/// The newest modification time of the workspace's inputs, by chapter:
/// the files of chapter N's folders under key N, all others under key 0.
pub struct Inputs {
    newest: BTreeMap<u32, SystemTime>,
}

impl Inputs {
    /// Looks at every file and folder of the workspace at `root` once.
    pub fn scan(root: &Path) -> Inputs {
        let mut inputs = Inputs {
            newest: BTreeMap::new(),
        };
        let mut top = entries(root);
        top.push(root.join(".cargo"));
        for entry in top {
            let name = entry.file_name().and_then(|n| n.to_str()).unwrap_or("");
            match name {
                "target" => {}
                _ if entry.is_file() && !BUILD_FILES.contains(&name) => {}
                "chapters" | "snapshots" => {
                    inputs.note(0, &entry);
                    for folder in entries(&entry) {
                        inputs.add(chapter_number(&folder), &folder);
                    }
                }
                _ => inputs.add(0, &entry),
            }
        }
        inputs
    }

    /// `chapter`'s last result, if none of its inputs changed since that
    /// run started: all are older than its start by more than
    /// [`CLOCK_MARGIN`].
    pub fn unchanged_result(&self, root: &Path, chapter: &ChapterEntry) -> Option<TestOutput> {
        let (started, output) = load(root, chapter)?;
        let newest = (self.newest.range(..=chapter.number()))
            .map(|(_, time)| *time)
            .max();
        newest
            .is_some_and(|t| t + CLOCK_MARGIN < started)
            .then_some(output)
    }

    /// Counts `path` (and all under it, if a folder) under key `number`.
    fn add(&mut self, number: u32, path: &Path) {
        self.note(number, path);
        if path.is_dir() && !path.is_symlink() {
            for entry in entries(path) {
                self.add(number, &entry);
            }
        }
    }

    /// Counts `path` itself: a folder's time changes when a file in it is
    /// made, removed or renamed.
    fn note(&mut self, number: u32, path: &Path) {
        let Ok(time) = fs::symlink_metadata(path).and_then(|m| m.modified()) else {
            return;
        };
        let newest = self.newest.entry(number).or_insert(time);
        *newest = (*newest).max(time);
    }
}

/// The entries of the folder `dir`, hidden ones (`.git`, an editor's swap
/// files) left out.
fn entries(dir: &Path) -> Vec<PathBuf> {
    let Ok(read) = fs::read_dir(dir) else {
        return Vec::new();
    };
    read.flatten()
        .filter(|e| !e.file_name().to_string_lossy().starts_with('.'))
        .map(|e| e.path())
        .collect()
}

/// The number of the chapter a folder under `chapters/` or `snapshots/`
/// belongs to (0, shared by all, if it is no chapter's).
fn chapter_number(folder: &Path) -> u32 {
    let name = folder.file_name().and_then(|n| n.to_str()).unwrap_or("");
    chapters::all()
        .iter()
        .find(|c| c.folder == name)
        .map_or(0, |c| c.number())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A workspace with chapters 1 to 3, each file written at `secs`.
    fn workspace(secs: u64) -> tempfile::TempDir {
        let root = tempfile::tempdir().unwrap();
        for file in [
            "Cargo.toml",
            "chapters/01-rays/src/lib.rs",
            "chapters/02-hits/src/lib.rs",
            "chapters/03-lambert/src/lib.rs",
            "snapshots/03-lambert/default.snap.png",
            "crates/workbench/src/lib.rs",
        ] {
            write(root.path(), file, secs);
        }
        for dir in ["chapters", "snapshots", "crates"] {
            set_times_under(&root.path().join(dir), secs);
        }
        root
    }

    fn at(secs: u64) -> SystemTime {
        SystemTime::UNIX_EPOCH + Duration::from_secs(secs)
    }

    fn write(root: &Path, file: &str, secs: u64) {
        let path = root.join(file);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(&path, b"x").unwrap();
        set_time(&path, secs);
    }

    fn set_time(path: &Path, secs: u64) {
        let file = fs::File::open(path).unwrap();
        file.set_modified(at(secs)).unwrap();
    }

    fn set_times_under(dir: &Path, secs: u64) {
        for entry in entries(dir) {
            if entry.is_dir() {
                set_times_under(&entry, secs);
            }
        }
        set_time(dir, secs);
    }

    fn chapter(folder: &str) -> &'static ChapterEntry {
        chapters::find(folder).unwrap()
    }

    fn passing() -> TestOutput {
        TestOutput {
            passed: 5,
            ..TestOutput::default()
        }
    }

    #[test]
    fn a_result_is_reused_until_one_of_its_chapters_inputs_changes() {
        let ws = workspace(1_000);
        let root = ws.path();
        for folder in ["01-rays", "02-hits", "03-lambert"] {
            save(root, chapter(folder), at(2_000), &passing());
        }
        let inputs = Inputs::scan(root);
        for folder in ["01-rays", "02-hits", "03-lambert"] {
            assert_eq!(
                inputs.unchanged_result(root, chapter(folder)),
                Some(passing()),
                "{folder}"
            );
        }
        // An edit in chapter 2 is an input of chapters 2 and 3, not of 1.
        write(root, "chapters/02-hits/src/lib.rs", 3_000);
        let inputs = Inputs::scan(root);
        assert!(inputs.unchanged_result(root, chapter("01-rays")).is_some());
        assert!(inputs.unchanged_result(root, chapter("02-hits")).is_none());
        assert!(
            inputs
                .unchanged_result(root, chapter("03-lambert"))
                .is_none()
        );
    }

    #[test]
    fn shared_files_removals_and_edits_during_the_run_count_a_top_level_picture_not() {
        let ws = workspace(1_000);
        let root = ws.path();
        save(root, chapter("01-rays"), at(2_000), &passing());
        write(root, "out.png", 3_000);
        assert!(
            Inputs::scan(root)
                .unchanged_result(root, chapter("01-rays"))
                .is_some()
        );
        write(root, "crates/workbench/src/lib.rs", 3_000);
        assert!(
            Inputs::scan(root)
                .unchanged_result(root, chapter("01-rays"))
                .is_none()
        );
        write(root, "crates/workbench/src/lib.rs", 1_000);
        write(root, "Cargo.lock", 3_000);
        assert!(
            Inputs::scan(root)
                .unchanged_result(root, chapter("01-rays"))
                .is_none()
        );

        let ws = workspace(1_000);
        let root = ws.path();
        save(root, chapter("03-lambert"), at(2_000), &passing());
        let snapshots = root.join("snapshots/03-lambert");
        fs::remove_file(snapshots.join("default.snap.png")).unwrap();
        set_time(&snapshots, 3_000);
        assert!(
            Inputs::scan(root)
                .unchanged_result(root, chapter("03-lambert"))
                .is_none()
        );

        // Saved while the run went on: the run started before the edit.
        let ws = workspace(1_000);
        let root = ws.path();
        write(root, "chapters/01-rays/src/lib.rs", 2_500);
        save(root, chapter("01-rays"), at(2_000), &passing());
        assert!(
            Inputs::scan(root)
                .unchanged_result(root, chapter("01-rays"))
                .is_none()
        );
    }

    #[test]
    fn the_last_result_says_whether_the_chapter_passed() {
        let ws = workspace(1_000);
        let root = ws.path();
        assert!(!passed_last_time(root, chapter("02-hits")));
        save(root, chapter("02-hits"), at(2_000), &passing());
        assert!(passed_last_time(root, chapter("02-hits")));
        let failing = TestOutput {
            failed: 1,
            ..passing()
        };
        save(root, chapter("02-hits"), at(2_000), &failing);
        assert!(!passed_last_time(root, chapter("02-hits")));
    }
}
