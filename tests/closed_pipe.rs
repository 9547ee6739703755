//! Every binary ends quietly when its output is closed, as in
//! `raybook render scene.toml | head -1`: no panic, no backtrace.

use std::path::Path;
use std::process::{Command, Stdio};

/// Runs a binary with its standard output closed before it writes a line,
/// and returns what it wrote to standard error.
fn stderr_with_stdout_closed(dir: &Path, args: &[&str]) -> String {
    let mut child = Command::new(env!("CARGO_BIN_EXE_raybook"))
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

fn assert_quiet(stderr: &str) {
    assert!(
        !stderr.contains("panicked") && !stderr.contains("Broken pipe"),
        "{stderr}"
    );
}

#[test]
fn raybook_render_ends_quietly_on_a_closed_pipe() {
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/chapters/03-lambert/scenes/default.toml"
    );
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "render", scene, "--width", "8", "--height", "6", "-q", "-o", "out.png",
    ];
    assert_quiet(&stderr_with_stdout_closed(dir.path(), &args));
}

#[test]
fn raybook_verify_ends_quietly_on_a_closed_pipe() {
    let reference = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/snapshots/03-lambert/default.snap.png"
    );
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(reference, dir.path().join("mine.png")).unwrap();
    assert_quiet(&stderr_with_stdout_closed(
        dir.path(),
        &["verify", "3", "mine.png"],
    ));
}
