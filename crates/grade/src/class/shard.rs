//! A class graded in slices, on as many machines as there are slices: a
//! course of thousands need not wait days for one teacher's machine.
//!
//! `grade CLASS --shard K/N --out DIR` grades the K-th of N slices of the
//! class and writes `DIR/shard-K-of-N.json`: the slice's results, and what
//! they were graded with (the reference, the settings, the class's list of
//! students). Its students' pictures go where a whole run puts them,
//! `DIR/report/<student>/`. `grade --merge DIR… --out FINAL` (`class/merge.rs`)
//! reads every slice, refuses slices that do not belong together, and
//! writes the outputs one run over the whole class writes, from the same
//! results: the gradebook, the Gradescope files, JUnit, the HTML report.
//!
//! Which slice grades a student: a hash of their folder's name, modulo N.
//! Not their place in the sorted list: a student added late (or a folder
//! renamed) would move every student after them to another slice, whose
//! cache has never seen them, and the whole class would be graded again.
//! With the hash, each student stays in their slice whatever the others
//! do, and a slice's cache (`DIR/.cache`, or `--cache`) grades only the
//! students whose files changed. The price: slices are balanced only on
//! average (a class of 1000 in 8 slices: 125 ± 11 a slice), not exactly.
//! The hash is FNV-1a with a final mix, written out here rather than
//! std's hasher, which may change with the toolchain: the machines of one
//! course must agree on it.
//!
//! Examples that run the slices on engines that exist, in
//! `crates/grade/teacher/`: a Slurm job array with a merge job that waits
//! for it, and a GitHub Actions workflow for the teacher's own repository
//! (a matrix of slices, then a job that merges). A student's repository
//! gets no workflow that decides their points: a student can edit it.

use std::path::{Path, PathBuf};
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use crate::class::settings_key;
use crate::judging::exercise_tests::Tests;
use crate::judging::reference::{Reference, Settings};
use crate::judging::verdict::StudentResult;

/// The K-th of N slices of a class (counted from 1, as `--shard 1/8`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    pub k: usize,
    pub n: usize,
}

impl FromStr for Shard {
    type Err = String;

    /// `K/N`, with 1 ≤ K ≤ N.
    fn from_str(text: &str) -> Result<Shard, String> {
        let wrong = || format!("{text:?}: a slice is K/N, with 1 ≤ K ≤ N (such as 3/8)");
        let (k, n) = text.split_once('/').ok_or_else(wrong)?;
        let k: usize = k.trim().parse().map_err(|_| wrong())?;
        let n: usize = n.trim().parse().map_err(|_| wrong())?;
        if k == 0 || k > n {
            return Err(wrong());
        }
        Ok(Shard { k, n })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}

impl Shard {
    /// Does this slice grade the student whose folder is `name`?
    pub fn holds(&self, name: &str) -> bool {
        slice_of(name, self.n) == self.k
    }

    /// The file the slice writes into its output folder.
    pub fn file_name(&self) -> String {
        format!("shard-{}-of-{}.json", self.k, self.n)
    }
}

/// The slice (1 to `n`) of the student whose folder is `name`.
pub fn slice_of(name: &str, n: usize) -> usize {
    (stable_hash(name.as_bytes()) % n as u64) as usize + 1
}

/// FNV-1a (64 bits), then MurmurHash3's final mix: FNV-1a's low bits
/// follow the low bits of the bytes too closely for `% N` alone. The same
/// on every machine and every toolchain.
fn stable_hash(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^ (h >> 33)
}

/// What slices must share to be merged: every slice's is compared with
/// the others' as a whole, field by field (`class/merge.rs`), so a field added
/// here is checked without more code.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct GradedWith {
    /// The version of what grading writes (`CACHE_FORMAT`).
    pub format: String,
    /// The reference's version and commit.
    pub reference: String,
    /// A hash of the reference's files.
    pub reference_hash: String,
    /// Every setting that changes a result (`class::settings_key`: the
    /// chapters, the limits, anything added to the settings, such as the
    /// seed of what is judged), but not how many run side by side.
    pub settings: String,
    /// The seed the exercises' inputs and scenes were drawn from (also in
    /// `settings`; here for the merge, which keeps it in `seed.txt` as a
    /// run over the whole class does).
    pub seed: u64,
    /// The tests of the chapters graded and of each exercise.
    pub tests: Tests,
    /// Every student folder of the class, as listed (hidden ones aside).
    pub class: Vec<String>,
}

/// The file a slice writes: which slice, what it was graded with, and the
/// results of its students, in the class's order.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShardFile {
    pub shard: Shard,
    pub graded_with: GradedWith,
    pub students: Vec<StudentResult>,
}

/// What a run with `reference` and `settings` over the class `class`
/// (every student's folder name) grades with.
pub fn graded_with(reference: &Reference, settings: &Settings, class: Vec<String>) -> GradedWith {
    GradedWith {
        format: crate::judging::CACHE_FORMAT.to_owned(),
        reference: reference.record.label(),
        reference_hash: reference.hash.clone(),
        settings: settings_key(settings),
        seed: settings.seed,
        tests: reference.tests.clone(),
        class,
    }
}

/// Writes the slice's file into `out` (atomically); its path.
pub fn write(out: &Path, file: &ShardFile) -> Result<PathBuf, String> {
    let json = serde_json::to_string_pretty(file).map_err(|e| e.to_string())?;
    crate::report::write(&out.join(file.shard.file_name()), json + "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slice_is_read_as_k_of_n() {
        assert_eq!("3/8".parse::<Shard>(), Ok(Shard { k: 3, n: 8 }));
        for wrong in ["0/8", "9/8", "3", "a/8", "3/0", "-1/8"] {
            let error = wrong.parse::<Shard>().unwrap_err();
            assert!(error.contains("1 ≤ K ≤ N"), "{wrong}: {error}");
        }
        assert_eq!(Shard { k: 2, n: 5 }.file_name(), "shard-2-of-5.json");
    }

    #[test]
    fn every_student_is_in_exactly_one_slice_which_others_do_not_change() {
        let names: Vec<String> = (0..1000).map(|i| format!("student-{i:04}")).collect();
        let n = 8;
        let mut sizes = [0usize; 8];
        for name in &names {
            let holding: Vec<usize> = (1..=n).filter(|&k| Shard { k, n }.holds(name)).collect();
            assert_eq!(holding.len(), 1, "{name}: {holding:?}");
            sizes[holding[0] - 1] += 1;
        }
        // Balanced on average: 125 a slice, a binomial spread of about 10.
        assert!(sizes.iter().all(|&s| (85..=165).contains(&s)), "{sizes:?}");
        // The assignment is a function of the name alone, and fixed: these
        // values were computed once, and a course's machines must agree.
        let fixed: Vec<usize> = ["ada", "grace", "alan", "edsger"]
            .iter()
            .map(|n| slice_of(n, 8))
            .collect();
        assert_eq!(fixed, FIXED);
    }

    /// `slice_of` of ada, grace, alan and edsger in 8 slices, computed
    /// apart from this code (a few lines of Python with the same constants).
    const FIXED: [usize; 4] = [2, 3, 5, 3];
}
