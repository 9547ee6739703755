//! Every binary ends quietly when its output is closed, as in
//! `raybook render scene.toml | head -1`: no panic, no backtrace.

use std::path::Path;
use std::process::{Command, Stdio};

/// Runs `binary` with `args` in `dir`, its standard output closed before it
/// writes a line, and returns what it wrote to standard error.
pub fn stderr_with_stdout_closed(binary: &str, dir: &Path, args: &[&str]) -> String {
    let mut child = Command::new(binary)
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let output = child.wait_with_output().unwrap();
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Fails if `stderr` shows a panic or a broken pipe.
pub fn assert_quiet(stderr: &str) {
    assert!(
        !stderr.contains("panicked") && !stderr.contains("Broken pipe"),
        "{stderr}"
    );
}
