//! The handout check without a second build: the reference's own test
//! binaries, run with some exercises taken out at run time (see
//! [`crate::workbench::exercise`]). A test that reaches a taken-out solution
//! panics with the handout's `todo!` message, just as it would in a handout.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::progress::{TestOutput, parse};
use crate::workbench::chapters::ChapterEntry;
use crate::workbench::exercise::TAKE_OUT;

/// The reference's test binaries, each with the folder of its package.
pub struct ReferenceTests {
    binaries: Vec<(PathBuf, PathBuf)>,
}

impl ReferenceTests {
    /// The test binaries of the workspace at `root`, as
    /// `cargo test --workspace --no-run` builds them. Run from `cargo test`,
    /// they are built already, and this takes a moment.
    pub fn build(root: &Path) -> Result<ReferenceTests, String> {
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .args(["test", "--workspace", "--no-run", "--message-format=json"])
            .current_dir(root)
            .env_remove("CARGO_MAKEFLAGS")
            .output()
            .map_err(|e| format!("cannot run cargo: {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "cargo test --workspace --no-run failed:\n{}",
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        let mut binaries = Vec::new();
        for message in cargo_metadata::Message::parse_stream(out.stdout.as_slice()) {
            let message = message.map_err(|e| format!("cargo's messages: {e}"))?;
            if let cargo_metadata::Message::CompilerArtifact(artifact) = message
                && let Some(executable) = artifact.executable
                && let Some(package) = artifact.manifest_path.parent()
            {
                binaries.push((package.into(), executable.into()));
            }
        }
        Ok(ReferenceTests { binaries })
    }

    /// Runs the test binaries of `chapter` (under `root`) with the
    /// exercises `ids` taken out, each in its package's folder as cargo
    /// runs them: did every test pass, what they printed, and that read as
    /// test results.
    pub fn run_taken_out(
        &self,
        root: &Path,
        chapter: &ChapterEntry,
        ids: &[&str],
    ) -> Result<(bool, String, TestOutput), String> {
        let folder = root.join(chapter.path());
        let folder = folder.canonicalize().unwrap_or(folder);
        let mut all_passed = true;
        let mut text = String::new();
        for (package, binary) in self.binaries.iter().filter(|(p, _)| *p == folder) {
            let out = Command::new(binary)
                .current_dir(package)
                .env(TAKE_OUT, ids.join(","))
                // A failing snapshot must not leave insta's .snap.new behind.
                .env("INSTA_UPDATE", "no")
                .output()
                .map_err(|e| format!("cannot run {}: {e}", binary.display()))?;
            all_passed &= out.status.success();
            text.push_str(&String::from_utf8_lossy(&out.stdout));
            text.push_str(&String::from_utf8_lossy(&out.stderr));
        }
        if text.is_empty() {
            return Err(format!("no test binary of {} was built", chapter.package()));
        }
        let parsed = parse(&text);
        Ok((all_passed, text, parsed))
    }
}
