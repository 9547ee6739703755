//! Running the probe (`crates/grade-probe`): built in a copy with one
//! chapter's feature, run once per exercise (so that an endless loop or a
//! crash in one exercise costs no other) and once for the chapter's seeded
//! scenes, each run under the limits; its output read back as data only.
//!
//! The probe's sources are the reference's, copied into every copy like
//! the tests (a student's handout has none: they are teacher-only), and
//! made read-only there.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::Duration;

use grade_probe::{FORMAT, Picture, Probed, Values};
use serde::Deserialize;

use super::cargo::{Place, cargo_build, test_binary};
use super::sandbox::{Limits, Ran, run};
use crate::workspace::PROBE;
use workbench::chapters::ChapterEntry;

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
    let all = crate::workspace::workspace_files(root)?;
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

/// Runs the probe built in `place` with `args` (`--exercise ID` or
/// `--scenes FOLDER`) and `seed`; its output, read back from the copy.
pub fn run_one(place: &Place, args: [&str; 2], seed: u64, limits: &Limits) -> Outcome {
    let binary = place.target.join("debug/grade-probe");
    let folder = place.target.join("probe");
    // The runs see the copy's target folder at `place.target`; the grader
    // reaches the same files from outside their namespace.
    std::fs::create_dir_all(place.outside(&folder)).map_err(|e| e.to_string())?;
    let out = folder.join(format!("{}.json", args[1]));
    let read_back = place.outside(&out);
    if std::fs::symlink_metadata(&read_back).is_ok() {
        std::fs::remove_file(&read_back)
            .map_err(|e| format!("cannot clear {}: {e}", read_back.display()))?;
    }
    let mut command = test_binary(place, &binary, &place.copy, "");
    command
        .args(args)
        .arg("--seed")
        .arg(seed.to_string())
        .arg("--out")
        .arg(&out);
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
    read(&read_back, seed)
}

/// Why a run failed, in a line: the panic's message if it printed one.
fn crashed(text: &str) -> String {
    let panic = text
        .lines()
        .skip_while(|l| !l.contains("panicked at"))
        .nth(1);
    match panic {
        Some(message) => format!("panicked: {}", message.trim()),
        None if text.contains("has overflowed its stack") => "a stack overflow".to_owned(),
        None => "crashed".to_owned(),
    }
}

/// A probe's output, read as data: a regular file (never a link, FIFO or
/// device), at most [`MOST`] bytes, in the probe's format, for `seed`.
pub fn read(path: &Path, seed: u64) -> Outcome {
    let meta = std::fs::symlink_metadata(path).map_err(|_| "wrote no values".to_owned())?;
    if !meta.file_type().is_file() {
        return Err("its output is not a regular file".to_owned());
    }
    if meta.len() > MOST {
        return Err(format!("its output is larger than {} MiB", MOST >> 20));
    }
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read its output: {e}"))?;
    let probed: Probed = serde_json::from_slice(&bytes)
        .map_err(|e| format!("its output is not the probe's: {e}"))?;
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
    let features: Vec<String> = probed.iter().map(|c| feature(c)).collect();
    let built = build(base, &features, limits, jobs)?;
    if !built.success {
        let tail: Vec<&str> = built.text.lines().rev().take(20).collect();
        return Err(format!(
            "the reference's probe does not build:\n{}",
            tail.join("\n")
        ));
    }
    let list = std::process::Command::new(base.target.join("debug/grade-probe"))
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
            let mut probed =
                run_one(base, ["--exercise", id], seed, limits).map_err(|e| fail(id, e))?;
            let values = probed
                .exercises
                .pop()
                .ok_or_else(|| fail(id, "no values".into()))?;
            expected.values.insert(id.clone(), values);
        }
        let probed = run_one(base, ["--scenes", &chapter.folder], seed, limits)
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
pub fn seed(given: Option<u64>, kept: &Path) -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let earlier = || std::fs::read_to_string(kept).ok()?.trim().parse().ok();
    given.or_else(earlier).unwrap_or_else(|| {
        let mut hasher = std::hash::RandomState::new().build_hasher();
        let now = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH);
        hasher.write_u128(now.map_or(0, |d| d.as_nanos()));
        hasher.finish()
    })
}
