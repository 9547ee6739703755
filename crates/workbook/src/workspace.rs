//! The workspace's files, and a copy of them with exercises taken out.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::regions::{Region, regions, replace_bodies};

/// The workspace that holds the current folder, or an error saying so.
pub fn current_workspace() -> Result<PathBuf, String> {
    let here = std::env::current_dir().map_err(|e| format!("no current folder: {e}"))?;
    workspace_root(&here)
}

/// The root of the cargo workspace that holds `start`, as `cargo metadata`
/// tells it.
pub fn workspace_root(start: &Path) -> Result<PathBuf, String> {
    let metadata = cargo_metadata::MetadataCommand::new()
        .current_dir(start)
        .no_deps()
        .exec()
        .map_err(|e| {
            format!(
                "{} is not inside the raybook workspace: {e}",
                start.display()
            )
        })?;
    Ok(metadata.workspace_root.into_std_path_buf())
}

/// The workspace's files, relative to `root`, in order: every file but what
/// its `.gitignore` files leave out (`target/`, review leftovers) and `.git/`.
/// Untracked new files come along, with or without git.
pub fn workspace_files(root: &Path) -> Result<Vec<PathBuf>, String> {
    let walk = ignore::WalkBuilder::new(root)
        .hidden(false)
        .parents(false)
        .require_git(false)
        .filter_entry(|entry| entry.file_name() != ".git")
        .build();
    let mut files = BTreeSet::new();
    for entry in walk {
        let entry = entry.map_err(|e| format!("cannot list {}: {e}", root.display()))?;
        if entry.file_type().is_some_and(|t| t.is_file()) {
            let relative = entry.path().strip_prefix(root).expect("below the root");
            files.insert(relative.to_owned());
        }
    }
    Ok(files.into_iter().collect())
}

/// May the file (relative to the root) hold exercise regions? The Rust
/// sources of the chapters do; the tools' own code under src/ and tests/
/// shows markers in examples and is left alone.
pub fn holds_exercises(file: &Path) -> bool {
    file.starts_with("chapters") && file.extension().is_some_and(|e| e == "rs")
}

/// What [`write_tree`] did.
#[derive(Debug, Default)]
pub struct Written {
    /// Files in the copy.
    pub files: usize,
    /// Files written because they were missing or differed.
    pub changed: usize,
    /// The regions taken out, with the file (relative to the root) and the
    /// line of the opening marker (from 1) in the copy.
    pub regions: Vec<(PathBuf, usize, Region)>,
}

/// Files that hold solutions and stay with the teacher: each chapter's
/// `mistakes.toml` (its classic mistakes are the solutions with one change,
/// and its `[[lecture]]` entries the lecture's own solutions), and the
/// grader (`crates/grade`: its fixture writes solutions, and grading is
/// not the student's tool) and its probe (`crates/grade-probe`: how the
/// grader draws the inputs it judges on), and `.github/`: the teacher's own
/// workflows (such as grading the class in slices), which a student's
/// repository must not get. The maintainers' checks read them from the
/// reference.
pub fn teacher_only(file: &Path) -> bool {
    let mistakes = file.starts_with("chapters")
        && file.file_name().is_some_and(|name| name == "mistakes.toml");
    let teacher = [GRADER, PROBE, ".github"];
    mistakes || teacher.iter().any(|folder| file.starts_with(folder))
}

/// The teacher's grader, which no handout holds.
pub const GRADER: &str = "crates/grade";

/// The grader's probe, which no handout holds either: the grader copies it
/// into each student's copy itself.
pub const PROBE: &str = "crates/grade-probe";

/// A lock file without the teacher's packages (`grade`, `grade-probe`):
/// what cargo itself writes in a workspace that holds neither. A handout
/// ships it so, so that its first build does not rewrite the lock (which
/// the grader would take for an edit).
pub fn lock_without_teacher(lock: &str) -> String {
    let teacher = ["name = \"grade\"\n", "name = \"grade-probe\"\n"];
    let blocks = lock.split("\n[[package]]\n");
    let kept = blocks.filter(|b| !teacher.iter().any(|t| b.starts_with(t)));
    kept.collect::<Vec<_>>().join("\n[[package]]\n")
}

/// Copies the workspace at `root` into `dir`, without the files that are
/// [`teacher_only`], and with the selected exercise regions of every `.rs`
/// file taken out (see [`crate::regions::hand_out`]).
///
/// A file already in `dir` with the same content is left alone, so that
/// cargo sees it unchanged and does not rebuild it: writing variants of a
/// handout into one folder one after the other rebuilds only what differs.
pub fn write_tree(
    root: &Path,
    dir: &Path,
    select: impl Fn(&Region) -> bool,
) -> Result<Written, String> {
    write_tree_with(root, dir, |r| select(r).then(|| r.todo_line()))
}

/// [`write_tree`] with each region's new body given by `body` (see
/// [`replace_bodies`]): None keeps the reference's.
pub fn write_tree_with(
    root: &Path,
    dir: &Path,
    body: impl Fn(&Region) -> Option<String>,
) -> Result<Written, String> {
    let mut written = Written::default();
    let mut ids = BTreeSet::new();
    for file in workspace_files(root)? {
        if teacher_only(&file) {
            continue;
        }
        let from = root.join(&file);
        let bytes = std::fs::read(&from).map_err(|e| format!("{}: {e}", from.display()))?;
        let bytes = if file == Path::new("Cargo.lock") {
            lock_without_teacher(&String::from_utf8_lossy(&bytes)).into_bytes()
        } else if holds_exercises(&file) {
            let (out, replaced) = replace_in_file(&file, bytes, &mut ids, &body)?;
            written.regions.extend(replaced);
            out
        } else {
            bytes
        };
        written.files += 1;
        if write_if_changed(&dir.join(&file), &bytes)? {
            written.changed += 1;
        }
    }
    Ok(written)
}

/// A region with its file (relative to the root) and the line of its
/// opening marker (from 1).
pub type Located = (PathBuf, usize, Region);

/// A chapter source with its regions' bodies replaced, and the replaced
/// regions as they stand in the new text. Checks that ids are unique.
fn replace_in_file(
    file: &Path,
    bytes: Vec<u8>,
    ids: &mut BTreeSet<String>,
    body: &impl Fn(&Region) -> Option<String>,
) -> Result<(Vec<u8>, Vec<Located>), String> {
    let source =
        String::from_utf8(bytes).map_err(|e| format!("{}: not UTF-8: {e}", file.display()))?;
    let found = regions(&source).map_err(|e| format!("{}: {e}", file.display()))?;
    let mut chosen = BTreeSet::new();
    for region in &found {
        if !ids.insert(region.id.clone()) {
            return Err(format!(
                "{}:{}: exercise id {} is used twice",
                file.display(),
                region.start + 1,
                region.id
            ));
        }
        if body(region).is_some() {
            chosen.insert(region.id.clone());
        }
    }
    let out = replace_bodies(&source, body).map_err(|e| format!("{}: {e}", file.display()))?;
    let replaced = if chosen.is_empty() {
        Vec::new()
    } else {
        let after = regions(&out).map_err(|e| format!("{}: {e}", file.display()))?;
        after
            .into_iter()
            .filter(|r| chosen.contains(&r.id))
            .map(|r| (file.to_owned(), r.start + 1, r))
            .collect()
    };
    Ok((out.into_bytes(), replaced))
}

/// Writes `bytes` to `to` unless it holds them already; true if it wrote.
fn write_if_changed(to: &Path, bytes: &[u8]) -> Result<bool, String> {
    if std::fs::read(to).ok().as_deref() == Some(bytes) {
        return Ok(false);
    }
    if let Some(parent) = to.parent() {
        std::fs::create_dir_all(parent)
            .map_err(|e| format!("cannot create {}: {e}", parent.display()))?;
    }
    std::fs::write(to, bytes).map_err(|e| format!("cannot write {}: {e}", to.display()))?;
    Ok(true)
}

/// Every exercise region of the workspace's chapters, with its file
/// (relative to `root`) and the line of its opening marker (from 1).
pub fn workspace_regions(root: &Path) -> Result<Vec<(PathBuf, usize, Region)>, String> {
    let mut found = Vec::new();
    for file in workspace_files(root)? {
        if !holds_exercises(&file) {
            continue;
        }
        let path = root.join(&file);
        let source =
            std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        for region in regions(&source).map_err(|e| format!("{}: {e}", file.display()))? {
            found.push((file.clone(), region.start + 1, region));
        }
    }
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_workspace_root_is_found_from_below() {
        // This crate lives in crates/workbook/, two folders below the workspace root.
        let here = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let here = here.canonicalize().unwrap();
        let root = workspace_root(&here.join("chapters/03-lambert/src")).unwrap();
        assert_eq!(root, here);
        assert!(workspace_root(&std::env::temp_dir()).is_err());
    }

    #[test]
    fn the_teachers_files_stay_out_of_a_handout() {
        for file in [
            "chapters/03-lambert/mistakes.toml",
            "crates/grade/teacher/slurm-grade.sh",
            ".github/workflows/grade.yml",
        ] {
            assert!(teacher_only(Path::new(file)), "{file}");
        }
        for file in [
            "chapters/03-lambert/src/lib.rs",
            "crates/workbook/src/lib.rs",
            ".gitignore",
        ] {
            assert!(!teacher_only(Path::new(file)), "{file}");
        }
    }
}
