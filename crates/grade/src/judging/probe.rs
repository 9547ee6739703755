//! Running the probe (`crates/grade-probe`): built in a copy with one
//! chapter's feature, run once per exercise (so that an endless loop or a
//! crash in one exercise costs no other) and once for the chapter's seeded
//! scenes, each run under the limits; its output read back as data only.
//!
//! The probe's sources are the reference's, copied into every copy like
//! the tests (a student's handout has none: they are teacher-only), and
//! made read-only there.

use std::collections::{BTreeMap, BTreeSet};
use std::io::Read;
use std::os::fd::{AsRawFd, OwnedFd};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use grade_probe::{FORMAT, Picture, Probed, Values};
use serde::Deserialize;

use crate::build::cargo::{Place, cargo_build, test_binary};
use crate::sandbox::beneath::clean_line;
use crate::sandbox::limits::{Limits, Ran, run};
use workbench::chapters::ChapterEntry;
use workbook::workspace::PROBE;

/// The most a probe's output may hold: far more than an honest run writes
/// (about 100 KB for a chapter's scenes).
const MOST: u64 = 16 << 20;

/// What the reference's probe computed with the seed: the values and
/// scenes a student's must agree with.
#[derive(Debug, Clone, Default)]
pub struct Expected {
    pub seed: u64,
    /// Each probed exercise's values, by id.
    pub values: BTreeMap<String, Values>,
    /// Each probed chapter's seeded scenes, by folder.
    pub scenes: BTreeMap<String, Vec<Picture>>,
}

impl Expected {
    /// Is exercise `id` judged by its values?
    pub fn probes(&self, id: &str) -> bool {
        self.values.contains_key(id)
    }
}

/// The probe's files in the reference at `root`, relative to it.
pub fn files(root: &Path) -> Result<Vec<PathBuf>, String> {
    let all = workbook::workspace::workspace_files(root)?;
    Ok(all.into_iter().filter(|f| f.starts_with(PROBE)).collect())
}

/// The probe's feature for a chapter: `ch03` for `03-lambert`.
pub fn feature(chapter: &ChapterEntry) -> String {
    format!("ch{:02}", chapter.number())
}

/// The chapters' features that the probe at `root` declares.
pub fn features(root: &Path) -> BTreeSet<String> {
    #[derive(Deserialize)]
    struct Manifest {
        #[serde(default)]
        features: BTreeMap<String, toml::Value>,
    }
    let path = root.join(PROBE).join("Cargo.toml");
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let manifest: Option<Manifest> = toml::from_str(&text).ok();
    manifest.map_or_else(BTreeSet::new, |m| m.features.into_keys().collect())
}

/// The limits of one probe run: a quarter of a chapter's tests' time (at
/// least 5 s). An honest run takes milliseconds.
pub fn limits(test: &Limits) -> Limits {
    Limits {
        time: (test.time / 4).max(Duration::from_secs(5)),
        ..*test
    }
}

/// Builds the probe in `place` with `features`; what the build printed.
pub fn build(
    place: &Place,
    features: &[String],
    limits: &Limits,
    jobs: usize,
) -> Result<Ran, String> {
    run(cargo_build(place, "grade-probe", features, jobs), limits)
}

/// What one probe run gave: its output, or why there is none.
pub type Outcome = Result<Probed, String>;

/// The descriptor on which a probe run writes its values: the writing end
/// of a pipe that grading opened and reads, so that no file a student's
/// code could swap for a link carries them (see `grade-probe --out-fd`).
const CHANNEL: i32 = 3;

/// Runs the probe `binary` (a path of the run) in `place` with `args`
/// (`--exercise ID` or `--scenes FOLDER`) and `seed`; its output, read
/// from the pipe it was handed. The student's code is linked into the
/// probe and may write to the pipe too: what comes out is checked as data
/// (the format, the seed, each exercise's id), and a forged record earns
/// only what its values are worth against the reference's, which never
/// leave grading's memory.
pub fn run_one(
    place: &Place,
    binary: &Path,
    args: [&str; 2],
    seed: u64,
    limits: &Limits,
) -> Outcome {
    let (reader, writer) = std::io::pipe().map_err(|e| format!("cannot make a pipe: {e}"))?;
    let mut command = test_binary(place, binary, &place.copy, "");
    command
        .args(args)
        .arg("--seed")
        .arg(seed.to_string())
        .arg("--out-fd")
        .arg(CHANNEL.to_string());
    hand_over(&mut command, writer.into());
    let answer = collect(reader);
    let ran = run(command, limits)?;
    if ran.timed_out {
        return Err(format!(
            "timed out after {} s (an endless loop?)",
            limits.time.as_secs()
        ));
    }
    if !ran.success {
        return Err(crashed(&ran.text));
    }
    // Every process of the run has ended, so the pipe has no writer left;
    // unsandboxed, one may have escaped with it: wait a little, not more.
    let bytes = answer
        .recv_timeout(Duration::from_secs(5))
        .map_err(|_| "its output did not end with the run".to_owned())??;
    read(&bytes, seed)
}

/// Gives the child `fd` as its descriptor [`CHANNEL`] (and closes the
/// grader's copy when the command is dropped, after it started).
fn hand_over(command: &mut std::process::Command, fd: OwnedFd) {
    use std::os::unix::process::CommandExt;
    // SAFETY: between fork and exec, only dup2 and fcntl (async-signal-
    // safe), on a descriptor the closure owns.
    unsafe {
        command.pre_exec(move || {
            let raw = fd.as_raw_fd();
            let done = if raw == CHANNEL {
                libc::fcntl(raw, libc::F_SETFD, 0)
            } else {
                libc::dup2(raw, CHANNEL)
            };
            if done < 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
}

/// Reads the pipe's reading end to its end, at most [`MOST`] bytes, in a
/// thread (a probe's output is larger than a pipe's buffer).
fn collect(reader: std::io::PipeReader) -> mpsc::Receiver<Result<Vec<u8>, String>> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let read = reader.take(MOST + 1).read_to_end(&mut bytes);
        let result = match read {
            Err(e) => Err(format!("cannot read its output: {e}")),
            Ok(_) if bytes.len() as u64 > MOST => {
                Err(format!("its output is larger than {} MiB", MOST >> 20))
            }
            Ok(_) => Ok(bytes),
        };
        let _ = send.send(result);
    });
    receive
}

/// Why a run failed, in a line: the panic's message if it printed one
/// (for the teacher's report only: it may hold what the probe was given).
fn crashed(text: &str) -> String {
    let panic = text
        .lines()
        .skip_while(|l| !l.contains("panicked at"))
        .nth(1);
    match panic {
        Some(message) => format!("panicked: {}", clean_line(message.trim())),
        None if text.contains("has overflowed its stack") => "a stack overflow".to_owned(),
        None => "crashed".to_owned(),
    }
}

/// A probe's output, read as data: in the probe's format, for `seed`.
pub fn read(bytes: &[u8], seed: u64) -> Outcome {
    if bytes.is_empty() {
        return Err("wrote no values".to_owned());
    }
    let probed: Probed = serde_json::from_slice(bytes)
        .map_err(|_| "its output is not the probe's (not its format)".to_owned())?;
    if probed.format != FORMAT || probed.seed != seed {
        return Err("its output is not this run's".to_owned());
    }
    Ok(probed)
}

/// The reference's values and scenes for `seed`, for the `chapters` that
/// the probe covers, computed in the base copy (trusted, outside any
/// student's run).
pub fn expected(
    base: &Place,
    chapters: &[&ChapterEntry],
    seed: u64,
    (limits, jobs): (&Limits, usize),
) -> Result<Expected, String> {
    let declared = features(&base.copy);
    let probed: Vec<&&ChapterEntry> = (chapters.iter())
        .filter(|c| declared.contains(&feature(c)))
        .collect();
    let mut expected = Expected {
        seed,
        ..Expected::default()
    };
    if probed.is_empty() {
        return Ok(expected);
    }
    // Outputs of an older grader, which wrote the values to files here:
    // the reference's values now live in this process's memory only.
    let _ = std::fs::remove_dir_all(base.target.join("probe"));
    let features: Vec<String> = probed.iter().map(|c| feature(c)).collect();
    let built = build(base, &features, limits, jobs)?;
    if !built.success {
        let tail: Vec<&str> = built.text.lines().rev().take(20).collect();
        return Err(format!(
            "the reference's probe does not build:\n{}",
            tail.join("\n")
        ));
    }
    let binary = base.target.join("debug/grade-probe");
    let list = std::process::Command::new(&binary)
        .arg("--list")
        .output()
        .map_err(|e| format!("cannot run the reference's probe: {e}"))?;
    #[derive(Deserialize)]
    struct List {
        exercises: BTreeMap<String, Vec<String>>,
    }
    let list: List = serde_json::from_slice(&list.stdout)
        .map_err(|e| format!("the reference's probe --list: {e}"))?;
    let fail = |what: &str, e: String| format!("the reference's probe of {what}: {e}");
    for chapter in probed {
        for id in list.exercises.get(&chapter.folder).into_iter().flatten() {
            let mut probed = run_one(base, &binary, ["--exercise", id], seed, limits)
                .map_err(|e| fail(id, e))?;
            let values = probed
                .exercises
                .pop()
                .ok_or_else(|| fail(id, "no values".into()))?;
            expected.values.insert(id.clone(), values);
        }
        let probed = run_one(base, &binary, ["--scenes", &chapter.folder], seed, limits)
            .map_err(|e| fail(&chapter.folder, e))?;
        expected
            .scenes
            .insert(chapter.folder.clone(), probed.scenes);
    }
    Ok(expected)
}

/// A seed for this run: `given`; else the one kept in `kept` (the output
/// folder's `seed.txt`) by an earlier run, so that grading the class again
/// judges on the same inputs and students whose files did not change keep
/// their cached results; else one drawn from the system's random source
/// (std's hasher keys come from it) and the clock.
pub fn seed(given: Option<u64>, kept: Option<&Path>) -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let earlier = || std::fs::read_to_string(kept?).ok()?.trim().parse().ok();
    given.or_else(earlier).unwrap_or_else(|| {
        let mut hasher = std::hash::RandomState::new().build_hasher();
        let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH);
        hasher.write_u128(now.map_or(0, |d| d.as_nanos()));
        hasher.finish()
    })
}
