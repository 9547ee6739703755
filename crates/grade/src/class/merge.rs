//! `grade --merge DIR… --out FINAL`: the slices of a class (`class/shard.rs`)
//! joined into the outputs one run over the whole class writes.
//!
//! The slices must belong together, or the gradebook would mix gradings
//! that cannot be compared: each slice's record of what it was graded
//! with (the reference, every setting that changes a result, the tests,
//! the class's list of students) must equal the others' as a whole; every
//! slice 1 to N must be there, once; each must hold exactly the students
//! the hash gives it; and the reference the merge reads (`--reference`,
//! by default the workspace it runs in) must be the one they used. The
//! outputs are then written by the code a whole run uses, from the same
//! results in the same order, with the points of `--points` (or
//! `points.toml` in FINAL): the same gradebook and report, byte for byte.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::args::GradeArgs;
use crate::class::shard::{Shard, ShardFile};
use crate::class::slugs;
use crate::judging::reference::Reference;
use crate::judging::verdict::StudentResult;
use crate::report::{self, points};
use crate::sandbox::beneath::Folder;

/// A slice as read from its folder.
struct Slice {
    /// The folder that holds it (its pictures are under `report/`).
    dir: PathBuf,
    /// Its file.
    file: PathBuf,
    data: ShardFile,
}

/// `--merge`: the slices read, checked and joined, and the outputs of the
/// whole class written into `out`.
pub fn main(args: &GradeArgs, root: &Path, out: &Path) -> Result<(), String> {
    let slices = read_slices(&args.merge)?;
    complete(&slices)?;
    same(&slices)?;
    let students = join(&slices)?;
    let mut exclude: Vec<PathBuf> = slices.iter().map(|s| s.dir.clone()).collect();
    exclude.push(out.to_owned());
    let first = &slices[0].data.graded_with;
    let reference = Reference::read(root, &exclude, first.tests.clone())?;
    if reference.hash != first.reference_hash {
        return Err(format!(
            "the reference at {} (raybook {}) is not the one the slices were graded \
             against (raybook {}): its files differ. Merge with that reference \
             (--reference DIR)",
            root.display(),
            reference.record.label(),
            first.reference
        ));
    }
    copy_pictures(&slices, out)?;
    let ids: Vec<_> = reference.tests.exercises.clone();
    let points = points::Points::load(args.points.as_deref(), out, &ids)?;
    let class = report::Class {
        reference: &reference,
        points: &points,
        students: &students,
    };
    let mut written = report::write_all(out, &class)?;
    // The teacher keeps the seed with the outputs, as one run does.
    let seed = format!("{}\n", first.seed);
    written.push(report::write(&out.join("seed.txt"), seed)?);
    report::print_table(&class);
    let (count, of) = (slices.len(), students.len());
    println!("\nmerged {count} slices: {of} students");
    report::print_written(&class, &written);
    Ok(())
}

/// Every `shard-K-of-N.json` in each of `dirs`.
fn read_slices(dirs: &[PathBuf]) -> Result<Vec<Slice>, String> {
    let mut slices = Vec::new();
    for dir in dirs {
        let dir = dir
            .canonicalize()
            .map_err(|e| format!("--merge {}: {e}", dir.display()))?;
        // A slice is read as a student's file is (`sandbox/beneath.rs`): a slice
        // that is a link, a FIFO or a device, or too large, is refused in
        // the grader's words, without waiting and without quoting it.
        let folder = Folder::open(&dir)?;
        let entries =
            (folder.entries()).map_err(|e| format!("cannot list {}: {e}", dir.display()))?;
        let mut names: Vec<String> = entries
            .into_iter()
            .filter_map(|(name, _)| name.into_string().ok())
            .filter(|name| slice_named(name).is_some())
            .collect();
        if names.is_empty() {
            return Err(format!(
                "{}: no slice here (a shard-K-of-N.json that grade --shard K/N writes)",
                dir.display()
            ));
        }
        names.sort();
        for name in names {
            let file = dir.join(&name);
            let by = Instant::now() + Duration::from_secs(60);
            let bytes = (folder.read(Path::new(&name), MOST_SLICE, by))
                .map_err(|why| format!("{}: {why}", file.display()))?;
            let data: ShardFile = serde_json::from_slice(&bytes)
                .map_err(|_| format!("{}: not a slice of this grade", file.display()))?;
            if slice_named(&name) != Some(data.shard) {
                return Err(format!("{} holds slice {}", file.display(), data.shard));
            }
            let dir = dir.clone();
            slices.push(Slice { dir, file, data });
        }
    }
    Ok(slices)
}

/// The most a slice's file may hold: a class of a thousand is a few MiB.
const MOST_SLICE: u64 = 256 << 20;

/// The slice a file's name gives: `shard-3-of-8.json` is 3/8.
fn slice_named(name: &str) -> Option<Shard> {
    let middle = name.strip_prefix("shard-")?.strip_suffix(".json")?;
    let (k, n) = middle.split_once("-of-")?;
    format!("{k}/{n}").parse().ok()
}

/// Every slice 1 to N, once, all of the same N.
fn complete(slices: &[Slice]) -> Result<(), String> {
    let first = &slices[0];
    let n = first.data.shard.n;
    if let Some(other) = slices.iter().find(|s| s.data.shard.n != n) {
        return Err(format!(
            "slices of different runs: {} is {}, {} is {}. Merge the slices of one run \
             (and remove the others' files)",
            first.file.display(),
            first.data.shard,
            other.file.display(),
            other.data.shard
        ));
    }
    let mut missing = Vec::new();
    for k in 1..=n {
        let given: Vec<&Slice> = slices.iter().filter(|s| s.data.shard.k == k).collect();
        match given.as_slice() {
            [] => missing.push(format!("{k}/{n}")),
            [_] => {}
            [a, b, ..] => {
                return Err(format!(
                    "slice {k}/{n} is given twice: {} and {}",
                    a.file.display(),
                    b.file.display()
                ));
            }
        }
    }
    if !missing.is_empty() {
        return Err(format!(
            "slices missing: {} (no shard-K-of-{n}.json for them in the folders given): \
             grade them with --shard, or wait for them to finish",
            missing.join(", ")
        ));
    }
    Ok(())
}

/// Every slice graded with what the first was: its record compared as a
/// whole, field by field, so that a field added to it is compared too.
fn same(slices: &[Slice]) -> Result<(), String> {
    let record = |s: &Slice| serde_json::to_value(&s.data.graded_with).map_err(|e| e.to_string());
    let first = record(&slices[0])?;
    for slice in &slices[1..] {
        let other = record(slice)?;
        let (Some(a), Some(b)) = (first.as_object(), other.as_object()) else {
            return Err("a slice's record is not an object".to_owned());
        };
        let differs = a.iter().find(|(key, value)| b.get(*key) != Some(*value));
        if let Some((key, value)) = differs {
            return Err(format!(
                "{} and {} were graded with different {key}: {}. Grade every slice of a \
                 class with the same reference, class, settings and seed",
                slices[0].file.display(),
                slice.file.display(),
                difference(value, b.get(key).unwrap_or(&serde_json::Value::Null))
            ));
        }
    }
    Ok(())
}

/// Where two values differ, in a few words: the first place their JSON
/// texts part, with a little of what comes before.
fn difference(a: &serde_json::Value, b: &serde_json::Value) -> String {
    let (a, b) = (a.to_string(), b.to_string());
    let same: usize = (a.chars().zip(b.chars()))
        .take_while(|(x, y)| x == y)
        .map(|(x, _)| x.len_utf8())
        .sum();
    let from = a[..same].char_indices().rev().nth(30).map_or(0, |(i, _)| i);
    let part = |text: &str| -> String { text[from..].chars().take(70).collect() };
    format!("…{} against …{}", part(&a), part(&b))
}

/// The slices' results in the class's order, each slice holding exactly
/// its students, named as the whole class names them.
fn join(slices: &[Slice]) -> Result<Vec<StudentResult>, String> {
    let class = &slices[0].data.graded_with.class;
    let slugs = slugs(class);
    let mut joined = Vec::with_capacity(class.len());
    for (name, slug) in class.iter().zip(&slugs) {
        let slice = (slices.iter())
            .find(|s| s.data.shard.holds(name))
            .expect("every slice is there");
        let found = slice.data.students.iter().find(|r| r.name == *name);
        match found {
            Some(result) if result.slug == *slug => joined.push(result.clone()),
            _ => {
                return Err(format!(
                    "{}: no result for {name:?}, whom slice {} grades: \
                     was it written by another version of grade?",
                    slice.file.display(),
                    slice.data.shard
                ));
            }
        }
    }
    let held: usize = slices.iter().map(|s| s.data.students.len()).sum();
    if held != joined.len() {
        return Err(format!(
            "the slices hold {held} results for a class of {}: one holds a student it \
             does not grade",
            joined.len()
        ));
    }
    Ok(joined)
}

/// Each student's pictures, from their slice's report folder into `out`'s
/// (only those their result names, regular files, within their folder).
fn copy_pictures(slices: &[Slice], out: &Path) -> Result<(), String> {
    for slice in slices.iter().filter(|s| s.dir != out) {
        for student in &slice.data.students {
            report::copy_pictures(student, &slice.dir.join("report"), &out.join("report"))
                .map_err(|e| format!("{}: {e}", slice.file.display()))?;
        }
    }
    Ok(())
}

#[cfg(test)]
#[path = "merge_tests.rs"]
mod tests;
