//! `raybook bench --tinyraytracer PROGRAM`: a row for tinyraytracer's scene,
//! raybook against the program, beside the SPD rows against POV-Ray.

use std::process::{Command, Output};

/// The bench keeps its pictures in the system's temporary folder for the
/// user to look at; the tests' go to cargo's folder for tests' files, in
/// target/, not into /tmp.
fn bench(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raybook"))
        .args(["bench", "--quiet", "--no-povray", "--runs", "1"])
        .args(args)
        .env("TMPDIR", env!("CARGO_TARGET_TMPDIR"))
        .output()
        .unwrap()
}

use test_support::table_row::row;

#[test]
fn tinyraytracer_gets_a_row_of_its_own_timed_against_the_program() {
    // `true` stands in for tinyraytracer: it runs, and takes no time.
    let out = bench(&[
        "--only",
        "tetra-3",
        "--size",
        "16",
        "--tinyraytracer",
        "true",
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let tiny = row(&stdout, "tinyraytracer");
    assert_eq!(tiny[1], "6", "four spheres and the board's two triangles");
    assert_eq!(tiny[5], "tinyraytracer", "{tiny:?}");
    let ratio: f64 = tiny[7].parse().unwrap();
    assert!(
        (0.0..1.0).contains(&ratio),
        "`true` is quicker than a render: {tiny:?}"
    );
    // 1024×768 primary rays: tinyraytracer's size, not --size.
    assert!(
        tiny[3].starts_with("2.") || tiny[3].starts_with("1."),
        "{tiny:?}"
    );
    let tetra = row(&stdout, "tetra-3");
    assert_eq!(tetra[5], "–", "POV-Ray is off: {tetra:?}");
}

#[test]
fn a_tinyraytracer_that_cannot_run_is_an_error_that_names_it() {
    let out = bench(&[
        "--only",
        "tetra-3",
        "--size",
        "8",
        "--tinyraytracer",
        "/nonexistent/tinyraytracer",
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("cannot run") && stderr.contains("/nonexistent/tinyraytracer"),
        "{stderr}"
    );
}
