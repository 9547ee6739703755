//! A student's folder: is it a handout we can grade, what files does it
//! hold, what did the student change besides their own code, and a hash
//! of it all for the rerun cache.
//!
//! Nothing here writes into the student's folder: it is only listed and
//! read, and every read goes through one road (`sandbox/beneath.rs`): beneath the
//! folder, opened once, with no symlink anywhere on the way, a regular
//! file only, at most [`MOST_FILE`] bytes a file and [`MOST_TOTAL`] in all,
//! within [`MOST_TIME`]. A refusal is said in the grader's words, never by
//! quoting the file.

use std::collections::BTreeMap;
use std::hash::Hash;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};

use ignore::gitignore::{Gitignore, GitignoreBuilder};

use crate::build::digest::Digest;
use crate::judging::reference::Reference;
use crate::sandbox::beneath::{Folder, Kind, Refused, clean_line};
use workbook::handout::record::{RECORD_FILE, Record};

/// The most grading reads of one file of a student's folder: more than
/// the largest file of a handout (a scene of a few MiB).
pub const MOST_FILE: u64 = 16 << 20;

/// The most grading reads of a student's folder in all: a handout is
/// about 25 MiB.
pub const MOST_TOTAL: u64 = 256 << 20;

/// The longest reading a student's folder may take.
pub const MOST_TIME: Duration = Duration::from_secs(120);

/// The most entries a student's folder may hold.
const MOST_ENTRIES: usize = 100_000;

/// A student folder that can be graded.
#[derive(Debug, Clone)]
pub struct Submission {
    /// The folder's name: the student.
    pub name: String,
    /// Warnings about it that do not stop grading (another commit).
    pub warnings: Vec<String>,
    /// What in it grading refused to read (a link, a FIFO, a file too
    /// large): each is a flag of the student's result.
    pub flags: Vec<String>,
    /// The folder, opened once: every read is beneath it.
    folder: Arc<Folder>,
    /// When reading it must be done.
    by: Instant,
}

/// One entry of a student's folder, relative to it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Entry {
    /// A regular file of this many bytes.
    File(u64),
    /// A symlink, never followed.
    Link,
    /// A FIFO, a socket, a device: never opened. Its kind, in words.
    Other(&'static str),
}

impl Submission {
    /// The bytes of the student's file `path` (relative to their folder):
    /// a regular file, no link on the way, at most [`MOST_FILE`] bytes,
    /// within the folder's time.
    pub fn read(&self, path: &Path) -> Result<Vec<u8>, String> {
        (self.folder.read(path, MOST_FILE, self.by))
            .map_err(|why| format!("{}: {why}", shown(path)))
    }
}

/// A path of a student's as grading's messages show it (on one line).
pub fn shown(path: &Path) -> String {
    clean_line(&path.to_string_lossy())
}

/// Checks the entry `name` of the class folder `class`: a folder holding a
/// handout of the reference's version (`reference`). The error says why
/// not, for the teacher.
pub fn check(
    class: &Path,
    name: &str,
    (reference, sandboxed): (&Record, bool),
) -> Result<Submission, String> {
    let dir = class.join(name);
    let meta = std::fs::symlink_metadata(&dir).map_err(|e| format!("cannot read it: {e}"))?;
    if meta.file_type().is_symlink() {
        return Err(symlink_refusal(class, &dir));
    }
    if !meta.is_dir() {
        return Err("a file, not a folder: each student's handout is a folder".to_owned());
    }
    let folder = Folder::open(&dir).map_err(|_| "cannot open it as a folder".to_owned())?;
    if folder
        .entries()
        .map_err(|e| format!("cannot list it: {e}"))?
        .is_empty()
    {
        return Err("an empty folder: nothing was handed in".to_owned());
    }
    let is_file = |p: &str| matches!(folder.kind(Path::new(p)), Ok(Kind::File(_)));
    if !is_file("Cargo.toml") || !is_file("chapters/chapters.toml") {
        return Err(
            "not a raybook handout: no Cargo.toml and chapters/chapters.toml at its root"
                .to_owned(),
        );
    }
    let mut submission = Submission {
        name: name.to_owned(),
        warnings: Vec::new(),
        flags: Vec::new(),
        folder: Arc::new(folder),
        by: Instant::now() + MOST_TIME,
    };
    version_check(&mut submission, reference)?;
    if !sandboxed {
        (submission.warnings).push(crate::sandbox::bwrap::UNSANDBOXED.to_owned());
    }
    Ok(submission)
}

/// Why a symlinked student folder is not graded: it is never followed.
fn symlink_refusal(class: &Path, dir: &Path) -> String {
    let leads = std::fs::read_link(dir).unwrap_or_default();
    let inside = dir
        .canonicalize()
        .ok()
        .zip(class.canonicalize().ok())
        .is_some_and(|(to, class)| to.starts_with(class));
    if inside {
        format!(
            "a symlink to {}: not followed (the folder it leads to is graded under its own name)",
            shown(&leads)
        )
    } else {
        format!(
            "a symlink leading outside the class folder, to {}: never followed",
            shown(&leads)
        )
    }
}

/// Refuses a handout of another version; warns about one made from another
/// commit, or that does not say; flags a record that is not one the
/// `handout` command writes (a link, a FIFO, a device, something else),
/// which is never quoted, and grades the handout against the reference.
fn version_check(submission: &mut Submission, reference: &Record) -> Result<(), String> {
    let record = match submission.read(Path::new(RECORD_FILE)) {
        Ok(bytes) => std::str::from_utf8(&bytes)
            .ok()
            .and_then(|text| toml::from_str::<Record>(text).ok())
            .ok_or_else(|| format!("{RECORD_FILE}: not a record the handout command writes")),
        Err(why) => Err(why),
    };
    let record = match record {
        Ok(record) => record,
        Err(_)
            if matches!(
                submission.folder.kind(Path::new(RECORD_FILE)),
                Err(Refused::Missing)
            ) =>
        {
            submission.warnings.push(format!(
                "no {RECORD_FILE}: a handout from before handouts recorded their version; \
                 graded against {}",
                reference.label()
            ));
            return Ok(());
        }
        Err(why) => {
            submission.flags.push(format!(
                "the handout's record {why}; graded against {}",
                reference.label()
            ));
            return Ok(());
        }
    };
    if record.version != reference.version {
        return Err(format!(
            "a handout of raybook {} ({RECORD_FILE}), but the reference is {}: \
             grade it with a reference of its version (--reference)",
            clean_line(&record.version),
            reference.label()
        ));
    }
    if record.commit != reference.commit {
        submission.warnings.push(format!(
            "made from raybook {}, graded against {}",
            clean_line(&record.label()),
            reference.label()
        ));
    }
    Ok(())
}

/// The files of a student's folder, relative to it, without following a
/// symlink: everything but `.git/` and what the reference's `.gitignore`
/// leaves out (the student's `target/`, snapshot leftovers). A file over
/// [`MOST_FILE`], and any beyond [`MOST_TOTAL`] in all, are flagged and
/// left out (never read, never copied).
pub fn files(
    submission: &mut Submission,
    ignore: &Gitignore,
) -> Result<BTreeMap<PathBuf, Entry>, String> {
    let skip = |path: &Path, folder: bool| {
        path.file_name().is_some_and(|n| n == ".git") || ignore.matched(path, folder).is_ignore()
    };
    let walked =
        (submission.folder.walk(&skip, MOST_ENTRIES)).map_err(|why| format!("its files: {why}"))?;
    let mut found = BTreeMap::new();
    let mut total = 0u64;
    for (path, kind) in walked {
        let entry = match kind {
            Kind::File(size) if size > MOST_FILE => {
                let why = format!(
                    "{size} bytes, more than the {} MiB a file may hold",
                    MOST_FILE >> 20
                );
                submission
                    .flags
                    .push(format!("oversized file {}: {why}: not read", shown(&path)));
                continue;
            }
            Kind::File(size) if total + size > MOST_TOTAL => {
                submission.flags.push(format!(
                    "file {} beyond the {} MiB a handout may hold in all: not read",
                    shown(&path),
                    MOST_TOTAL >> 20
                ));
                continue;
            }
            Kind::File(size) => {
                total += size;
                Entry::File(size)
            }
            Kind::Link => Entry::Link,
            Kind::Other(what) => Entry::Other(what),
            Kind::Folder => continue,
        };
        found.insert(path, entry);
    }
    Ok(found)
}

/// The reference's `.gitignore`, applied to a student's folder.
pub fn ignore_rules(reference_root: &Path) -> Gitignore {
    let mut builder = GitignoreBuilder::new("");
    builder.add(reference_root.join(".gitignore"));
    // A student's own build folder, wherever the rules put it.
    let _ = builder.add_line(None, "/target");
    builder.build().unwrap_or_else(|_| Gitignore::empty())
}

/// A hash of a student's files (names, contents, and the other entries'
/// kinds, and what grading refused): the same as at the last run means
/// nothing changed. (Whether they are graded in the sandbox is in the
/// settings' part of the cache's key.)
pub fn hash_files(
    submission: &Submission,
    files: &BTreeMap<PathBuf, Entry>,
) -> Result<String, String> {
    let mut hasher = Digest::default();
    for (path, entry) in files {
        path.hash(&mut hasher);
        match entry {
            Entry::File(_) => submission.read(path)?.hash(&mut hasher),
            other => format!("{other:?}").hash(&mut hasher),
        }
    }
    submission.flags.hash(&mut hasher);
    Ok(hasher.hex())
}

/// What a student changed outside their own code, all of which grading
/// puts back from the reference: the `flags` (tests, pictures, the
/// manifest, Cargo files, build scripts: what changes the verdict; a file
/// the handout never held; what is not a file; sources that reach out)
/// and the `notes` (another of the reference's files edited or removed;
/// symlinks, never followed).
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct Changes {
    pub flags: Vec<String>,
    pub notes: Vec<String>,
}

/// Compares the student's files outside their own code with the
/// reference's.
pub fn changes(
    submission: &Submission,
    files: &BTreeMap<PathBuf, Entry>,
    reference: &Reference,
) -> Result<Changes, String> {
    let mut changes = Changes::default();
    // Flagged whatever the path: what reaches out, what is not a file,
    // what the handout never held.
    let mut flagged = Vec::new();
    let mut note = |path: &Path, what: &str| {
        let line = format!("{what} {}", shown(path));
        if is_protected(path) {
            changes.flags.push(line);
        } else {
            changes.notes.push(line);
        }
    };
    for (path, entry) in files {
        match entry {
            Entry::Link => {
                note(path, "symlink (not followed):");
                continue;
            }
            Entry::Other(what) => {
                flagged.push(format!("{what} at {}: never opened", shown(path)));
                continue;
            }
            Entry::File(_) => {}
        }
        if reference.is_students(path) {
            flagged.extend(reaching_out(submission, path)?);
            continue;
        }
        if path == Path::new(RECORD_FILE) {
            continue;
        }
        match reference.file(path) {
            // Not the reference's and not the student's own code: flagged,
            // since nothing of a handout's is there (never copied in).
            None => flagged.push(format!("added {}", shown(path))),
            Some(_) if path == Path::new("Cargo.lock") => {
                if !same_lock(&submission.read(path)?, &root_lock(reference))? {
                    note(path, "edited")
                }
            }
            Some(ours) if !same_bytes(submission, (path, entry), &ours)? => note(path, "edited"),
            Some(_) => {}
        }
    }
    for path in reference.files() {
        if !reference.is_students(path) && !files.contains_key(path) {
            note(path, "removed");
        }
    }
    changes.flags.extend(flagged);
    Ok(changes)
}

/// What one of the student's own files does to reach outside their folder
/// (`class/source_paths.rs`), or a build setting among their sources (a `build.rs`, a
/// Cargo file, a `.cargo/config`, a toolchain file: grading builds with
/// the reference's, but someone tried).
fn reaching_out(submission: &Submission, path: &Path) -> Result<Vec<String>, String> {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let setting = matches!(
        name,
        "build.rs" | "Cargo.toml" | "Cargo.lock" | "rust-toolchain" | "rust-toolchain.toml"
    ) || path.components().any(|c| c.as_os_str() == ".cargo");
    if setting {
        return Ok(vec![format!(
            "build setting among the student's sources: {} (not used: the build is the \
             reference's)",
            shown(path)
        )]);
    }
    if path.extension().is_none_or(|e| e != "rs") {
        return Ok(Vec::new());
    }
    let bytes = submission.read(path)?;
    // The chapter's folder: its sources read its README and scenes.
    let folder: PathBuf = path.components().take(2).collect();
    Ok(crate::class::source_paths::reaching(
        &String::from_utf8_lossy(&bytes),
        path,
        &folder,
    ))
}

/// The reference's lock file as its root holds it (the base copy's is the
/// one cargo rewrote there).
fn root_lock(reference: &Reference) -> PathBuf {
    reference.root.join("Cargo.lock")
}

/// Are two lock files the same but for the teacher's packages (`grade`,
/// `grade-probe`), which cargo drops from a handout's lock on its first
/// build, since a handout holds neither?
fn same_lock(theirs: &[u8], reference: &Path) -> Result<bool, String> {
    let ours = std::fs::read_to_string(reference)
        .map_err(|e| format!("cannot read {}: {e}", reference.display()))?;
    let Ok(theirs) = std::str::from_utf8(theirs) else {
        return Ok(false);
    };
    let without = workbook::workspace::lock_without_teacher;
    Ok(without(theirs) == without(&ours))
}

/// Do the student's file and the reference's hold the same bytes? Sizes
/// first, so that a file of another size is never read.
fn same_bytes(
    submission: &Submission,
    (path, entry): (&Path, &Entry),
    reference: &Path,
) -> Result<bool, String> {
    let size = std::fs::metadata(reference).map(|m| m.len()).ok();
    if size.map(Entry::File).as_ref() != Some(entry) {
        return Ok(false);
    }
    let ours = std::fs::read(reference)
        .map_err(|e| format!("cannot read {}: {e}", reference.display()))?;
    Ok(submission.read(path)? == ours)
}

/// Is this one of the files whose edit changes a verdict: a test, a
/// reference picture, the manifest, a Cargo file, a build script?
pub fn is_protected(path: &Path) -> bool {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let in_tests = path.components().any(|c| c.as_os_str() == "tests");
    in_tests
        || path.starts_with("snapshots")
        || path == Path::new("chapters/chapters.toml")
        || matches!(
            name,
            "Cargo.toml" | "Cargo.lock" | "build.rs" | "rust-toolchain" | "rust-toolchain.toml"
        )
        || path.components().any(|c| c.as_os_str() == ".cargo")
}

#[cfg(test)]
#[path = "submission_tests.rs"]
mod tests;
