//! `.raybook-handout.toml`: the raybook a handout was made from, its
//! version and commit, written by `workbook handout` into the handout's
//! root. `grade` reads it to refuse a handout of another version
//! (whose exercises and tests may differ) and to warn about one made from
//! another commit of the same version.

use std::path::Path;
use std::process::Command;

use serde::{Deserialize, Serialize};

/// The record's file name, at the handout's root.
pub const RECORD_FILE: &str = ".raybook-handout.toml";

/// Which raybook a workspace is, or a handout was made from.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Record {
    /// `[workspace.package] version` of the root Cargo.toml.
    pub version: String,
    /// The git commit (`git rev-parse HEAD`), or `unknown` outside git.
    pub commit: String,
    /// True if the files differed from the commit (uncommitted changes).
    #[serde(default)]
    pub modified: bool,
}

impl Record {
    /// The version and commit of the workspace at `root`.
    pub fn of_workspace(root: &Path) -> Record {
        let git = |args: &[&str]| {
            let out = Command::new("git").arg("-C").arg(root).args(args).output();
            out.ok()
                .filter(|o| o.status.success())
                .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_owned())
        };
        let commit = git(&["rev-parse", "HEAD"]);
        let modified = commit.is_some()
            && git(&["status", "--porcelain", "--untracked-files=no"])
                .is_some_and(|s| !s.is_empty());
        Record {
            version: workspace_version(root).unwrap_or_else(|| "unknown".to_owned()),
            commit: commit.unwrap_or_else(|| "unknown".to_owned()),
            modified,
        }
    }

    /// `0.1.0 @ fcfa207b3259` (and `+ uncommitted changes`): for reports.
    pub fn label(&self) -> String {
        let short = &self.commit[..self.commit.len().min(12)];
        let changes = if self.modified {
            " + uncommitted changes"
        } else {
            ""
        };
        format!("{} @ {short}{changes}", self.version)
    }

    /// Writes the record into the handout at `dir`.
    pub fn write(&self, dir: &Path) -> Result<(), String> {
        let text = format!(
            "# Written by `workbook handout`: the raybook this handout was made from.\n\
             # `grade` reads it; please leave it as it is.\n{}",
            toml::to_string(self).map_err(|e| format!("cannot write the record: {e}"))?
        );
        let path = dir.join(RECORD_FILE);
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
    }

    /// The record of the handout at `dir`: None if it has none, an error if
    /// it cannot be read.
    pub fn read(dir: &Path) -> Result<Option<Record>, String> {
        let path = dir.join(RECORD_FILE);
        match std::fs::read_to_string(&path) {
            Ok(text) => toml::from_str(&text)
                .map(Some)
                .map_err(|e| format!("{}: not a handout record: {e}", path.display())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(format!("cannot read {}: {e}", path.display())),
        }
    }
}

/// `[workspace.package] version` of the Cargo.toml at `root`.
pub fn workspace_version(root: &Path) -> Option<String> {
    let text = std::fs::read_to_string(root.join("Cargo.toml")).ok()?;
    let manifest: toml::Table = toml::from_str(&text).ok()?;
    let version = manifest.get("workspace")?.get("package")?.get("version")?;
    version.as_str().map(str::to_owned)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_is_written_and_read_back() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(Record::read(dir.path()).unwrap(), None);
        let record = Record {
            version: "0.1.0".into(),
            commit: "fcfa207b3259a8e36cacd021cd33ed16404382cc".into(),
            modified: true,
        };
        record.write(dir.path()).unwrap();
        assert_eq!(Record::read(dir.path()).unwrap(), Some(record.clone()));
        assert_eq!(record.label(), "0.1.0 @ fcfa207b3259 + uncommitted changes");
        std::fs::write(dir.path().join(RECORD_FILE), "version = 3").unwrap();
        assert!(
            Record::read(dir.path())
                .unwrap_err()
                .contains("not a handout record")
        );
    }

    #[test]
    fn the_workspace_version_is_read_from_its_cargo_toml() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        assert_eq!(
            workspace_version(&root).as_deref(),
            Some(env!("CARGO_PKG_VERSION"))
        );
    }
}
