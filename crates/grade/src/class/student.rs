//! Grading one student: their code in a fresh copy of the reference, each
//! chapter built and tested there under the limits (the tests' messages are
//! the feedback), then each exercise judged by what its code computed on
//! the probe's drawn inputs, outside the sandbox (`judging/rule.rs`).
//!
//! The copy is the reference's base copy with the student's own folders
//! (each exercise chapter's `src/`) in place of the reference's: so their
//! tests, pictures, manifest, Cargo files, lock file and the grader's probe
//! are the reference's, and no build script of theirs is there to run.
//! Their folder is only read. After their runs, any of the reference's
//! files in the copy that changed is flagged.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::build::cargo::{Place, cargo_test};
use crate::class::submission::{Entry, Submission, changes};
use crate::judging::outcomes::{Outcomes, name_of, outcomes};
use crate::judging::reference::{Reference, Settings};
use crate::judging::verdict::{ChapterRun, Picture, StudentResult, Verdict};
use crate::sandbox::beneath::{Refused, clean_line, clean_name};
use crate::sandbox::limits::{Limits, Ran, run};
use crate::sandbox::outbound;
use workbench::chapters::ChapterEntry;
use workbook::handout::share::copy_keeping_time;
use workbook::progress::{TestOutput, parse};

/// Grades `submission` in a copy under `work`, and copies the pictures of
/// its failures into `pictures` (the report's folder for this student).
pub fn grade(
    (submission, listed): (&Submission, &BTreeMap<PathBuf, Entry>),
    slug: &str,
    reference: &Reference,
    settings: &Settings,
    (work, pictures): (&Path, &Path),
) -> StudentResult {
    let start = Instant::now();
    let mut result = StudentResult {
        name: submission.name.clone(),
        slug: slug.to_owned(),
        warnings: submission.warnings.clone(),
        ..StudentResult::default()
    };
    // The copy, and beside it (in no run's sandbox but as a read-only
    // mount) the probes kept for it.
    let (copy, probes) = (work.join(slug), work.join(format!("{slug}.probes")));
    if let Err(e) = grade_in(
        (submission, listed),
        (reference, settings),
        (&copy, &probes),
        pictures,
        &mut result,
    ) {
        result.refused = Some(e);
    }
    let _ = std::fs::remove_dir_all(&copy);
    let _ = std::fs::remove_dir_all(&probes);
    result.seconds = start.elapsed().as_secs_f64();
    result.bounded()
}

/// [`grade`], in the copy at `copy`.
fn grade_in(
    (submission, listed): (&Submission, &BTreeMap<PathBuf, Entry>),
    (reference, settings): (&Reference, &Settings),
    (copy, probes): (&Path, &Path),
    pictures: &Path,
    result: &mut StudentResult,
) -> Result<(), String> {
    let changed = changes(submission, listed, reference)?;
    (result.flags, result.notes) = (submission.flags.clone(), changed.notes);
    result.flags.extend(changed.flags);
    let theirs: Vec<&PathBuf> = (listed.iter())
        .filter(|(path, entry)| matches!(entry, Entry::File(_)) && reference.is_students(path))
        .map(|(path, _)| path)
        .collect();
    let place = write_copy((reference, settings), submission, &theirs, (copy, probes))?;
    let target = place.outside(&place.target);
    reference.shared.put(&reference.base.target, &target)?;
    let _ = std::fs::remove_dir_all(pictures);
    result.seed = reference.expected.seed;
    // First every chapter's build and tests (their messages are the
    // student's feedback); then the probes, which were built before any of
    // the student's code ran. So nothing a probe run is given or writes
    // reaches a run whose output the student sees.
    let mut runs = Vec::new();
    for chapter in &settings.chapters {
        let probed =
            (reference.exercises_of(&chapter.folder)).any(|e| reference.expected.probes(&e.id));
        let (mut chapter_run, found) = run_chapter(&place, chapter, settings, probed)?;
        let from_tests: Vec<Verdict> = (reference.exercises_of(&chapter.folder))
            .map(|exercise| judge(exercise, &chapter_run, &found))
            .collect();
        if chapter_run.compiled {
            let all = reference.tests.chapters.get(&chapter.folder);
            let missing = all.map(|t| t.iter().filter(|t| !found.0.contains_key(*t)).count());
            chapter_run.unfinished = missing.unwrap_or(0);
        }
        chapter_run.pictures = keep_pictures(&place, chapter, pictures, &mut result.flags)?;
        runs.push((chapter, chapter_run, from_tests));
    }
    // What the tests left in the build folder, looked through before the
    // probes run: a file the probe's run leaves could be named with what
    // the probe was given (the seed), and the flags reach the student.
    result.flags.extend(crate::judging::rule::touched(&place));
    for (chapter, chapter_run, from_tests) in runs {
        let judged = crate::judging::rule::chapter(
            &place,
            chapter,
            (reference, settings),
            &chapter_run,
            from_tests,
            &result.exercises,
        );
        result.exercises.extend(judged);
        result.chapters.push(chapter_run);
    }
    result.notes.extend(place.notes());
    let contradictions = crate::judging::rule::contradictions(&result.exercises, &result.chapters);
    result.flags.extend(contradictions);
    result
        .flags
        .extend(crate::judging::rule::tampered(&place.copy, reference));
    Ok(())
}

/// The reference's base copy at `copy`, with the student's own files
/// (`theirs`, relative to `dir`) in place of the reference's students'
/// folders. Symlinks are never copied; the copy is made fresh.
fn write_copy(
    (reference, settings): (&Reference, &Settings),
    submission: &Submission,
    theirs: &[&PathBuf],
    (copy, probes): (&Path, &Path),
) -> Result<Place, String> {
    if copy.exists() {
        std::fs::remove_dir_all(copy)
            .map_err(|e| format!("cannot clear {}: {e}", copy.display()))?;
    }
    // The reference's files keep the base copy's modification times, so
    // that cargo finds the shared crates built from them fresh (see
    // share.rs); the student's are new files, newer than any build.
    let copy_one = |from: &Path, to: &Path| {
        if let Some(parent) = to.parent() {
            std::fs::create_dir_all(parent).map_err(|e| e.to_string())?;
        }
        copy_keeping_time(from, to).map_err(|e| format!("cannot copy {}: {e}", from.display()))
    };
    for path in reference.files() {
        if !reference.is_students(path) {
            copy_one(&reference.base.copy.join(path), &copy.join(path))?;
        }
    }
    for path in &reference.probe_files {
        let to = copy.join(path);
        copy_one(&reference.base.copy.join(path), &to)?;
        read_only(&to)?;
    }
    for path in theirs {
        let to = copy.join(path);
        if let Some(parent) = to.parent() {
            std::fs::create_dir_all(parent).map_err(|e| e.to_string())?;
        }
        std::fs::write(&to, submission.read(path)?)
            .map_err(|e| format!("cannot copy {}: {e}", to.display()))?;
    }
    let copy = copy.canonicalize().map_err(|e| e.to_string())?;
    let _ = std::fs::remove_dir_all(probes);
    Place::student(&copy, probes, &settings.sandbox)
}

/// Makes the file at `path` read-only.
fn read_only(path: &Path) -> Result<(), String> {
    let mut permissions = std::fs::metadata(path)
        .map_err(|e| format!("{}: {e}", path.display()))?
        .permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(path, permissions).map_err(|e| format!("{}: {e}", path.display()))
}

/// What one chapter's test run printed, read two ways.
pub struct Found(pub Outcomes, pub TestOutput);

/// Builds the chapter's tests (under the build limits), then runs them
/// (under the test limits).
fn run_chapter(
    place: &Place,
    chapter: &ChapterEntry,
    settings: &Settings,
    probed: bool,
) -> Result<(ChapterRun, Found), String> {
    let package = chapter.package();
    let mut done = ChapterRun {
        folder: chapter.folder.clone(),
        ..ChapterRun::default()
    };
    let build = cargo_test(place, &package, true, settings.cargo_jobs);
    let built = run(build, &settings.build)?;
    done.build_seconds = built.seconds;
    if !built.success {
        done.trouble = trouble(&built, &settings.build, "the build");
        if done.trouble.is_none() {
            done.compile_error = Some(compile_error(&built.text));
        }
        return Ok((done, Found(Outcomes::new(), TestOutput::default())));
    }
    done.compiled = true;
    if probed {
        // Before any of the student's code runs: what decides the points is
        // built from the sources alone, whatever the tests then do to the
        // files of their own target folder.
        done.probe_built = Some(crate::judging::rule::build_probe(place, chapter, settings));
    }
    let tested = run(
        cargo_test(place, &package, false, settings.cargo_jobs),
        &settings.test,
    )?;
    done.test_seconds = tested.seconds;
    done.trouble = trouble(&tested, &settings.test, "the tests");
    let parsed = parse(&tested.text);
    (done.passed, done.failed) = (parsed.passed, parsed.failed);
    Ok((done, Found(outcomes(&tested.text, "unknown"), parsed)))
}

/// The first compile error of a failed build, or cargo's last error line.
fn compile_error(text: &str) -> String {
    let parsed = parse(text);
    parsed.compile_error.unwrap_or_else(|| {
        let last = text.lines().rev().find(|l| l.starts_with("error"));
        last.unwrap_or("the build failed").to_owned()
    })
}

/// What stopped a run, if anything did: the time limit, the output cap, a
/// stack overflow, the memory limit, a signal.
fn trouble(ran: &Ran, limits: &Limits, what: &str) -> Option<String> {
    let mib = |bytes: u64| bytes >> 20;
    if ran.timed_out {
        Some(format!(
            "{what} timed out after {} s (an endless loop?): killed",
            limits.time.as_secs()
        ))
    } else if ran.output_capped {
        Some(format!(
            "{what} printed more than {} MiB: killed",
            mib(limits.output as u64)
        ))
    } else if ran.text.contains("has overflowed its stack") {
        Some(format!(
            "{what} crashed: a stack overflow (endless recursion?)"
        ))
    } else if ran.text.contains("memory allocation of") {
        Some(format!(
            "{what} ran out of memory (limit {} MiB per process)",
            mib(limits.memory)
        ))
    } else {
        let signal = ran.text.lines().find(|l| l.contains("(signal: "))?;
        let signal = signal.split("(signal: ").nth(1)?.trim_end_matches(')');
        Some(format!("{what} crashed (signal {signal})"))
    }
}

/// An exercise's verdict by its tests: it passes when every test that
/// grades it passed. Otherwise, the first failing test (in the chapter's
/// order) and its message, as progress shows it. This is the feedback of
/// an exercise that the probe judges (`judging/rule.rs`), and the verdict of one
/// it does not cover yet.
fn judge(
    exercise: &crate::judging::exercise_tests::ExerciseTests,
    run: &ChapterRun,
    found: &Found,
) -> Verdict {
    let Found(outcomes, parsed) = found;
    let mut verdict = Verdict {
        id: exercise.id.clone(),
        chapter: exercise.chapter.clone(),
        ..Verdict::default()
    };
    if let Some(error) = &run.compile_error {
        verdict.message = Some(format!("does not compile: {error}"));
        return verdict;
    }
    let first = (exercise.tests.iter()).find(|t| outcomes.get(*t) != Some(&true));
    let Some(test) = first else {
        verdict.passed = true;
        return verdict;
    };
    let name = name_of(test);
    let panic = (parsed.panics.iter()).find(|(t, _)| t == name);
    verdict.message = Some(match (outcomes.get(test), panic) {
        (_, Some((_, message))) => format!("test {name}: {message}"),
        (Some(_), None) => format!("test {name} failed"),
        (None, None) => match &run.trouble {
            Some(trouble) => format!("test {name} did not finish: {trouble}"),
            None => format!("test {name} did not run"),
        },
    });
    verdict
}

/// Copies the chapter's failure pictures (the three-panel diffs the
/// snapshot checks write into the copy's target/snapshot-failures/) into
/// `pictures/<folder>/`; the list of them, relative to the report folder
/// (`pictures`' parent). Everything is read beneath the build folder with
/// no link on the way (`sandbox/beneath.rs`): a regular file of a bounded size,
/// with a clean name, at most [`MOST_PICTURES`] of them and
/// [`outbound::MAX_CHAPTER_BYTES`] together, within a time.
/// What else stands there is refused, and `flags` say so.
fn keep_pictures(
    place: &Place,
    chapter: &ChapterEntry,
    pictures: &Path,
    flags: &mut Vec<String>,
) -> Result<Vec<Picture>, String> {
    let folder = Path::new("snapshot-failures").join(&chapter.folder);
    let shown = format!("target/snapshot-failures/{}", chapter.folder);
    let opened = place.target_folder()?.folder(&folder);
    let listed = opened.and_then(|failures| Ok((failures.entries()?, failures)));
    let (entries, failures) = match listed {
        Ok(listed) => listed,
        Err(Refused::Missing) => return Ok(Vec::new()),
        Err(why) => {
            flags.push(format!("failure pictures {shown}: {why}"));
            return Ok(Vec::new());
        }
    };
    let by = Instant::now() + outbound::MAX_TIME;
    let slug = pictures.file_name().unwrap_or_default().to_string_lossy();
    let (mut kept, mut bytes_kept) = (Vec::new(), 0);
    for (name, _) in entries {
        let name = name.to_string_lossy();
        let Some(stem) = name.strip_suffix(".diff.png") else {
            continue;
        };
        if !clean_name(stem) {
            flags.push(format!(
                "failure picture in {shown} named {:?}: a control character in its name: refused",
                clean_line(stem)
            ));
            continue;
        }
        if kept.len() == MOST_PICTURES {
            flags.push(format!(
                "more than {MOST_PICTURES} failure pictures in {shown}: the rest refused"
            ));
            break;
        }
        let room = outbound::MAX_CHAPTER_BYTES - bytes_kept;
        let read = failures.read(Path::new(&*name), outbound::MAX_BYTES.min(room), by);
        let bytes = match read {
            Ok(bytes) => bytes,
            Err(Refused::TooLarge(_)) if room < outbound::MAX_BYTES => {
                flags.push(format!(
                    "failure pictures in {shown} beyond the {} MiB a chapter's may hold: \
                     the rest refused",
                    outbound::MAX_CHAPTER_BYTES >> 20
                ));
                break;
            }
            Err(why) => {
                flags.push(format!("failure picture {shown}/{name}: {why}"));
                continue;
            }
        };
        bytes_kept += bytes.len() as u64;
        let to = pictures.join(&chapter.folder).join(&*name);
        outbound::write(&to, &bytes)?;
        let diff = format!("{slug}/{}/{name}", chapter.folder);
        kept.push(Picture {
            name: stem.to_owned(),
            diff: Some(diff),
        });
    }
    Ok(kept)
}

/// The most failure pictures a chapter's run may leave (it has a few
/// snapshot tests).
const MOST_PICTURES: usize = 32;

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn what_stopped_a_run_is_named() {
        let limits = Limits {
            time: Duration::from_secs(60),
            memory: 4 << 30,
            output: 16 << 20,
        };
        let said = |ran: Ran| trouble(&ran, &limits, "the tests").unwrap_or_default();
        let printed = |text: &str| Ran {
            text: text.to_owned(),
            ..Ran::default()
        };
        let timed_out = Ran {
            timed_out: true,
            ..Ran::default()
        };
        assert!(said(timed_out).contains("timed out after 60 s"));
        let flood = Ran {
            output_capped: true,
            ..Ran::default()
        };
        assert!(said(flood).contains("printed more than 16 MiB"));
        let overflow =
            "\nthread 'deep' has overflowed its stack\nfatal runtime error: stack overflow";
        assert!(said(printed(overflow)).contains("a stack overflow"));
        let memory = "memory allocation of 1099511627776 bytes failed\n";
        assert!(said(printed(memory)).contains("ran out of memory (limit 4096 MiB"));
        let signal = "  process didn't exit successfully: `x` (signal: 11, SIGSEGV: invalid memory reference)";
        assert!(said(printed(signal)).contains("crashed (signal 11, SIGSEGV"));
        assert_eq!(said(printed("test result: ok. 3 passed")), "");
    }
}
