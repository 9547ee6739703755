//! Which tests grade which exercise: those that fail when its solution is
//! taken out. The reference's own test binaries are run with one exercise
//! taken out at a time (`RAYBOOK_TAKE_OUT`, as `cargo test --workspace`
//! checks that every exercise makes a test of its chapter fail), once per
//! reference: the result is cached beside the base copy, keyed by the hash
//! of the reference's files.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::build::cargo::{Place, TestBinary, test_binary};
use crate::judging::outcomes::{Outcomes, outcomes};
use crate::pool;
use crate::sandbox::limits::{Limits, run};
use workbook::regions::Region;

/// An exercise and the tests that grade it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ExerciseTests {
    /// `ch03-lambert`.
    pub id: String,
    /// Its chapter's folder, `03-lambert`.
    pub chapter: String,
    /// Its one-line hint.
    pub hint: String,
    /// The tests of its chapter that fail without its solution, keyed as
    /// in [`crate::judging::outcomes`], in the order the chapter's files write them.
    pub tests: Vec<String>,
}

/// The tests of the chapters graded and of their exercises.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Tests {
    /// The exercises, in the chapters' order.
    pub exercises: Vec<ExerciseTests>,
    /// Every test of each chapter's test binaries, by chapter folder.
    pub chapters: BTreeMap<String, Vec<String>>,
}

/// What the cache file holds.
#[derive(Serialize, Deserialize)]
struct Cached {
    reference: String,
    tests: Tests,
}

/// The tests of each exercise: from the cache at `cache` if it was made
/// for the reference `hash`, else by running `binaries` (each chapter's,
/// by folder) once per exercise of `regions`, `jobs` at a time.
pub fn exercise_tests(
    place: &Place,
    binaries: &BTreeMap<String, Vec<TestBinary>>,
    regions: &[(String, Region)],
    (limits, jobs): (&Limits, usize),
    (cache, hash): (&Path, &str),
) -> Result<Tests, String> {
    let chapters: Vec<&str> = binaries.keys().map(String::as_str).collect();
    let key = format!(
        "{} {hash} {}",
        crate::judging::CACHE_FORMAT,
        chapters.join(",")
    );
    if let Ok(text) = std::fs::read_to_string(cache)
        && let Ok(cached) = serde_json::from_str::<Cached>(&text)
        && cached.reference == key
    {
        return Ok(cached.tests);
    }
    let mut baselines = BTreeMap::new();
    for (chapter, bins) in binaries {
        baselines.insert(chapter.clone(), baseline(place, chapter, bins, limits)?);
    }
    let mut found = Vec::new();
    let mut failures = Vec::new();
    let work = |(chapter, region): &(String, Region)| -> Result<ExerciseTests, String> {
        let bins = &binaries[chapter];
        let without = run_all(place, bins, &region.id, limits)?;
        let mut tests: Vec<String> = (baselines[chapter].keys())
            .filter(|test| without.get(*test) != Some(&true))
            .cloned()
            .collect();
        if tests.is_empty() {
            return Err(format!(
                "no test of {chapter} fails without exercise {}: it cannot be graded",
                region.id
            ));
        }
        reading_order(&bins[0].package_dir, &mut tests);
        Ok(ExerciseTests {
            id: region.id.clone(),
            chapter: chapter.clone(),
            hint: region.hint.clone(),
            tests,
        })
    };
    let chosen: Vec<_> = regions
        .iter()
        .filter(|(c, _)| binaries.contains_key(c))
        .collect();
    pool::for_each(chosen, jobs, work, |r| match r {
        Ok(e) => found.push(e),
        Err(e) => failures.push(e),
    });
    if !failures.is_empty() {
        return Err(failures.join("\n"));
    }
    let order = |e: &ExerciseTests| regions.iter().position(|(_, r)| r.id == e.id);
    found.sort_by_key(order);
    most_specific_first(&mut found);
    let chapters = (baselines.into_iter())
        .map(|(chapter, all)| (chapter, all.into_keys().collect()))
        .collect();
    let tests = Tests {
        exercises: found,
        chapters,
    };
    let cached = Cached {
        reference: key,
        tests: tests.clone(),
    };
    let json = serde_json::to_vec_pretty(&cached).map_err(|e| e.to_string())?;
    ch00_toolkit::image::write_atomically(cache, &json)
        .map_err(|e| format!("cannot write {}: {e}", cache.display()))?;
    Ok(tests)
}

/// The chapter's tests with nothing taken out: every one must pass.
fn baseline(
    place: &Place,
    chapter: &str,
    bins: &[TestBinary],
    limits: &Limits,
) -> Result<Outcomes, String> {
    let all = run_all(place, bins, "", limits)?;
    let failing: Vec<&String> = all.iter().filter(|(_, ok)| !**ok).map(|(t, _)| t).collect();
    if !failing.is_empty() || all.is_empty() {
        return Err(format!(
            "the reference fails its own tests of {chapter} (or has none): {failing:?}"
        ));
    }
    Ok(all)
}

/// Runs each binary with `take_out` taken out; every test's outcome.
fn run_all(
    place: &Place,
    bins: &[TestBinary],
    take_out: &str,
    limits: &Limits,
) -> Result<Outcomes, String> {
    let mut all = Outcomes::new();
    for bin in bins {
        let command = test_binary(place, &bin.path, &bin.package_dir, take_out);
        let ran = run(command, limits)?;
        if ran.timed_out || ran.output_capped {
            return Err(format!(
                "the reference's {} with {take_out:?} taken out did not finish within the limits",
                bin.target
            ));
        }
        all.extend(outcomes(&ran.text, &bin.target));
    }
    Ok(all)
}

/// Puts each exercise's own tests before those it shares with other
/// exercises (a chapter's snapshot needs them all), keeping the reading
/// order among equals: so the first failing test, whose message grading
/// shows, is the one most about that exercise.
fn most_specific_first(exercises: &mut [ExerciseTests]) {
    let mut sharing: BTreeMap<String, usize> = BTreeMap::new();
    for test in exercises.iter().flat_map(|e| &e.tests) {
        *sharing.entry(test.clone()).or_default() += 1;
    }
    for exercise in exercises {
        exercise.tests.sort_by_key(|t| sharing[t]);
    }
}

/// Sorts test keys (`target::name`) in the order the chapter's files
/// write them: by target, then by where `fn name(` stands in the target's
/// files (its own, then the modules beside it), as progress orders a
/// chapter's failures.
pub fn reading_order(package_dir: &Path, keys: &mut [String]) {
    let mut texts: BTreeMap<String, String> = BTreeMap::new();
    keys.sort_by_cached_key(|key| {
        let (target, name) = key.split_once("::").unwrap_or(("", key));
        let text = texts
            .entry(target.to_owned())
            .or_insert_with(|| target_text(&package_dir.join(target)));
        let function = name.rsplit("::").next().unwrap_or(name);
        let at = text.find(&format!("fn {function}(")).unwrap_or(usize::MAX);
        (target.to_owned(), at, name.to_owned())
    });
}

/// A target's source, then the other `.rs` files of its folder (its
/// modules), by name.
fn target_text(file: &Path) -> String {
    let mut text = std::fs::read_to_string(file).unwrap_or_default();
    let is_root = file
        .file_name()
        .is_some_and(|n| n == "main.rs" || n == "lib.rs");
    if let (true, Some(folder)) = (is_root, file.parent()) {
        let mut others: Vec<_> = std::fs::read_dir(folder)
            .map(|entries| entries.filter_map(|e| Some(e.ok()?.path())).collect())
            .unwrap_or_default();
        others.sort();
        for other in others.iter().filter(|p| *p != file) {
            if other.extension().is_some_and(|e| e == "rs") {
                text.push_str(&std::fs::read_to_string(other).unwrap_or_default());
            }
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tests_are_ordered_as_their_files_write_them() {
        let dir = tempfile::tempdir().unwrap();
        let folder = dir.path().join("tests/chapter09");
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("main.rs"), "mod b;\n#[test]\nfn zeta() {}\n").unwrap();
        std::fs::write(folder.join("b.rs"), "#[test]\nfn alpha() {}\n").unwrap();
        let mut keys = vec![
            "tests/chapter09/main.rs::b::alpha".to_owned(),
            "tests/chapter09/main.rs::zeta".to_owned(),
            "tests/a.rs::x".to_owned(),
        ];
        reading_order(dir.path(), &mut keys);
        assert_eq!(
            keys,
            [
                "tests/a.rs::x",
                "tests/chapter09/main.rs::zeta",
                "tests/chapter09/main.rs::b::alpha"
            ]
        );
    }
}
