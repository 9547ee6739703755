//! The raybook command ends quietly when its output is closed, as in
//! `raybook render scene.toml | head -1`: no panic, no backtrace.

use raybook::workbench::snapshot::workspace_root;
use test_support::closed_pipe::{assert_quiet, stderr_with_stdout_closed};

#[test]
fn raybook_render_ends_quietly_on_a_closed_pipe() {
    let scene = workspace_root().join("chapters/03-lambert/scenes/default.toml");
    let scene = scene.to_str().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "render", scene, "--width", "8", "--height", "6", "-q", "-o", "out.png",
    ];
    let stderr = stderr_with_stdout_closed(env!("CARGO_BIN_EXE_raybook"), dir.path(), &args);
    assert_quiet(&stderr);
}
