//! The workbook's tools end quietly when their output is closed, as in
//! `workbook verify 3 mine.png | head -1`: no panic, no backtrace.

use test_support::closed_pipe::{assert_quiet, stderr_with_stdout_closed};
use workbook::workbench::snapshot::workspace_root;

#[test]
fn workbook_verify_ends_quietly_on_a_closed_pipe() {
    let reference = workspace_root().join("snapshots/03-lambert/default.snap.png");
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(reference, dir.path().join("mine.png")).unwrap();
    let args = ["verify", "3", "mine.png"];
    let stderr = stderr_with_stdout_closed(env!("CARGO_BIN_EXE_workbook"), dir.path(), &args);
    assert_quiet(&stderr);
}
