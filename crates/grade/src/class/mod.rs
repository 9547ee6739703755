//! Grading a class: the student folders listed, each checked, graded side
//! by side (or read from the rerun cache when their files and the
//! reference are those of the last run), with a progress bar.

pub mod merge;
pub mod shard;
pub mod source_paths;
pub mod student;
pub mod submission;

use std::path::{Path, PathBuf};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};
use serde::{Deserialize, Serialize};

use crate::class::student::grade;
use crate::class::submission::{check, files, hash_files, ignore_rules};
use crate::judging::reference::{Reference, Settings};
use crate::judging::verdict::StudentResult;
use crate::report::copy_pictures;
use crate::sandbox::beneath::clean_line;

/// The student folders of `class`, by name: every entry but hidden ones
/// (`.git`, `.DS_Store`); those that are not folders are refused later,
/// with a message.
pub fn list(class: &Path) -> Result<Vec<String>, String> {
    let entries = std::fs::read_dir(class)
        .map_err(|e| format!("cannot list the class folder {}: {e}", class.display()))?;
    let mut names: Vec<String> = entries
        .filter_map(|e| Some(e.ok()?.file_name().to_string_lossy().into_owned()))
        .filter(|name| !name.starts_with('.'))
        .collect();
    names.sort();
    Ok(names)
}

/// A name for each student's files and links: letters, digits, `-` and
/// `_`, never starting with `_` (the report's own folders do), unique.
pub fn slugs(names: &[String]) -> Vec<String> {
    let mut taken: Vec<String> = Vec::new();
    for name in names {
        let mut slug: String = name
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() || c == '-' {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect();
        if slug.is_empty() || slug.starts_with('_') {
            slug.insert(0, 's');
        }
        let base = slug.clone();
        let mut n = 2;
        while taken.contains(&slug) {
            slug = format!("{base}-{n}");
            n += 1;
        }
        taken.push(slug);
    }
    taken
}

/// A student's cached result, with what it was graded from.
#[derive(Serialize, Deserialize)]
struct Cached {
    key: String,
    result: StudentResult,
}

/// Grades the students `names` of `class`, whose slugs are `slugs` (made
/// from the whole class's names, so that a slice of it names each student
/// as the whole class does), `again`: ignoring the cache, `settings.jobs`
/// side by side; the results, in the order of `names`, and how many were
/// graded (not read from the cache).
pub fn grade_class(
    class: &Path,
    (names, slugs): (&[String], &[String]),
    reference: &Reference,
    settings: &Settings,
    (out, again): (&Path, bool),
) -> (Vec<StudentResult>, usize) {
    let bar = progress_bar(names.len());
    let mut results: Vec<Option<StudentResult>> = vec![None; names.len()];
    let mut graded = 0;
    let items: Vec<usize> = (0..names.len()).collect();
    let work = |i: usize| {
        bar.set_message(clean_line(&names[i]));
        // Whatever goes wrong in one student's grading (a bug of the
        // grader's their files found), the others are graded and every
        // output written, with this student marked.
        let graded = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            one(
                class,
                &names[i],
                &slugs[i],
                reference,
                settings,
                (out, again),
            )
        }));
        let (result, fresh) = graded.unwrap_or_else(|_| {
            let result = StudentResult {
                name: names[i].clone(),
                slug: slugs[i].clone(),
                refused: Some(
                    "grading failed on this folder (an error of the grader's, \
                     reported to the teacher); the others were graded"
                        .to_owned(),
                ),
                ..StudentResult::default()
            };
            (result, true)
        });
        (i, result, fresh)
    };
    crate::pool::for_each(items, settings.jobs, work, |(i, result, fresh)| {
        graded += usize::from(fresh);
        let name = clean_line(&result.name);
        let verdict = match (&result.refused, fresh) {
            (Some(reason), _) => format!("{name}: not graded: {}", clean_line(reason)),
            (None, true) => format!("{name}: graded in {:.0} s", result.seconds),
            (None, false) => format!("{name}: unchanged since the last run"),
        };
        // A hidden bar (output not a terminal) prints nothing: say it anyway.
        if bar.is_hidden() {
            eprintln!("{verdict}");
        } else {
            bar.println(verdict);
        }
        results[i] = Some(result);
        bar.inc(1);
    });
    bar.finish_and_clear();
    (results.into_iter().flatten().collect(), graded)
}

/// The progress bar: students done, of how many, time left.
fn progress_bar(count: usize) -> ProgressBar {
    let bar = ProgressBar::new(count as u64);
    let style = ProgressStyle::with_template(
        "[{elapsed_precise}] {wide_bar} {pos}/{len} students, about {eta} left ({msg})",
    );
    if let Ok(style) = style {
        bar.set_style(style);
    }
    bar.enable_steady_tick(Duration::from_secs(1));
    bar
}

/// One student: checked, then read from the cache or graded (and cached).
/// True if it was graded now.
fn one(
    class: &Path,
    name: &str,
    slug: &str,
    reference: &Reference,
    settings: &Settings,
    (out, again): (&Path, bool),
) -> (StudentResult, bool) {
    let refused = |reason: String| StudentResult {
        name: name.to_owned(),
        slug: slug.to_owned(),
        refused: Some(reason),
        ..StudentResult::default()
    };
    let sandboxed = settings.sandbox.sandboxed;
    let mut submission = match check(class, name, (&reference.record, sandboxed)) {
        Ok(submission) => submission,
        Err(reason) => return (refused(reason), false),
    };
    let listed = files(&mut submission, &ignore_rules(&reference.base.copy));
    let hash = listed.and_then(|l| hash_files(&submission, &l).map(|hash| (l, hash)));
    let (listed, hash) = match hash {
        Ok(found) => found,
        Err(reason) => return (refused(reason), false),
    };
    let key = format!(
        "{} {hash} {} {}",
        crate::judging::CACHE_FORMAT,
        reference.hash,
        settings_key(settings)
    );
    let cache = cache_path(&settings.cache, slug);
    // The pictures are kept in the cache with the result, and copied to
    // where the report shows them: the cache may serve another output
    // folder (--cache), whose report has never seen them.
    let (kept, report) = (settings.cache.join("pictures"), out.join("report"));
    if !again
        && let Some(result) = cached(&cache, &key, name)
        && copy_pictures(&result, &kept, &report).is_ok()
    {
        return (result, false);
    }
    let work = settings.cache.join("work");
    let mut result = grade(
        (&submission, &listed),
        slug,
        reference,
        settings,
        (&work, &kept.join(slug)),
    );
    if let Err(e) = copy_pictures(&result, &kept, &report) {
        result.refused = Some(e);
    }
    // Not graded here means grading itself failed (a file it could not
    // copy): the next run tries again.
    if result.refused.is_none() {
        store(&cache, key, &result);
    }
    (result, true)
}

/// What in the settings changes a result: all of them but how many run
/// side by side and where the cache and the outputs are. Written from the
/// settings as a whole, so that a setting added later (the seed of what is
/// judged) is part of it without more code: it keys the cache, and slices
/// of a class merge only if theirs are equal (`class/merge.rs`).
pub fn settings_key(settings: &Settings) -> String {
    let what_changes_a_result = Settings {
        jobs: 0,
        cargo_jobs: 0,
        cache: PathBuf::new(),
        exclude: Vec::new(),
        sandbox: std::sync::Arc::new(settings.sandbox.key()),
        ..settings.clone()
    };
    format!("{what_changes_a_result:?}")
}

/// Where a student's result is cached (`cache`: the grading cache folder).
fn cache_path(cache: &Path, slug: &str) -> PathBuf {
    cache.join("students").join(format!("{slug}.json"))
}

/// The cached result, if it was made from `key` for this student.
fn cached(path: &Path, key: &str, name: &str) -> Option<StudentResult> {
    let text = std::fs::read_to_string(path).ok()?;
    let cached: Cached = serde_json::from_str(&text).ok()?;
    (cached.key == key && cached.result.name == name).then_some(cached.result)
}

/// Caches a result (best effort: a failure only means grading again).
fn store(path: &Path, key: String, result: &StudentResult) {
    let cached = Cached {
        key,
        result: result.clone(),
    };
    if let Ok(json) = serde_json::to_vec(&cached) {
        let _ = ch00_toolkit::image::write_atomically(path, &json);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slugs_are_safe_and_unique() {
        let names = ["Ada Lovelace", "ada_lovelace", "_x", "=cmd", "ok-1"].map(String::from);
        assert_eq!(
            slugs(&names),
            ["ada_lovelace", "ada_lovelace-2", "s_x", "s_cmd", "ok-1"]
        );
    }
}
