//! Sharing the registry crates a workspace has compiled with another
//! target folder: the handout check's (linked), and a new handout's
//! (copied), so that neither compiles again what is compiled already.
//!
//! A registry crate compiled with the same features, profile and compiler
//! has the same file names and fingerprints in any target folder (cargo's
//! hashes of it do not depend on the workspace), so cargo takes the shared
//! files as fresh. The workspace's own crates are left out: their hashes
//! hold their paths, and cargo builds them anew.

use std::collections::BTreeSet;
use std::path::Path;

/// How the files reach the other target folder.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum How {
    /// Hard links (a copy where the file system has none): for a folder of
    /// the maintainers' own, never written by anyone else.
    Link,
    /// Copies: for a folder of a student's, which must not share a file
    /// with the clone it came from.
    Copy,
}

/// Shares the registry crates compiled in the dev profile of the workspace
/// at `root` (its target folder's `debug/`) with `target` (a target
/// folder), where they are not there yet: their artifacts, fingerprints
/// and build-script outputs. Returns how many entries it shared.
pub fn registry_builds(root: &Path, target: &Path, how: How) -> Result<usize, String> {
    let metadata = cargo_metadata::MetadataCommand::new()
        .current_dir(root)
        .exec()
        .map_err(|e| format!("cargo metadata: {e}"))?;
    let main = metadata.target_directory.as_std_path().join("debug");
    let registry: Vec<_> = (metadata.packages.iter())
        .filter(|p| p.source.is_some())
        .collect();
    let packages: BTreeSet<String> = registry.iter().map(|p| p.name.to_string()).collect();
    let crates: BTreeSet<String> = (registry.iter())
        .flat_map(|p| p.targets.iter().map(|t| t.name.replace('-', "_")))
        .collect();
    // deps/ holds lib<crate>-<hash>.rlib and <crate>-<hash>.d;
    // .fingerprint/ and build/ hold <package>-<hash> folders.
    let stem = |name: &str| {
        let name = name.strip_prefix("lib").unwrap_or(name);
        name.rsplit_once('-').map(|(stem, _)| stem.to_owned())
    };
    let debug = target.join("debug");
    let shared = || -> std::io::Result<usize> {
        let mut count = share_matching(&main.join("deps"), &debug.join("deps"), how, |n| {
            stem(n).is_some_and(|s| crates.contains(&s))
        })?;
        for folder in [".fingerprint", "build"] {
            count += share_matching(&main.join(folder), &debug.join(folder), how, |n| {
                n.rsplit_once('-')
                    .is_some_and(|(s, _)| packages.contains(s))
            })?;
        }
        Ok(count)
    };
    shared().map_err(|e| format!("cannot share the main build's dependencies: {e}"))
}

/// Shares each entry of `from` whose name is chosen (folders with all they
/// hold) into `to`, unless it is there already; how many it shared. (The
/// grader shares its base build with each student's build folder so.)
pub fn share_matching(
    from: &Path,
    to: &Path,
    how: How,
    chosen: impl Fn(&str) -> bool,
) -> std::io::Result<usize> {
    let Ok(entries) = std::fs::read_dir(from) else {
        return Ok(0);
    };
    std::fs::create_dir_all(to)?;
    let mut count = 0;
    for entry in entries {
        let entry = entry?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if chosen(&name) && !to.join(&name).exists() {
            share_tree(&entry.path(), &to.join(&name), how)?;
            count += 1;
        }
    }
    Ok(count)
}

/// Shares a file, or a folder's files, from `from` to `to`, keeping their
/// modification times (cargo compares a crate's build time with its
/// dependencies'). A symlink is shared as a link (build scripts' outputs
/// may hold one), never followed.
fn share_tree(from: &Path, to: &Path, how: How) -> std::io::Result<()> {
    let meta = std::fs::symlink_metadata(from)?;
    if meta.is_dir() {
        std::fs::create_dir_all(to)?;
        for entry in std::fs::read_dir(from)? {
            let entry = entry?;
            share_tree(&entry.path(), &to.join(entry.file_name()), how)?;
        }
    } else if meta.is_symlink() {
        if std::fs::symlink_metadata(to).is_err() {
            std::os::unix::fs::symlink(std::fs::read_link(from)?, to)?;
        }
    } else if std::fs::symlink_metadata(to).is_err() {
        let linked = how == How::Link && std::fs::hard_link(from, to).is_ok();
        if !linked {
            copy_keeping_time(from, to)?;
        }
    }
    Ok(())
}

/// Copies a file and gives the copy the original's modification time. A
/// fresh file: never a link to the original (`std::fs::copy` writes a new
/// inode).
pub fn copy_keeping_time(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::copy(from, to)?;
    let modified = std::fs::metadata(from)?.modified()?;
    std::fs::File::options()
        .write(true)
        .open(to)?
        .set_modified(modified)
}
