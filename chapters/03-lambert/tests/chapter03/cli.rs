//! The chapter binary tells a student when a scene needs a later chapter.

use std::process::Command;

/// Runs the chapter binary with its picture written into a folder of the
/// test's own (the tests run side by side).
fn run(args: &[&str]) -> std::process::Output {
    let dir = tempfile::tempdir().unwrap();
    Command::new(env!("CARGO_BIN_EXE_ch03-lambert"))
        .args(args)
        .args(["--width", "16", "--height", "12", "-q", "-o"])
        .arg(dir.path().join("out.png"))
        .output()
        .unwrap()
}

const GLASS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../06-refraction/scenes/default.toml"
);

#[test]
fn a_scene_from_a_later_chapter_renders_with_a_note() {
    let output = run(&[GLASS]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(
        stderr.contains(
            "this scene calls for refraction, introduced in chapter 6 (chapters/06-refraction)"
        ),
        "{stderr}"
    );
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("simulated: lambert"), "{stdout}");
}

#[test]
fn strict_makes_it_an_error() {
    let output = run(&[GLASS, "--strict"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("error: this scene calls for"), "{stderr}");
}

#[test]
fn a_bad_scene_fails_with_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.toml");
    std::fs::write(&bad, "[camera]\neye = [0, 0]\n").unwrap();
    let output = run(&[bad.to_str().unwrap()]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains(":2:7: camera.eye: expected three numbers"),
        "{stderr}"
    );
}

#[test]
fn the_path_criteria_are_refused_before_the_chapter_that_teaches_them() {
    let output = run(&["--max-depth", "2"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains(
            "error: --max-depth: chapter 3 (03-lambert) ends no path by it; \
             chapter 5 (chapters/05-reflection) introduces it"
        ),
        "{stderr}"
    );
    let output = run(&["--min-weight", "0.1"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(
        stderr.contains("chapter 7 (chapters/07-termination) introduces it"),
        "{stderr}"
    );
}
