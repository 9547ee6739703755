//! Which chapter the student edited since progress last ran, so that its
//! verdict comes first: the chapters after it depend on it, and building
//! and testing them takes several times as long.

use std::collections::HashMap;
use std::fs;
use std::hash::{DefaultHasher, Hasher};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

use crate::workbench::chapters::ChapterEntry;

/// The file whose modification time marks progress's last run.
fn stamp_path(root: &Path) -> PathBuf {
    root.join("target/workbook/progress.stamp")
}

/// The file that keeps a digest of the content of every file of the
/// chapters at progress's last run: a file saved since with the same
/// content (an edit undone) is no edit.
fn digests_path(root: &Path) -> PathBuf {
    root.join("target/workbook/progress.digests")
}

/// When progress last ran in the workspace at `root`, if it has.
pub fn last_run(root: &Path) -> Option<SystemTime> {
    fs::metadata(stamp_path(root)).ok()?.modified().ok()
}

/// Marks now as progress's last run, with the content of the files of
/// `chapters` as it is now (silently skipped if it cannot).
pub fn stamp(root: &Path, chapters: &[&ChapterEntry]) {
    let path = stamp_path(root);
    if let Some(dir) = path.parent() {
        let _ = fs::create_dir_all(dir);
    }
    let _ = fs::write(path, b"");
    let mut text = String::new();
    for chapter in chapters {
        for (file, _) in files_in(&root.join(chapter.path())) {
            if let Some(digest) = digest(&file) {
                text += &format!("{digest:016x} {}\n", file.display());
            }
        }
    }
    let partial = digests_path(root).with_extension("partial");
    if fs::write(&partial, text).is_ok() {
        let _ = fs::rename(&partial, digests_path(root));
    }
}

/// The content digests kept by the last [`stamp`], by file.
fn last_digests(root: &Path) -> HashMap<PathBuf, u64> {
    let text = fs::read_to_string(digests_path(root)).unwrap_or_default();
    text.lines()
        .filter_map(|line| {
            let (digest, file) = line.split_once(' ')?;
            Some((PathBuf::from(file), u64::from_str_radix(digest, 16).ok()?))
        })
        .collect()
}

/// A digest of the content of `file` (std's SipHash: the same for the
/// same bytes with one toolchain; after an update every file merely
/// counts as edited once).
fn digest(file: &Path) -> Option<u64> {
    let bytes = fs::read(file).ok()?;
    let mut hasher = DefaultHasher::new();
    hasher.write(&bytes);
    Some(hasher.finish())
}

/// Of `chapters`, the one edited last since `since`: whose content
/// changed (a file saved with other content, made, or removed) most
/// recently. A file saved again with the content it had at the last run
/// is no edit. With several chapters edited, the one saved last comes
/// first: it is the one the student is working on.
pub fn last_changed<'a>(
    root: &Path,
    chapters: &[&'a ChapterEntry],
    since: SystemTime,
) -> Option<&'a ChapterEntry> {
    let before = last_digests(root);
    let edited_at = |chapter: &ChapterEntry| {
        let dir = root.join(chapter.path());
        let files = files_in(&dir);
        let changed = files
            .iter()
            // `>=`: a save in the same tick of the file system's coarse
            // clock as the last run's stamp has the same time; the digest
            // decides then.
            .filter(|(file, time)| *time >= since && before.get(file).copied() != digest(file));
        let newest = changed.map(|(_, time)| *time).max();
        // A file of the last run that is gone: the chapter changed when
        // the folder that held it did.
        let removed = (before.keys())
            .filter(|file| file.starts_with(&dir) && !files.iter().any(|(f, _)| f == *file))
            .filter_map(|file| modified(file.parent()?))
            .max();
        newest.max(removed)
    };
    let times = chapters.iter().map(|c| (edited_at(c), *c));
    times
        .filter(|(t, _)| t.is_some())
        .max_by_key(|(t, _)| *t)
        .map(|(_, c)| c)
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

/// The files under `dir` (hidden ones left out) and their modification times.
fn files_in(dir: &Path) -> Vec<(PathBuf, SystemTime)> {
    let mut files = Vec::new();
    for entry in fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if entry.file_name().to_string_lossy().starts_with('.') {
            continue;
        }
        if path.is_dir() {
            files.extend(files_in(&path));
        } else if let Some(time) = modified(&path) {
            files.push((path, time));
        }
    }
    files
}

/// When `path` was last modified.
fn modified(path: &Path) -> Option<SystemTime> {
    fs::metadata(path).ok()?.modified().ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workbench::chapters;
    use std::time::Duration;

    #[test]
    fn the_chapter_whose_content_changed_last_is_the_edited_one() {
        let root = tempfile::tempdir().unwrap();
        let root = root.path();
        let steps: Vec<_> = ["01-rays", "02-hits", "03-lambert"]
            .iter()
            .map(|f| chapters::find(f).unwrap())
            .collect();
        let at = |secs| SystemTime::UNIX_EPOCH + Duration::from_secs(secs);
        let write = |chapter: &ChapterEntry, text: &str, secs| {
            let file = root.join(chapter.path()).join("src/lib.rs");
            fs::create_dir_all(file.parent().unwrap()).unwrap();
            fs::write(&file, text).unwrap();
            fs::File::options()
                .write(true)
                .open(&file)
                .unwrap()
                .set_modified(at(secs))
                .unwrap();
            file
        };
        for chapter in &steps {
            write(chapter, "fn f() {}", 1_000);
        }
        stamp(root, &steps);
        let since = at(2_000);
        assert!(last_changed(root, &steps, since).is_none());
        // Saved again with the same content: no edit.
        write(steps[0], "fn f() {}", 3_000);
        assert!(last_changed(root, &steps, since).is_none());
        // Chapter 1 edited, then chapter 3, then chapter 2: the last saved
        // comes first, whatever the chapters' order.
        write(steps[0], "fn f() { 1 }", 3_000);
        write(steps[2], "fn f() { 3 }", 4_000);
        let edited = write(steps[1], "fn f() { 2 }", 5_000);
        assert_eq!(last_changed(root, &steps, since).unwrap().folder, "02-hits");
        // Chapter 2's edit undone: chapter 3 is the last edited.
        write(steps[1], "fn f() {}", 6_000);
        assert_eq!(
            last_changed(root, &steps, since).unwrap().folder,
            "03-lambert"
        );
        assert_eq!(chapter_of(root, &steps, &edited).unwrap().folder, "02-hits");
    }
}
