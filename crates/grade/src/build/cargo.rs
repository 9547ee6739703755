//! The commands grading runs: cargo in a copy, and a test binary, each with
//! the same small environment, so that the reference's base build and
//! every student's build ask cargo for exactly the same units (and the
//! shared dependencies are found fresh), and so that a student's tests see
//! none of the teacher's variables.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;

use crate::sandbox::beneath::{Folder, Refused};
use crate::sandbox::build_folder::BuildFolder;
use crate::sandbox::bwrap::{Setup, confined};
use workbench::exercise::TAKE_OUT;

/// Where a build or test run works: the copy, its target folder, and a
/// scratch folder that is its HOME and TMPDIR.
#[derive(Debug, Clone)]
pub struct Place {
    pub copy: PathBuf,
    pub target: PathBuf,
    pub scratch: PathBuf,
    /// How the runs are confined (`sandbox/bwrap.rs`).
    setup: Arc<Setup>,
    /// A student's writable, size-limited build folder
    /// (`sandbox/build_folder.rs`); none for the reference's base copy,
    /// which is all writable, and when grading without the sandbox.
    build: Option<Arc<BuildFolder>>,
    /// The grader's own folder of this student's probes, built before any
    /// of their code ran and kept where no student's run can write: shown
    /// read-only to the runs at [`PROBES`].
    probes: Option<PathBuf>,
}

/// Where a student's runs see their probes (a read-only mount).
pub const PROBES: &str = "/raybook-probes";

/// The largest probe grading keeps. Each chapter's probe is copied out of
/// the student's build folder (bounded by `--disk`) into the grader's own
/// folder on the teacher's disk, and read whole into memory on the way:
/// without a bound, code padded with a large `static` would put up to
/// `--disk` on the teacher's disk for every chapter graded. An honest
/// probe is about 15 MiB (a debug build of chapters 1 to 7 with the
/// probe); four times that leaves room for any honest code.
pub const MOST_PROBE: u64 = 64 << 20;

impl Place {
    /// The place of a copy: its target folder and scratch folder inside it.
    pub fn of(copy: &Path, setup: &Arc<Setup>) -> Place {
        Place {
            setup: Arc::clone(setup),
            copy: copy.to_owned(),
            target: copy.join("target"),
            scratch: copy.join("target/scratch"),
            build: None,
            probes: None,
        }
    }

    /// The place of a student's copy: in the sandbox, the copy is
    /// read-only and its target folder a build folder of its own (a tmpfs of
    /// `--disk`'s size), which ends when the last clone of the place is
    /// dropped.
    pub fn student(copy: &Path, probes: &Path, setup: &Arc<Setup>) -> Result<Place, String> {
        let mut place = Place::of(copy, setup);
        std::fs::create_dir_all(probes)
            .map_err(|e| format!("cannot create {}: {e}", probes.display()))?;
        place.probes = Some(probes.to_owned());
        if setup.sandboxed {
            std::fs::create_dir_all(&place.target)
                .map_err(|e| format!("cannot create {}: {e}", place.target.display()))?;
            place.build = Some(Arc::new(BuildFolder::new(&place.target, setup)?));
        }
        Ok(place)
    }

    /// Where the grader reads or writes `path`, a path of the runs (in the
    /// copy's target folder, which only the runs' namespace sees).
    pub fn outside(&self, path: &Path) -> PathBuf {
        match &self.build {
            Some(room) => room.outside(path),
            None => path.to_owned(),
        }
    }

    /// The student's build folder, opened once: everything grading reads
    /// or makes in it after their code ran goes beneath it (`sandbox/beneath.rs`).
    pub fn target_folder(&self) -> Result<Folder, String> {
        Folder::open(&self.outside(&self.target))
    }

    /// Keeps the probe just built (`target/debug/grade-probe`) as the
    /// probe of `chapter` (`ch03`), in the grader's own folder, before any
    /// of the student's code runs; later runs cannot change it. A probe
    /// larger than [`MOST_PROBE`] is refused, never read.
    pub fn keep_probe(&self, chapter: &str) -> Result<(), String> {
        let Some(probes) = &self.probes else {
            return Ok(());
        };
        let by = std::time::Instant::now() + std::time::Duration::from_secs(60);
        let read = (self.target_folder()?).read(Path::new("debug/grade-probe"), MOST_PROBE, by);
        let bytes = read.map_err(|why| match why {
            Refused::TooLarge(size) => format!(
                "the probe just built is {} MiB, more than the {} MiB grading keeps \
                 (an honest one is about 15 MiB): refused",
                size >> 20,
                MOST_PROBE >> 20
            ),
            why => format!("the probe just built: {why}"),
        })?;
        let kept = probes.join(chapter);
        std::fs::write(&kept, bytes).map_err(|e| format!("cannot keep the probe: {e}"))?;
        std::fs::set_permissions(&kept, std::os::unix::fs::PermissionsExt::from_mode(0o555))
            .map_err(|e| format!("cannot keep the probe: {e}"))
    }

    /// The probe of `chapter` as the runs see it: the one kept, or (the
    /// reference's base copy) the one built.
    pub fn probe(&self, chapter: &str) -> PathBuf {
        match (&self.probes, &self.build) {
            (None, _) => self.target.join("debug/grade-probe"),
            (Some(_), Some(_)) => Path::new(PROBES).join(chapter),
            (Some(kept), None) => kept.join(chapter),
        }
    }

    /// What the student's limits did, for their result's notes.
    pub fn notes(&self) -> Vec<String> {
        self.build.as_ref().map(|r| r.notes()).unwrap_or_default()
    }

    /// `program` with `args` and the small environment (and `extra`), in
    /// `cwd`, confined to this place.
    fn command(
        &self,
        program: &OsString,
        args: &[OsString],
        (cwd, extra): (&Path, &[(OsString, OsString)]),
    ) -> Command {
        // Beneath the build folder, never through a link the runs left.
        match &self.build {
            Some(_) => {
                if let Ok(target) = self.target_folder() {
                    target.make_folder("scratch");
                }
            }
            None => {
                let _ = std::fs::create_dir_all(&self.scratch);
            }
        }
        let mut env = small_environment(self);
        env.extend(extra.iter().cloned());
        let probes = (self.probes.as_deref()).map(|p| (p, Path::new(PROBES)));
        confined(
            (&self.copy, cwd),
            (self.build.as_deref(), probes),
            (program, args),
            (&env, self.setup.sandboxed),
        )
    }
}

/// `cargo test -p <package> --offline --no-fail-fast` in the copy (with
/// `--no-run` to build only), with `jobs` compiler processes at once.
pub fn cargo_test(place: &Place, package: &str, build_only: bool, jobs: usize) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut args: Vec<OsString> = ["test", "--offline", "--no-fail-fast", "--color", "never"]
        .map(OsString::from)
        .to_vec();
    args.extend(["-p".into(), package.into(), "--jobs".into()]);
    args.push(jobs.max(1).to_string().into());
    if build_only {
        let more = ["--no-run", "--message-format", "json-render-diagnostics"];
        args.extend(more.map(OsString::from));
    }
    place.command(&cargo, &args, (&place.copy, &[]))
}

/// `cargo build -p <package> --offline --no-default-features --features
/// <features>` in the copy: the grader's probe, built with the chapters'
/// features it is asked for (see `judging/probe.rs`).
pub fn cargo_build(place: &Place, package: &str, features: &[String], jobs: usize) -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut args: Vec<OsString> = ["build", "--offline", "--color", "never", "-p", package]
        .map(OsString::from)
        .to_vec();
    args.extend(["--no-default-features".into(), "--features".into()]);
    args.push(features.join(",").into());
    args.extend(["--jobs".into(), jobs.max(1).to_string().into()]);
    place.command(&cargo, &args, (&place.copy, &[]))
}

/// A test binary of the copy, run as cargo runs it (in its package's
/// folder), with the exercises `take_out` taken out (see
/// [`workbench::exercise`]).
pub fn test_binary(place: &Place, binary: &Path, package_dir: &Path, take_out: &str) -> Command {
    let take_out = [(OsString::from(TAKE_OUT), OsString::from(take_out))];
    place.command(
        &binary.as_os_str().to_owned(),
        &[],
        (package_dir, &take_out),
    )
}

/// Only what cargo and the tests need.
fn small_environment(place: &Place) -> Vec<(OsString, OsString)> {
    let mut env: Vec<(OsString, OsString)> = Vec::new();
    for var in ["PATH", "LANG", "LC_ALL", "RUSTUP_TOOLCHAIN", "RUSTC"] {
        if let Some(value) = std::env::var_os(var) {
            env.push((var.into(), value));
        }
    }
    // cargo and rustup find their homes under HOME: name them, so that
    // HOME can be the scratch folder.
    let homes = crate::sandbox::bwrap::tool_homes();
    for (var, value) in [("CARGO_HOME", homes.cargo), ("RUSTUP_HOME", homes.rustup)] {
        if let Some(value) = value {
            env.push((var.into(), value.into()));
        }
    }
    let set = [
        ("HOME", place.scratch.as_os_str()),
        ("TMPDIR", place.scratch.as_os_str()),
        ("CARGO_TARGET_DIR", place.target.as_os_str()),
        // Incremental caches are large and are never reused here.
        ("CARGO_INCREMENTAL", "0".as_ref()),
        ("CARGO_TERM_COLOR", "never".as_ref()),
        ("CARGO_TERM_PROGRESS_WHEN", "never".as_ref()),
        // A failing snapshot must not leave insta's .snap.new behind.
        ("INSTA_UPDATE", "no".as_ref()),
        ("RUST_BACKTRACE", "0".as_ref()),
    ];
    env.extend(set.map(|(k, v)| (k.into(), v.to_owned())));
    env
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A place of `copy` whose probes are kept in `probes`, unsandboxed.
    fn place(copy: &Path, probes: &Path) -> Place {
        let mut place = Place::of(copy, &Arc::new(Setup::none()));
        place.probes = Some(probes.to_owned());
        place
    }

    #[test]
    fn a_probe_padded_past_the_bound_is_refused_unread_and_an_honest_one_kept() {
        let dir = tempfile::tempdir().unwrap();
        let (copy, probes) = (dir.path().join("copy"), dir.path().join("probes"));
        std::fs::create_dir_all(copy.join("target/debug")).unwrap();
        std::fs::create_dir_all(&probes).unwrap();
        let built = copy.join("target/debug/grade-probe");
        // Sparse: its size is what a padded build writes, its pages are not.
        let padded = std::fs::File::create(&built).unwrap();
        padded.set_len(MOST_PROBE + 1).unwrap();
        let refused = place(&copy, &probes).keep_probe("ch01").unwrap_err();
        assert!(refused.contains("more than the 64 MiB"), "{refused}");
        assert!(!probes.join("ch01").exists(), "nothing kept");
        std::fs::write(&built, b"an honest probe").unwrap();
        place(&copy, &probes).keep_probe("ch01").unwrap();
        assert_eq!(
            std::fs::read(probes.join("ch01")).unwrap(),
            b"an honest probe"
        );
    }
}
