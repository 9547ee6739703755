//! One build of the dependencies, shared by every student.
//!
//! Each student builds in a target folder of their own (inside their graded
//! copy), never in a shared one: cargo names a workspace member's artifacts
//! by its path inside the workspace and decides that they are up to date by
//! the files' modification times, so in a shared target folder one
//! student's compiled chapter could be taken for another's, whose files
//! happen to be older, and grade them on the wrong code. What the students
//! share is what is the same for all of them, compiled once in the
//! reference's base copy and put into each student's target folder before
//! their build:
//!
//! * the registry dependencies (image, insta, clap, ...), copied: their
//!   artifacts are named by a hash of their version, features and flags,
//!   which the students' builds reproduce exactly (same commands, same
//!   environment), so cargo finds them fresh and never writes them again;
//! * the workspace's crates that no student can change and that depend on
//!   none a student can (the toolkit, scene-files: the copy holds the
//!   reference's files for them, with the base copy's modification times,
//!   so cargo finds them fresh too), copied with their times. Not the
//!   workbench: it embeds the path of its copy (`env!("CARGO_MANIFEST_DIR")`,
//!   to find the snapshots and to write the failure pictures), so a shared
//!   build would write every student's pictures into the base copy; it and
//!   the chapters are built anew for each student.
//!
//! Every shared file is *copied* into the student's target folder (a room
//! of its own in the sandbox, `sandbox/bwrap.rs`), never hard-linked: a test
//! that overwrites one in place changes its own copy only, never the base
//! build that the next student's copy comes from, nor the teacher's own
//! `target/`. The base build's folder itself is never in a student's
//! sandbox. (A copy costs time and room per student: the registry
//! dependencies of the chapters graded, a few hundred MiB.)

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use cargo_metadata::{DependencyKind, Metadata};

use workbook::handout::share::{How, share_matching};

/// Packages and their crates, as the target folder names their files.
#[derive(Debug, Clone, Default)]
struct Names {
    /// Package names (`.fingerprint/` and `build/` hold `<package>-<hash>`).
    packages: BTreeSet<String>,
    /// Crate names (`deps/` holds `lib<crate>-<hash>.rlib`, `<crate>-<hash>.d`).
    crates: BTreeSet<String>,
}

impl Names {
    fn of<'a>(packages: impl Iterator<Item = &'a cargo_metadata::Package>) -> Names {
        let mut names = Names::default();
        for package in packages {
            names.packages.insert(package.name.to_string());
            let crates = package.targets.iter().map(|t| t.name.replace('-', "_"));
            names.crates.extend(crates);
        }
        names
    }
}

/// What a student's target folder gets from the base build.
#[derive(Debug, Clone, Default)]
pub struct Shared {
    /// The registry dependencies: copied.
    registry: Names,
    /// The workspace crates no student can change: copied.
    workspace: Names,
}

impl Shared {
    /// What can be shared in the workspace at `root`, whose students own
    /// the folders `students` (relative to it), from `cargo metadata`.
    pub fn of_workspace(root: &Path, students: &[PathBuf]) -> Result<Shared, String> {
        let metadata = cargo_metadata::MetadataCommand::new()
            .current_dir(root)
            .other_options(vec!["--offline".to_owned()])
            .exec()
            .map_err(|e| format!("cargo metadata in {}: {e}", root.display()))?;
        let registry = metadata.packages.iter().filter(|p| p.source.is_some());
        let shareable = shareable_members(&metadata, root, students);
        let members = metadata.workspace_packages().into_iter();
        Ok(Shared {
            registry: Names::of(registry),
            workspace: Names::of(members.filter(|p| shareable.contains(p.name.as_str()))),
        })
    }

    /// Only the registry dependencies.
    pub fn registry_only(&self) -> Shared {
        Shared {
            registry: self.registry.clone(),
            workspace: Names::default(),
        }
    }

    /// Copies the shared artifacts of the target folder `from` into `to`
    /// (`debug/deps`, `debug/.fingerprint`, `debug/build`), where they are
    /// not there already. Never a link: see the module.
    pub fn put(&self, from: &Path, to: &Path) -> Result<(), String> {
        let (from, to) = (from.join("debug"), to.join("debug"));
        let put = |names: &Names| {
            let in_deps = |name: &str| stem(name).is_some_and(|s| names.crates.contains(s));
            let in_folders = |name: &str| {
                name.rsplit_once('-')
                    .is_some_and(|(s, _)| names.packages.contains(s))
            };
            share_matching(&from.join("deps"), &to.join("deps"), How::Copy, in_deps)?;
            for folder in [".fingerprint", "build"] {
                share_matching(&from.join(folder), &to.join(folder), How::Copy, in_folders)?;
            }
            Ok::<(), std::io::Error>(())
        };
        put(&self.registry)
            .and_then(|()| put(&self.workspace))
            .map_err(|e| {
                format!(
                    "cannot put the shared dependencies into {}: {e}",
                    to.display()
                )
            })
    }
}

/// The workspace members whose build every student can share: not a
/// student's (no folder of theirs inside), naming neither its copy's path
/// (`CARGO_MANIFEST_DIR`) nor its build's (`OUT_DIR`) in its sources, and
/// depending only on such members.
fn shareable_members(metadata: &Metadata, root: &Path, students: &[PathBuf]) -> BTreeSet<String> {
    let members = metadata.workspace_packages();
    let folder = |p: &cargo_metadata::Package| {
        p.manifest_path
            .parent()
            .map(|d| d.as_std_path().to_owned())
            .unwrap_or_default()
    };
    let mut candidates: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for package in &members {
        let dir = folder(package);
        let theirs = students.iter().any(|s| root.join(s).starts_with(&dir));
        if theirs || names_its_paths(&dir.join("src")) {
            continue;
        }
        let local = package.dependencies.iter().filter(|d| {
            d.path.is_some() && matches!(d.kind, DependencyKind::Normal | DependencyKind::Build)
        });
        let deps = local.map(|d| d.name.to_string()).collect();
        candidates.insert(package.name.to_string(), deps);
    }
    // Drop, until none is left to drop, those depending on a dropped one.
    loop {
        let dropped: Vec<String> = candidates
            .iter()
            .filter(|(_, deps)| deps.iter().any(|d| !candidates.contains_key(d)))
            .map(|(name, _)| name.clone())
            .collect();
        if dropped.is_empty() {
            return candidates.into_keys().collect();
        }
        for name in dropped {
            candidates.remove(&name);
        }
    }
}

/// Does any Rust file under `dir` name `CARGO_MANIFEST_DIR` or `OUT_DIR`?
fn names_its_paths(dir: &Path) -> bool {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return false;
    };
    entries.flatten().any(|entry| {
        let path = entry.path();
        if path.is_dir() {
            return names_its_paths(&path);
        }
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        path.extension().is_some_and(|e| e == "rs")
            && (text.contains("CARGO_MANIFEST_DIR") || text.contains("OUT_DIR"))
    })
}

/// The crate of a file of `deps/`: `lib<crate>-<hash>.<ext>` or
/// `<crate>-<hash>.d`.
fn stem(name: &str) -> Option<&str> {
    let name = name.strip_prefix("lib").unwrap_or(name);
    name.rsplit_once('-').map(|(stem, _)| stem)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_chosen_crates_and_packages_are_copied_never_linked() {
        let dir = tempfile::tempdir().unwrap();
        let (from, to) = (dir.path().join("from"), dir.path().join("to"));
        for file in [
            "debug/deps/libimage-0123.rlib",
            "debug/deps/image-0123.d",
            "debug/deps/libch01_rays-4567.rlib",
            "debug/.fingerprint/image-0123/lib-image",
            "debug/.fingerprint/ch01-rays-4567/lib-ch01_rays",
            "debug/build/png-89ab/out/x",
        ] {
            let path = from.join(file);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, file).unwrap();
        }
        let names = |list: [&str; 2]| BTreeSet::from(list.map(String::from));
        let shared = Shared {
            registry: Names {
                packages: names(["image", "png"]),
                crates: names(["image", "png"]),
            },
            workspace: Names::default(),
        };
        shared.put(&from, &to).unwrap();
        let has = |file: &str| to.join(file).exists();
        // A copy, not a hard link: writing it leaves the base build as it was.
        let rlib = "debug/deps/libimage-0123.rlib";
        use std::os::unix::fs::MetadataExt;
        assert_eq!(std::fs::metadata(to.join(rlib)).unwrap().nlink(), 1);
        std::fs::write(to.join(rlib), "overwritten").unwrap();
        assert_eq!(std::fs::read_to_string(from.join(rlib)).unwrap(), rlib);
        assert!(has("debug/deps/libimage-0123.rlib") && has("debug/deps/image-0123.d"));
        assert!(has("debug/.fingerprint/image-0123/lib-image"));
        assert!(has("debug/build/png-89ab/out/x"));
        assert!(
            !has("debug/deps/libch01_rays-4567.rlib"),
            "a chapter is never shared"
        );
        assert!(!has("debug/.fingerprint/ch01-rays-4567"));
    }
}
