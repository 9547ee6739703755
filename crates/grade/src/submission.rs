//! A student's folder: is it a handout we can grade, what files does it
//! hold (read without following a symlink), what did the student change
//! besides their own code, and a hash of it all for the rerun cache.
//!
//! Nothing here writes into the student's folder: it is only listed and
//! read.

use std::collections::BTreeMap;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};

use ignore::gitignore::{Gitignore, GitignoreBuilder};

use super::digest::Digest;
use super::reference::Reference;
use crate::handout::record::{RECORD_FILE, Record};

/// A student folder that can be graded.
#[derive(Debug, Clone)]
pub struct Submission {
    /// The folder's name: the student.
    pub name: String,
    /// The folder.
    pub dir: PathBuf,
    /// Warnings about it that do not stop grading (another commit).
    pub warnings: Vec<String>,
}

/// One entry of a student's folder, relative to it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Entry {
    /// A regular file.
    File,
    /// A symlink, never followed: where it leads.
    Link(PathBuf),
}

/// Checks the entry `name` of the class folder `class`: a folder holding a
/// handout of the reference's version (`reference`). The error says why
/// not, for the teacher.
pub fn check(class: &Path, name: &str, reference: &Record) -> Result<Submission, String> {
    let dir = class.join(name);
    let meta = std::fs::symlink_metadata(&dir).map_err(|e| format!("cannot read it: {e}"))?;
    if meta.file_type().is_symlink() {
        return Err(symlink_refusal(class, &dir));
    }
    if !meta.is_dir() {
        return Err("a file, not a folder: each student's handout is a folder".to_owned());
    }
    let mut entries = std::fs::read_dir(&dir).map_err(|e| format!("cannot list it: {e}"))?;
    if entries.next().is_none() {
        return Err("an empty folder: nothing was handed in".to_owned());
    }
    if !dir.join("Cargo.toml").is_file() || !dir.join("chapters/chapters.toml").is_file() {
        return Err(
            "not a raybook handout: no Cargo.toml and chapters/chapters.toml at its root"
                .to_owned(),
        );
    }
    let mut warnings = version_warnings(&dir, reference)?;
    if super::confine::unsandboxed() {
        warnings.push(super::confine::UNSANDBOXED.to_owned());
    }
    Ok(Submission {
        name: name.to_owned(),
        dir,
        warnings,
    })
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
            leads.display()
        )
    } else {
        format!(
            "a symlink leading outside the class folder, to {}: never followed",
            leads.display()
        )
    }
}

/// Refuses a handout of another version; warns about one made from another
/// commit, or that does not say.
fn version_warnings(dir: &Path, reference: &Record) -> Result<Vec<String>, String> {
    let Some(record) = Record::read(dir)? else {
        return Ok(vec![format!(
            "no {RECORD_FILE}: a handout from before handouts recorded their version; \
             graded against {}",
            reference.label()
        )]);
    };
    if record.version != reference.version {
        return Err(format!(
            "a handout of raybook {} ({RECORD_FILE}), but the reference is {}: \
             grade it with a reference of its version (--reference)",
            record.version,
            reference.label()
        ));
    }
    if record.commit != reference.commit {
        return Ok(vec![format!(
            "made from raybook {}, graded against {}",
            record.label(),
            reference.label()
        )]);
    }
    Ok(Vec::new())
}

/// The files of a student's folder, relative to it, without following a
/// symlink: everything but `.git/` and what the reference's `.gitignore`
/// leaves out (the student's `target/`, snapshot leftovers).
pub fn files(dir: &Path, ignore: &Gitignore) -> Result<BTreeMap<PathBuf, Entry>, String> {
    let mut found = BTreeMap::new();
    let mut folders = vec![PathBuf::new()];
    while let Some(folder) = folders.pop() {
        let path = dir.join(&folder);
        let entries =
            std::fs::read_dir(&path).map_err(|e| format!("cannot list {}: {e}", path.display()))?;
        for entry in entries {
            let entry = entry.map_err(|e| format!("cannot list {}: {e}", path.display()))?;
            let relative = folder.join(entry.file_name());
            let kind = entry.file_type().map_err(|e| format!("{e}"))?;
            if entry.file_name() == ".git" || ignore.matched(&relative, kind.is_dir()).is_ignore() {
                continue;
            }
            if kind.is_symlink() {
                let to = std::fs::read_link(entry.path()).unwrap_or_default();
                found.insert(relative, Entry::Link(to));
            } else if kind.is_dir() {
                folders.push(relative);
            } else if kind.is_file() {
                found.insert(relative, Entry::File);
            }
        }
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

/// A hash of a student's files (names, contents, where symlinks lead), and
/// of whether they are graded in the sandbox: the same as at the last run
/// means nothing changed (and a result graded without the sandbox is never
/// taken for one graded in it).
pub fn hash_files(dir: &Path, files: &BTreeMap<PathBuf, Entry>) -> Result<String, String> {
    let mut hasher = Digest::default();
    super::confine::unsandboxed().hash(&mut hasher);
    for (path, entry) in files {
        path.hash(&mut hasher);
        match entry {
            Entry::File => hash_file(&dir.join(path), &mut hasher)
                .map_err(|e| format!("cannot read {}: {e}", path.display()))?,
            Entry::Link(to) => to.hash(&mut hasher),
        }
    }
    Ok(hasher.hex())
}

/// Feeds a file's bytes and length to `hasher`, a piece at a time (a
/// student's folder may hold a file of gigabytes).
fn hash_file(path: &Path, hasher: &mut impl Hasher) -> std::io::Result<()> {
    use std::io::Read;
    let mut file = std::fs::File::open(path)?;
    let mut chunk = vec![0u8; 1 << 16];
    let mut length = 0u64;
    loop {
        let n = file.read(&mut chunk)?;
        if n == 0 {
            hasher.write_u64(length);
            return Ok(());
        }
        hasher.write(&chunk[..n]);
        length += n as u64;
    }
}

/// What a student changed outside their own code, all of which grading
/// puts back from the reference: the `flags` (tests, pictures, the
/// manifest, Cargo files, build scripts: what changes the verdict) and
/// the `notes` (any other file; symlinks, never followed).
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct Changes {
    pub flags: Vec<String>,
    pub notes: Vec<String>,
}

/// Compares the student's files outside their own code with the
/// reference's.
pub fn changes(
    dir: &Path,
    files: &BTreeMap<PathBuf, Entry>,
    reference: &Reference,
) -> Result<Changes, String> {
    let mut changes = Changes::default();
    let mut reaching = Vec::new();
    let mut note = |path: &Path, what: &str| {
        let line = format!("{what} {}", path.display());
        if is_protected(path) {
            changes.flags.push(line);
        } else {
            changes.notes.push(line);
        }
    };
    for (path, entry) in files {
        if let Entry::Link(to) = entry {
            note(
                path,
                &format!("symlink (to {}, not followed):", to.display()),
            );
            continue;
        }
        if reference.is_students(path) {
            reaching.extend(reaching_out(dir, path)?);
            continue;
        }
        if path == Path::new(RECORD_FILE) {
            continue;
        }
        match reference.file(path) {
            None => note(path, "added"),
            Some(_) if path == Path::new("Cargo.lock") => {
                if !same_lock(&dir.join(path), &root_lock(reference))? {
                    note(path, "edited")
                }
            }
            Some(theirs) if !same_bytes(&dir.join(path), &theirs)? => note(path, "edited"),
            Some(_) => {}
        }
    }
    for path in reference.files() {
        if !reference.is_students(path) && !files.contains_key(path) {
            note(path, "removed");
        }
    }
    changes.flags.extend(reaching);
    Ok(changes)
}

/// What one of the student's own files does to reach outside their folder
/// (`reach.rs`), or a build setting among their sources (a `build.rs`, a
/// Cargo file, a `.cargo/config`, a toolchain file: grading builds with
/// the reference's, but someone tried).
fn reaching_out(dir: &Path, path: &Path) -> Result<Vec<String>, String> {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let setting = matches!(
        name,
        "build.rs" | "Cargo.toml" | "Cargo.lock" | "rust-toolchain" | "rust-toolchain.toml"
    ) || path.components().any(|c| c.as_os_str() == ".cargo");
    if setting {
        return Ok(vec![format!(
            "build setting among the student's sources: {} (not used: the build is the \
             reference's)",
            path.display()
        )]);
    }
    if path.extension().is_none_or(|e| e != "rs") {
        return Ok(Vec::new());
    }
    let bytes = std::fs::read(dir.join(path))
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    // The chapter's folder: its sources read its README and scenes.
    let folder: PathBuf = path.components().take(2).collect();
    Ok(super::reach::reaching(
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
fn same_lock(theirs: &Path, reference: &Path) -> Result<bool, String> {
    let read = |p: &Path| {
        std::fs::read_to_string(p).map_err(|e| format!("cannot read {}: {e}", p.display()))
    };
    let size = std::fs::metadata(theirs).map(|m| m.len()).unwrap_or(0);
    if size > 4 << 20 {
        return Ok(false);
    }
    let without = |text: String| workbook::workspace::lock_without_teacher(&text);
    Ok(without(read(theirs)?) == without(read(reference)?))
}

/// Do the student's file and the reference's hold the same bytes? Sizes
/// first, so that a huge file is never read.
fn same_bytes(theirs: &Path, reference: &Path) -> Result<bool, String> {
    let size = |p: &Path| std::fs::metadata(p).map(|m| m.len()).ok();
    if size(theirs) != size(reference) {
        return Ok(false);
    }
    let read = |p: &Path| std::fs::read(p).map_err(|e| format!("cannot read {}: {e}", p.display()));
    Ok(read(theirs)? == read(reference)?)
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
mod tests {
    use super::*;

    fn record(version: &str, commit: &str) -> Record {
        Record {
            version: version.to_owned(),
            commit: commit.to_owned(),
            modified: false,
        }
    }

    #[test]
    fn what_is_not_a_handout_of_this_version_is_refused_with_its_reason() {
        let class = tempfile::tempdir().unwrap();
        let root = class.path();
        let reference = record("0.1.0", "abc");
        let refused = |name: &str| check(root, name, &reference).unwrap_err();
        std::fs::create_dir(root.join("empty")).unwrap();
        assert!(refused("empty").contains("an empty folder"));
        std::fs::write(root.join("notes.txt"), "x").unwrap();
        assert!(refused("notes.txt").contains("a file, not a folder"));
        std::os::unix::fs::symlink("/etc", root.join("away")).unwrap();
        assert!(refused("away").contains("leading outside the class folder"));
        std::os::unix::fs::symlink(root.join("empty"), root.join("alias")).unwrap();
        assert!(refused("alias").contains("graded under its own name"));
        std::fs::create_dir_all(root.join("essay")).unwrap();
        std::fs::write(root.join("essay/essay.md"), "x").unwrap();
        assert!(refused("essay").contains("not a raybook handout"));

        let handout = root.join("handout");
        std::fs::create_dir_all(handout.join("chapters")).unwrap();
        std::fs::write(handout.join("Cargo.toml"), "").unwrap();
        std::fs::write(handout.join("chapters/chapters.toml"), "").unwrap();
        let graded = check(root, "handout", &reference).unwrap();
        assert!(graded.warnings[0].contains("no .raybook-handout.toml"));
        record("0.1.0", "def").write(&handout).unwrap();
        let graded = check(root, "handout", &reference).unwrap();
        assert!(graded.warnings[0].contains("made from raybook 0.1.0 @ def"));
        record("0.1.0", "abc").write(&handout).unwrap();
        assert!(
            check(root, "handout", &reference)
                .unwrap()
                .warnings
                .is_empty()
        );
        record("0.2.0", "abc").write(&handout).unwrap();
        assert!(refused("handout").contains("a handout of raybook 0.2.0"));
    }

    #[test]
    fn tests_pictures_and_cargo_files_are_protected_and_a_readme_is_not() {
        for protected in [
            "chapters/02-hits/tests/chapter02/spheres.rs",
            "snapshots/01-rays/default.snap.png",
            "chapters/chapters.toml",
            "Cargo.lock",
            "chapters/01-rays/Cargo.toml",
            "chapters/01-rays/build.rs",
            ".cargo/config.toml",
            "chapters/01-rays/.cargo/config",
        ] {
            assert!(is_protected(Path::new(protected)), "{protected}");
        }
        assert!(!is_protected(Path::new("chapters/01-rays/README.md")));
        assert!(!is_protected(Path::new("crates/workbench/src/snapshot.rs")));
    }

    #[test]
    fn the_digest_sees_every_byte_and_is_the_same_twice() {
        let digest = |text: &str| {
            let mut d = Digest::default();
            text.hash(&mut d);
            d.hex()
        };
        assert_eq!(digest("abc"), digest("abc"));
        assert_ne!(digest("abc"), digest("abd"));
        assert_eq!(digest("abc").len(), 32);
    }

    #[test]
    fn files_are_listed_without_following_symlinks_or_entering_ignored_folders() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("chapters/01-rays/src")).unwrap();
        std::fs::create_dir_all(root.join("target/debug")).unwrap();
        std::fs::write(root.join("chapters/01-rays/src/lib.rs"), "fn f() {}").unwrap();
        std::fs::write(root.join("target/debug/x"), "built").unwrap();
        std::os::unix::fs::symlink("/etc", root.join("chapters/etc")).unwrap();
        let listed = files(root, &ignore_rules(Path::new("/nonexistent"))).unwrap();
        let expected = BTreeMap::from([
            (PathBuf::from("chapters/01-rays/src/lib.rs"), Entry::File),
            (PathBuf::from("chapters/etc"), Entry::Link("/etc".into())),
        ]);
        assert_eq!(listed, expected);
    }
}
