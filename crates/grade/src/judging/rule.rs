//! Judging an exercise by what the student's code computed, outside the
//! sandbox: the probe's values and scenes (`judging/probe.rs`), drawn from a seed
//! the teacher keeps, against the reference's.
//!
//! The rule, for each exercise the probe covers:
//!
//! 1. **Values.** It earns its points only if its values agree with the
//!    reference's on every drawn input (`grade_probe::first_disagreement`,
//!    with the tolerance the reference's probe states). Otherwise the
//!    first input that disagrees, and both values, are its feedback.
//! 2. **Pictures.** Every seeded scene of its chapter that its code draws
//!    must come out as the reference's, within the chapters' snapshot
//!    tolerance (`workbench::compare::Tolerance::for_size`). A scene that
//!    differs while some exercise that draws it already disagrees on its
//!    values (of this chapter or an earlier one) is explained by that
//!    exercise, which has lost its points already: nothing more is taken.
//!    A scene that differs while every exercise that draws it agrees on
//!    its values shows a mistake the values cannot (how they are put
//!    together): then every exercise of the chapter that draws it loses.
//!
//! A chapter that does not compile earns nothing; a probe run that does
//! not finish in its time, crashes, or writes no output of the right form
//! leaves that exercise (or the chapter's scenes) without values, which
//! disagree. The chapters' own tests still run, for their feedback (the
//! message that names the mistake); they decide the points only of an
//! exercise the probe does not cover yet, and its verdict says so.

use std::path::Path;

use grade_probe::{Picture, first_disagreement};
use workbench::chapters::ChapterEntry;
use workbench::compare::{Tolerance, Verdict as Compared, compare};

use crate::build::cargo::Place;
use crate::judging::probe::{self, Expected};
use crate::judging::reference::{Reference, Settings};
use crate::judging::verdict::{
    ChapterRun, Disagreement, JUDGED_BY_TESTS, JUDGED_BY_VALUES, Verdict,
};
use crate::sandbox::beneath::{Kind, clean_line};

/// The verdicts of `chapter`'s exercises, from the tests' verdicts
/// (`from_tests`, kept as feedback) and the probe run in `place`;
/// `earlier` are the verdicts of the chapters before.
pub fn chapter(
    place: &Place,
    chapter: &ChapterEntry,
    (reference, settings): (&Reference, &Settings),
    run: &ChapterRun,
    from_tests: Vec<Verdict>,
    earlier: &[Verdict],
) -> Vec<Verdict> {
    let expected = &reference.expected;
    let mut verdicts: Vec<Verdict> = from_tests.into_iter().map(|v| start(v, expected)).collect();
    if !verdicts.iter().any(|v| v.judged_by == JUDGED_BY_VALUES) {
        return verdicts;
    }
    let mut probed: Vec<&mut Verdict> = (verdicts.iter_mut())
        .filter(|v| v.judged_by == JUDGED_BY_VALUES)
        .collect();
    if let Some(error) = &run.compile_error {
        for v in &mut probed {
            v.message = Some(format!("does not compile: {error}"));
        }
        return verdicts;
    }
    // Built and kept before any of the student's code ran (`class/student.rs`);
    // never built now, after their tests had their target folder.
    let built = (run.probe_built.clone()).unwrap_or_else(|| Err("not built".to_owned()));
    if let Err(error) = built {
        for v in &mut probed {
            v.message = Some(format!("the probe of its chapter does not build: {error}"));
        }
        return verdicts;
    }
    let limits = probe::limits(&settings.test);
    let binary = place.probe(&probe::feature(chapter));
    let run_one = |args: [&str; 2]| probe::run_one(place, &binary, args, expected.seed, &limits);
    for v in &mut probed {
        let outcome = run_one(["--exercise", &v.id]);
        values(v, outcome, expected);
    }
    let scenes = run_one(["--scenes", &chapter.folder]);
    let ours = expected
        .scenes
        .get(&chapter.folder)
        .map_or(&[][..], Vec::as_slice);
    pictures(ours, scenes.map(|p| p.scenes), &mut verdicts, earlier);
    verdicts
}

/// Builds the grader's probe of `chapter` in `place` and keeps it where
/// no later run can change it (`class/student.rs` does this before the
/// student's tests run); the first error if it fails.
pub fn build_probe(
    place: &Place,
    chapter: &ChapterEntry,
    settings: &Settings,
) -> Result<(), String> {
    let feature = probe::feature(chapter);
    match probe::build(
        place,
        std::slice::from_ref(&feature),
        &settings.build,
        settings.cargo_jobs,
    ) {
        Ok(ran) if ran.success => place.keep_probe(&feature),
        Ok(ran) => Err(first_error(&ran.text)),
        Err(e) => Err(e),
    }
}

/// A verdict judged by values (not passed yet), or by the tests if the
/// probe does not cover the exercise; the tests' message kept as feedback.
fn start(from_tests: Verdict, expected: &Expected) -> Verdict {
    if !expected.probes(&from_tests.id) {
        return Verdict {
            judged_by: JUDGED_BY_TESTS.to_owned(),
            ..from_tests
        };
    }
    Verdict {
        passed: false,
        judged_by: JUDGED_BY_VALUES.to_owned(),
        feedback: from_tests.message.filter(|_| !from_tests.passed),
        message: None,
        ..from_tests
    }
}

/// Judges `v` by the values the probe run gave.
fn values(v: &mut Verdict, outcome: probe::Outcome, expected: &Expected) {
    let ours = &expected.values[&v.id];
    v.cases = ours.cases.len();
    let theirs = match outcome {
        Ok(probed) => probed.exercises.into_iter().find(|x| x.id == v.id),
        Err(why) => {
            v.message = Some(format!("no values: its probe {why}"));
            return;
        }
    };
    let Some(theirs) = theirs else {
        v.message = Some("no values: its probe wrote none for it".to_owned());
        return;
    };
    // The probe writes every drawn input as it was given: a record with
    // other inputs, or another number of them, was written by someone else.
    v.forged = theirs.cases.len() != ours.cases.len()
        || (ours.cases.iter().zip(&theirs.cases)).any(|(a, b)| a.input != b.input);
    match first_disagreement(ours, &theirs) {
        None => {
            (v.passed, v.agreed) = (true, v.cases);
            v.message = Some(format!(
                "agrees with the reference on all {} drawn inputs",
                v.cases
            ));
        }
        Some(i) => {
            v.agreed = i;
            let found = theirs.cases.get(i).map(|c| &c.value);
            let disagreement = Disagreement {
                case: i + 1,
                input: ours.cases[i].input.clone(),
                expected: short(&ours.cases[i].value),
                found: found.map_or("nothing".to_owned(), short),
            };
            v.message = Some(format!(
                "disagrees on drawn input {} of {}: {}: the reference gives {}, yours {}",
                disagreement.case,
                v.cases,
                disagreement.input,
                disagreement.expected,
                disagreement.found
            ));
            v.disagreement = Some(disagreement);
        }
    }
}

/// A value as the report shows it: at most 300 characters.
fn short(value: &serde_json::Value) -> String {
    let text = value.to_string();
    match text.char_indices().nth(300) {
        Some((at, _)) => format!("{}…", &text[..at]),
        None => text,
    }
}

/// Applies the pictures' rule (module documentation) to `verdicts`, given
/// the reference's scenes `ours` and what the student's probe drew.
fn pictures(
    ours: &[Picture],
    theirs: Result<Vec<Picture>, String>,
    verdicts: &mut [Verdict],
    earlier: &[Verdict],
) {
    let disagreeing: Vec<String> = (earlier.iter().chain(verdicts.iter()))
        .filter(|v| !v.passed)
        .map(|v| v.id.clone())
        .collect();
    for (k, scene) in ours.iter().enumerate() {
        let problem = match &theirs {
            Err(why) => Some(format!("was not drawn: its probe {why}")),
            Ok(pictures) => picture_problem(scene, pictures.get(k)),
        };
        let Some(problem) = problem else { continue };
        if scene.uses.iter().any(|id| disagreeing.contains(id)) {
            continue; // explained by an exercise that lost its points already
        }
        for v in verdicts.iter_mut() {
            if v.passed && v.judged_by == JUDGED_BY_VALUES && scene.uses.contains(&v.id) {
                v.passed = false;
                v.message = Some(format!(
                    "agrees on its {} drawn inputs, but the {} {problem}",
                    v.cases, scene.name
                ));
            }
        }
    }
}

/// What is wrong with the student's picture of `scene`, if anything.
pub fn picture_problem(scene: &Picture, theirs: Option<&Picture>) -> Option<String> {
    let Some(theirs) = theirs else {
        return Some("is missing".to_owned());
    };
    let image = |p: &Picture| image::RgbImage::from_raw(p.width, p.height, p.rgb.clone());
    let (Some(expected), Some(found)) = (image(scene), image(theirs)) else {
        return Some("is not a picture".to_owned());
    };
    if theirs.name != scene.name {
        return Some("is not the scene drawn".to_owned());
    }
    let tolerance = Tolerance::for_size(scene.width, scene.height);
    match compare(&expected, &found, tolerance) {
        Compared::Pass(_) => None,
        Compared::Differs(d) => Some(format!(
            "differs from the reference's in {} of {} pixels (at most {} may differ by more \
             than {} steps)",
            d.pixels_over, d.total, tolerance.pixels, tolerance.channel
        )),
        Compared::WrongSize { found, .. } => Some(format!("is {}×{}", found.0, found.1)),
    }
}

/// The first compile error of a build's output, or its last error line.
fn first_error(text: &str) -> String {
    let line = (text.lines()).find(|l| l.starts_with("error"));
    line.unwrap_or("the build failed").to_owned()
}

/// What the teacher should look at, though no verdict changes: an
/// exercise whose values agree with the reference's while its own tests
/// reach its `todo!` (or say it is not done), as code that knows when it
/// is graded would; a chapter whose tests never finished.
pub fn contradictions(verdicts: &[Verdict], runs: &[ChapterRun]) -> Vec<String> {
    let mut flags = Vec::new();
    for v in verdicts
        .iter()
        .filter(|v| v.passed && v.judged_by == JUDGED_BY_VALUES)
    {
        let feedback = v.feedback.as_deref().unwrap_or("");
        let todo = feedback.contains(&format!("not yet implemented: {}", v.id));
        if todo || feedback.contains("not done") {
            flags.push(format!(
                "{}: its values agree with the reference's, yet its tests say it is not \
                 written: code that behaves otherwise when graded?",
                v.id
            ));
        }
    }
    for v in verdicts.iter().filter(|v| v.forged) {
        flags.push(format!(
            "{}: its probe's record is not one the probe writes (other inputs than the \
             drawn ones, or another number of them): written by the student's code?",
            v.id
        ));
    }
    for run in runs {
        let never = run.unfinished > 0
            || run
                .trouble
                .as_ref()
                .is_some_and(|t| t.contains("timed out"));
        if never && run.compiled {
            flags.push(format!("{}: its tests never finished", run.folder));
        }
    }
    flags
}

/// What the student's runs left in their build folder that no build or
/// test writes: a symlink (a folder swapped for a link), a FIFO, a socket,
/// a device, a cargo setting. Each is a flag: the run touched more than
/// its chapters' sources and their build. Walked beneath the folder, no
/// link followed (`sandbox/beneath.rs`), before the probes run: these
/// flags reach the student, and a name left by a probe's run could carry
/// what the probe was given.
pub fn touched(place: &Place) -> Vec<String> {
    let walked = place
        .target_folder()
        .map_err(|e| e.to_string())
        .and_then(|folder| folder.walk(&|_, _| false, 1_000_000));
    let entries = match walked {
        Ok(entries) => entries,
        Err(why) => {
            return vec![format!(
                "its build folder could not be looked through: {why}"
            )];
        }
    };
    let mut flags = Vec::new();
    for (path, kind) in entries {
        let shown = format!("target/{}", clean_line(&path.to_string_lossy()));
        let setting = path.components().any(|c| c.as_os_str() == ".cargo");
        match kind {
            Kind::Link => flags.push(format!("its run left a symlink at {shown}")),
            Kind::Other(what) => flags.push(format!("its run left {what} at {shown}")),
            _ if setting => flags.push(format!("its run wrote a cargo setting at {shown}")),
            _ => {}
        }
        if flags.len() >= 20 {
            flags.push("and more".to_owned());
            break;
        }
    }
    flags
}

/// The reference's files in `copy` (the tests, pictures, Cargo files and the
/// probe's sources: everything but the student's own folders) that are no
/// longer the reference's after the student's runs: each is a flag.
pub fn tampered(copy: &Path, reference: &Reference) -> Vec<String> {
    let theirs = (reference.files())
        .filter(|p| !reference.is_students(p))
        .chain(&reference.probe_files);
    let mut changed = Vec::new();
    for path in theirs {
        let (ours, in_copy) = (reference.base.copy.join(path), copy.join(path));
        let same = std::fs::symlink_metadata(&in_copy).is_ok_and(|m| {
            m.file_type().is_file()
                && std::fs::metadata(&ours).is_ok_and(|o| o.len() == m.len())
                && std::fs::read(&in_copy).ok() == std::fs::read(&ours).ok()
        });
        if !same {
            changed.push(format!("changed during the run: {}", path.display()));
        }
    }
    changed
}

#[cfg(test)]
#[path = "rule_tests.rs"]
mod tests;
