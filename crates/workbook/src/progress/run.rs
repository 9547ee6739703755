//! A chapter's `cargo test -p`, started in the background and read when it
//! ends, so that the next chapter's build can go on while the tests of the
//! one before it run (cargo builds one at a time: it locks `target/`).

use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::thread::JoinHandle;
use std::time::SystemTime;

use super::{TestOutput, order, parse};
use crate::workbench::chapters::ChapterEntry;

/// A chapter's tests, running.
pub struct Started {
    chapter: &'static ChapterEntry,
    child: Child,
    stdout: JoinHandle<Vec<u8>>,
    stderr: JoinHandle<Vec<u8>>,
    /// When they started: an edit after it is one they may not have seen.
    pub at: SystemTime,
}

/// Starts `cargo test -p` of `chapter`, from the workspace root.
pub fn start(root: &Path, chapter: &'static ChapterEntry) -> Result<Started, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let at = SystemTime::now();
    let mut child = Command::new(cargo)
        .args(["test", "-p", &chapter.package(), "--color", "never"])
        .current_dir(root)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let stdout = read_all(child.stdout.take());
    let stderr = read_all(child.stderr.take());
    Ok(Started {
        chapter,
        child,
        stdout,
        stderr,
        at,
    })
}

/// Reads all of a child's output, in a thread of its own (so that neither
/// pipe fills up while the other is read).
fn read_all(pipe: Option<impl Read + Send + 'static>) -> JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.read_to_end(&mut bytes);
        }
        bytes
    })
}

impl Started {
    /// Waits for the tests to end, and reads what they printed.
    pub fn finish(mut self, root: &Path) -> Result<TestOutput, String> {
        let status = (self.child.wait()).map_err(|e| format!("cannot run cargo: {e}"))?;
        let stdout = self.stdout.join().unwrap_or_default();
        let stderr = self.stderr.join().unwrap_or_default();
        let text = format!(
            "{}\n{}",
            String::from_utf8_lossy(&stdout),
            String::from_utf8_lossy(&stderr)
        );
        let mut parsed = parse(&text);
        if !status.success() && parsed.failed == 0 && parsed.compile_error.is_none() {
            // cargo failed before any test ran, and said why on its last line.
            let last = text.lines().rev().find(|l| l.starts_with("error"));
            parsed.compile_error = Some(last.unwrap_or("cargo test failed").to_owned());
        }
        let order = order::test_order(&root.join(self.chapter.path()).join("tests"));
        order::in_chapter_order(&mut parsed, &order);
        Ok(parsed)
    }
}
