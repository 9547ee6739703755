//! Which chapter the student edited since progress last ran, so that its
//! verdict comes first: the chapters after it depend on it, and building
//! and testing them takes several times as long.

use std::fs;
use std::path::Path;
use std::time::SystemTime;

use crate::workbench::chapters::ChapterEntry;

/// The file whose modification time marks progress's last run.
fn stamp_path(root: &Path) -> std::path::PathBuf {
    root.join("target/workbook/progress.stamp")
}

/// When progress last ran in the workspace at `root`, if it has.
pub fn last_run(root: &Path) -> Option<SystemTime> {
    fs::metadata(stamp_path(root)).ok()?.modified().ok()
}

/// Marks now as progress's last run (silently skipped if it cannot).
pub fn stamp(root: &Path) {
    let path = stamp_path(root);
    if let Some(dir) = path.parent() {
        let _ = fs::create_dir_all(dir);
    }
    let _ = fs::write(path, b"");
}

/// The first of `chapters` with a file under its folder changed after
/// `since`: the one an edit affects first.
pub fn first_changed<'a>(
    root: &Path,
    chapters: &[&'a ChapterEntry],
    since: SystemTime,
) -> Option<&'a ChapterEntry> {
    let changed = |c: &&&ChapterEntry| newest_in(&root.join(c.path())).is_some_and(|t| t > since);
    chapters.iter().find(changed).copied()
}

/// The chapter (of `chapters`) that holds `path`, a file under `root`.
pub fn chapter_of<'a>(
    root: &Path,
    chapters: &[&'a ChapterEntry],
    path: &Path,
) -> Option<&'a ChapterEntry> {
    let relative = path.strip_prefix(root).unwrap_or(path);
    chapters
        .iter()
        .find(|c| relative.starts_with(c.path()))
        .copied()
}

/// The newest modification time of the files under `dir`.
fn newest_in(dir: &Path) -> Option<SystemTime> {
    let mut newest = None;
    for entry in fs::read_dir(dir).ok()?.flatten() {
        let path = entry.path();
        let time = if path.is_dir() {
            newest_in(&path)
        } else {
            entry.metadata().ok().and_then(|m| m.modified().ok())
        };
        newest = newest.max(time);
    }
    newest
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workbench::chapters;

    #[test]
    fn the_first_chapter_changed_since_a_time_is_found() {
        let root = std::env::temp_dir().join(format!("progress-edited-{}", std::process::id()));
        let steps: Vec<_> = ["01-rays", "02-hits", "03-lambert"]
            .iter()
            .map(|f| chapters::find(f).unwrap())
            .collect();
        let at = |secs| SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(secs);
        let write = |chapter: &ChapterEntry, secs| {
            let file = root.join(chapter.path()).join("src/lib.rs");
            fs::create_dir_all(file.parent().unwrap()).unwrap();
            fs::File::create(&file)
                .unwrap()
                .set_modified(at(secs))
                .unwrap();
            file
        };
        for chapter in &steps {
            write(chapter, 1_000);
        }
        assert!(first_changed(&root, &steps, at(2_000)).is_none());
        let edited = write(steps[1], 3_000);
        assert_eq!(
            first_changed(&root, &steps, at(2_000)).unwrap().folder,
            "02-hits"
        );
        assert_eq!(
            first_changed(&root, &steps, at(500)).unwrap().folder,
            "01-rays"
        );
        assert_eq!(
            chapter_of(&root, &steps, &edited).unwrap().folder,
            "02-hits"
        );
        fs::remove_dir_all(&root).unwrap();
    }
}
