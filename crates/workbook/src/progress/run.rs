//! A chapter's `cargo test -p`, started in the background and read when it
//! ends, so that the next chapter's build can go on while the tests of the
//! one before it run (cargo builds one at a time: it locks `target/`).

use std::ffi::OsStr;
use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::Sender;
use std::thread::JoinHandle;
use std::time::SystemTime;

use super::{TestOutput, order, parse};
use crate::workbench::chapters::ChapterEntry;

/// A chapter's tests, ended.
pub struct Finished {
    /// The chapter's row in the table.
    pub row: usize,
    /// When its tests started: an edit after it is one they may not have seen.
    pub started: SystemTime,
    pub output: Result<TestOutput, String>,
}

/// Starts `cargo test -p` of `chapter` (with the program `cargo`), from
/// the workspace `root`; when it
/// ends, what it printed is sent to `done`, as row `row`'s.
pub fn start(
    cargo: &OsStr,
    root: &Path,
    chapter: &'static ChapterEntry,
    row: usize,
    done: Sender<Finished>,
) -> Result<(), String> {
    let started = SystemTime::now();
    let mut child = Command::new(cargo)
        .args(["test", "-p", &chapter.package(), "--color", "never"])
        .current_dir(root)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let tests = root.join(chapter.path()).join("tests");
    std::thread::spawn(move || {
        let output = finish(&mut child, &tests);
        let _ = done.send(Finished {
            row,
            started,
            output,
        });
    });
    Ok(())
}

/// Waits for `child`, a `cargo test`, to end and reads what it printed;
/// failures in the order of the chapter's test files under `tests`.
fn finish(child: &mut Child, tests: &Path) -> Result<TestOutput, String> {
    let stdout = read_all(child.stdout.take());
    let stderr = read_all(child.stderr.take());
    let status = (child.wait()).map_err(|e| format!("cannot run cargo: {e}"))?;
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(&stdout.join().unwrap_or_default()),
        String::from_utf8_lossy(&stderr.join().unwrap_or_default())
    );
    let mut parsed = parse(&text);
    if !status.success() && parsed.failed == 0 && parsed.compile_error.is_none() {
        // cargo failed before any test ran, and said why on its last line.
        let last = text.lines().rev().find(|l| l.starts_with("error"));
        parsed.compile_error = Some(last.unwrap_or("cargo test failed").to_owned());
    }
    order::in_chapter_order(&mut parsed, &order::test_order(tests));
    Ok(parsed)
}

/// Reads all of a pipe, in a thread of its own (so that neither of a
/// child's pipes fills up while the other is read). The lab runs chapter
/// binaries with it too.
pub fn read_all(pipe: Option<impl Read + Send + 'static>) -> JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.read_to_end(&mut bytes);
        }
        bytes
    })
}
