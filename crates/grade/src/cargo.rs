//! The commands grading runs: cargo in a copy, and a test binary, each with
//! the same small environment, so that the reference's base build and
//! every student's build ask cargo for exactly the same units (and the
//! shared dependencies are found fresh), and so that a student's tests see
//! none of the teacher's variables.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

use super::confine::confined;
use workbench::exercise::TAKE_OUT;

/// Where a build or test run works: the copy, its target folder, and a
/// scratch folder that is its HOME and TMPDIR.
#[derive(Debug, Clone)]
pub struct Place {
    pub copy: PathBuf,
    pub target: PathBuf,
    pub scratch: PathBuf,
}

impl Place {
    /// The place of a copy: its target folder and scratch folder inside it.
    pub fn of(copy: &Path) -> Place {
        Place {
            copy: copy.to_owned(),
            target: copy.join("target"),
            scratch: copy.join("target/scratch"),
        }
    }
}

/// `cargo test -p <package> --offline --no-fail-fast` in the copy (with
/// `--no-run` to build only), with `jobs` compiler processes at once.
pub fn cargo_test(place: &Place, package: &str, build_only: bool, jobs: usize) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = confined(&cargo, &place.copy);
    command.args(["test", "--offline", "--no-fail-fast", "--color", "never"]);
    command.args(["-p", package, "--jobs", &jobs.max(1).to_string()]);
    if build_only {
        command.args(["--no-run", "--message-format", "json-render-diagnostics"]);
    }
    command.current_dir(&place.copy);
    small_environment(&mut command, place);
    command
}

/// `cargo build -p <package> --offline --no-default-features --features
/// <features>` in the copy: the grader's probe, built with the chapters'
/// features it is asked for (see `probe.rs`).
pub fn cargo_build(place: &Place, package: &str, features: &[String], jobs: usize) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = confined(&cargo, &place.copy);
    command.args(["build", "--offline", "--color", "never", "-p", package]);
    command.args(["--no-default-features", "--features", &features.join(",")]);
    command.args(["--jobs", &jobs.max(1).to_string()]);
    command.current_dir(&place.copy);
    small_environment(&mut command, place);
    command
}

/// A test binary of the copy, run as cargo runs it (in its package's
/// folder), with the exercises `take_out` taken out (see
/// [`workbench::exercise`]).
pub fn test_binary(place: &Place, binary: &Path, package_dir: &Path, take_out: &str) -> Command {
    let mut command = confined(binary.as_os_str(), &place.copy);
    command.current_dir(package_dir);
    small_environment(&mut command, place);
    command.env(TAKE_OUT, take_out);
    command
}

/// Clears the environment and sets only what cargo and the tests need.
fn small_environment(command: &mut Command, place: &Place) {
    let _ = std::fs::create_dir_all(&place.scratch);
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let under_home = |folder: &str| home.as_ref().map(|h| h.join(folder).into_os_string());
    command.env_clear();
    for var in ["PATH", "LANG", "LC_ALL", "RUSTUP_TOOLCHAIN", "RUSTC"] {
        if let Some(value) = std::env::var_os(var) {
            command.env(var, value);
        }
    }
    // cargo and rustup find their homes under HOME: name them, so that
    // HOME can be the scratch folder.
    let homes: [(&str, Option<OsString>); 2] = [
        ("CARGO_HOME", under_home(".cargo")),
        ("RUSTUP_HOME", under_home(".rustup")),
    ];
    for (var, default) in homes {
        if let Some(value) = std::env::var_os(var).or(default) {
            command.env(var, value);
        }
    }
    command
        .env("HOME", &place.scratch)
        .env("TMPDIR", &place.scratch)
        .env("CARGO_TARGET_DIR", &place.target)
        // Incremental caches are large and are never reused here.
        .env("CARGO_INCREMENTAL", "0")
        .env("CARGO_TERM_COLOR", "never")
        .env("CARGO_TERM_PROGRESS_WHEN", "never")
        // A failing snapshot must not leave insta's .snap.new behind.
        .env("INSTA_UPDATE", "no")
        .env("RUST_BACKTRACE", "0");
}

/// A test binary that `cargo test --no-run --message-format json` built.
#[derive(Debug, Clone)]
pub struct TestBinary {
    /// Its target, as cargo names it when it runs it: `tests/chapter03/main.rs`.
    pub target: String,
    /// The executable.
    pub path: PathBuf,
    /// Its package's folder, where cargo runs it.
    pub package_dir: PathBuf,
}

/// The test binaries of the package in `package_dir` among cargo's JSON
/// messages.
pub fn test_binaries(messages: &str, package_dir: &Path) -> Vec<TestBinary> {
    let mut found = Vec::new();
    for message in cargo_metadata::Message::parse_stream(messages.as_bytes()).flatten() {
        if let cargo_metadata::Message::CompilerArtifact(artifact) = message
            && let Some(path) = artifact.executable
            && artifact.manifest_path.parent().map(|p| p.as_std_path()) == Some(package_dir)
        {
            let source = artifact.target.src_path.as_std_path();
            let target = source.strip_prefix(package_dir).unwrap_or(source);
            found.push(TestBinary {
                target: target.display().to_string(),
                path: path.into(),
                package_dir: package_dir.to_owned(),
            });
        }
    }
    found
}
