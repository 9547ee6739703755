//! What the grading tests and the class benchmark share: a still snapshot
//! of the reference, handouts made from it, the `grade` command,
//! the gradebook read back, and a fingerprint of a class folder.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A gradebook row: column → cell.
pub type Row = BTreeMap<String, String>;

/// Copies the workspace's files (the teacher's included) to `dir`: a
/// reference that stays as it is while others edit the workspace.
pub fn snapshot_reference(dir: &Path) -> PathBuf {
    let root = workbook::workbench::snapshot::workspace_root();
    for file in workbook::handout::workspace_files(&root).unwrap() {
        let to = dir.join(&file);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(root.join(&file), &to).unwrap();
    }
    dir.canonicalize().unwrap()
}

/// `workbook handout --solved-through N DIR`, made from `reference`
/// (the library call, which prints what the command prints).
pub fn handout(reference: &Path, dir: &Path, solved_through: u32) {
    workbook::handout::write_handout_from(reference, dir, solved_through).unwrap();
}

/// `grade ARGS --reference R --out OUT --chapters 1-3`: what it
/// printed (stdout, then stderr). Panics if it fails.
pub fn grade(reference: &Path, out: &Path, args: &[&OsStr]) -> String {
    grade_chapters(reference, out, args, "1-3")
}

/// [`grade`] of the `chapters` given.
pub fn grade_chapters(reference: &Path, out: &Path, args: &[&OsStr], chapters: &str) -> String {
    let mut all = args.to_vec();
    all.extend(["--reference".as_ref(), reference.as_os_str()]);
    all.extend(["--out".as_ref(), out.as_os_str(), "--chapters".as_ref()]);
    all.push(chapters.as_ref());
    run_grade(&all)
}

/// The `grade` binary with `args`: what it printed (stdout, then stderr).
/// Panics if it fails.
pub fn run_grade(args: &[&OsStr]) -> String {
    let run = Command::new(env!("CARGO_BIN_EXE_grade"))
        .args(args)
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(run.status.success(), "grade {args:?} failed:\n{text}");
    text
}

/// The gradebook's rows, by student.
pub fn read_csv(path: &Path) -> BTreeMap<String, Row> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut records = records(&text).into_iter();
    let header = records.next().expect("a header");
    records
        .map(|cells| {
            let row: Row = header.iter().cloned().zip(cells).collect();
            (row["student"].clone(), row)
        })
        .collect()
}

/// The records of a CSV text (RFC 4180: quoted fields, doubled quotes).
fn records(text: &str) -> Vec<Vec<String>> {
    let (mut records, mut record, mut field) = (Vec::new(), Vec::new(), String::new());
    let (mut quoted, mut chars) = (false, text.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            ('"', _) => quoted = !quoted,
            (',', false) => record.push(std::mem::take(&mut field)),
            ('\r', false) => {}
            ('\n', false) => {
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
            }
            (c, _) => field.push(c),
        }
    }
    records
}

/// Every entry under `dir` (symlinks not followed): its path, kind, mode,
/// modification time, and its bytes' hash (a regular file up to 64 MiB),
/// its kind and size (anything else), or where it leads.
pub fn class_fingerprint(dir: &Path) -> Vec<String> {
    use std::hash::{Hash, Hasher};
    let mut found = Vec::new();
    let mut folders = vec![dir.to_owned()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            let meta = std::fs::symlink_metadata(&path).unwrap();
            let what = if meta.is_symlink() {
                format!("-> {}", std::fs::read_link(&path).unwrap().display())
            } else if meta.is_dir() {
                folders.push(path.clone());
                "dir".to_owned()
            } else if !meta.is_file() || meta.len() > 64 << 20 {
                // A FIFO would block a read, a sparse gigabyte is slow:
                // their kind, size and time say whether they changed.
                format!("{:?} {} bytes", meta.file_type(), meta.len())
            } else {
                let mut hasher = std::hash::DefaultHasher::new();
                std::fs::read(&path).unwrap().hash(&mut hasher);
                format!("{:x}", hasher.finish())
            };
            let modified = (meta.mtime(), meta.mtime_nsec());
            let relative = path.strip_prefix(dir).unwrap().display().to_string();
            found.push(format!("{relative} {what} {:o} {modified:?}", meta.mode()));
        }
    }
    found.sort();
    found
}
