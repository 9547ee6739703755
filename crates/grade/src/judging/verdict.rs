//! What grading found for one student: kept in the rerun cache as JSON,
//! and read by every output (the points are applied when they are written,
//! so that editing the points file needs no new run).

use serde::{Deserialize, Serialize};

use crate::sandbox::beneath::clean_line;

/// One student's grading.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct StudentResult {
    /// The student's folder name.
    pub name: String,
    /// Their folder name made safe for a file name and a link (unique).
    pub slug: String,
    /// Why the folder was not graded, if it was not.
    pub refused: Option<String>,
    /// What does not stop grading but is worth knowing (another commit).
    pub warnings: Vec<String>,
    /// Files that change a verdict (tests, pictures, manifest, Cargo files,
    /// build scripts) the student changed: graded on the reference's.
    pub flags: Vec<String>,
    /// Other files the student changed outside their code (put back too),
    /// and symlinks, never followed.
    pub notes: Vec<String>,
    /// Each chapter graded.
    pub chapters: Vec<ChapterRun>,
    /// Each exercise of the chapters graded.
    pub exercises: Vec<Verdict>,
    /// Wall-clock time of their grading, in seconds.
    pub seconds: f64,
    /// The seed their exercises' inputs and scenes were drawn from.
    pub seed: u64,
}

/// A chapter's build and test run.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ChapterRun {
    /// `03-lambert`.
    pub folder: String,
    /// Did its tests compile?
    pub compiled: bool,
    /// Tests passed and failed (libtest's counts, doctests included).
    pub passed: usize,
    pub failed: usize,
    /// Tests of the reference's binaries that never reported (their binary
    /// crashed or was killed).
    pub unfinished: usize,
    /// The first compile error, if it did not compile.
    pub compile_error: Option<String>,
    /// An endless loop, a stack overflow, running out of memory, a flood of
    /// output: what stopped the run, in a few words.
    pub trouble: Option<String>,
    /// Its pictures that differ from the reference's.
    pub pictures: Vec<Picture>,
    /// Seconds to build, and to run the tests.
    pub build_seconds: f64,
    pub test_seconds: f64,
    /// Did the grader's probe of the chapter build, before any of the
    /// student's code ran? None if the chapter has no probe or its tests
    /// did not compile (not kept: it only passes from the run to the
    /// judging).
    #[serde(skip)]
    pub probe_built: Option<Result<(), String>>,
}

/// A picture that differs from its reference.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Picture {
    /// The snapshot's name: `default`.
    pub name: String,
    /// The three-panel diff (reference | mask | the student's), relative to
    /// the report folder, if the test wrote one.
    pub diff: Option<String>,
}

/// An exercise's verdict (the rule is `judging/rule.rs`'s).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    /// `ch03-lambert`.
    pub id: String,
    /// Its chapter's folder.
    pub chapter: String,
    /// Does it earn its points?
    pub passed: bool,
    /// [`JUDGED_BY_VALUES`], or [`JUDGED_BY_TESTS`] for an exercise the
    /// probe does not cover yet.
    pub judged_by: String,
    /// Why it earns its points or not, in a line: the values agreed on
    /// every input, the first input that disagreed and both values, the
    /// seeded scene that differs; or, judged by the tests, the first
    /// failing test's message.
    pub message: Option<String>,
    /// The inputs drawn, and how many agreed before the first that did not.
    pub cases: usize,
    pub agreed: usize,
    /// The first drawn input on which its values disagree.
    pub disagreement: Option<Disagreement>,
    /// The first failing test's message (the chapter's own tests, run for
    /// their feedback), when it is judged by its values.
    pub feedback: Option<String>,
    /// Its probe's record was not one the probe writes: other inputs than
    /// the drawn ones, or another number of them (a record forged by the
    /// student's code, which may write to the probe's pipe).
    #[serde(default)]
    pub forged: bool,
}

impl Verdict {
    /// What the reports say of it: why it earns its points or not, how it
    /// was judged, and the chapter's tests' message if they failed.
    pub fn explained(&self) -> String {
        let mut text = match (&self.message, self.passed) {
            (Some(message), _) => message.clone(),
            (None, true) => "passes".to_owned(),
            (None, false) => "fails".to_owned(),
        };
        if self.judged_by == JUDGED_BY_TESTS {
            text.push_str(" (judged by its chapter's tests: no probe of it yet)");
        }
        if let Some(feedback) = &self.feedback {
            text.push_str(&format!("; the chapter's tests say: {feedback}"));
        }
        text
    }
}

impl Verdict {
    /// What the student is told (Gradescope): why it earns its points or
    /// not, without what the teacher keeps. Nothing of the probe's run
    /// reaches a student: not the seed, not a drawn input, not the
    /// reference's value (with which a table of answers could be built
    /// over resubmissions), not a path or what the probe printed. Their
    /// chapter's tests' message, which names the mistake, is theirs.
    pub fn for_student(&self) -> String {
        let mut text = if self.judged_by == JUDGED_BY_TESTS || self.passed {
            return clean_line(&self.explained());
        } else if let Some(d) = &self.disagreement {
            format!(
                "disagrees with the reference on drawn input {} of {} (the inputs are drawn \
                 afresh at each grading and stay with the teacher)",
                d.case, self.cases
            )
        } else {
            match self.message.as_deref().unwrap_or("fails") {
                m if m.starts_with("no values: its probe panicked") => {
                    "no values: your code panicked when the grader called it (your chapter's \
                     tests show your own panics)"
                        .to_owned()
                }
                m => m.to_owned(),
            }
        };
        if let Some(feedback) = &self.feedback {
            text.push_str(&format!("; the chapter's tests say: {feedback}"));
        }
        clean_line(&text)
    }
}

/// An exercise judged by what its code computed on the drawn inputs.
pub const JUDGED_BY_VALUES: &str = "values";
/// An exercise judged by its chapter's tests (no probe of it yet).
pub const JUDGED_BY_TESTS: &str = "tests";

/// The first drawn input on which a student's values disagree.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Disagreement {
    /// Its number among the inputs, from 1.
    pub case: usize,
    /// The input, as the probe shows it.
    pub input: String,
    /// The reference's value and the student's (JSON, shortened).
    pub expected: String,
    pub found: String,
}

impl StudentResult {
    /// Did every chapter graded compile? (False if it was not graded.)
    pub fn compiled(&self) -> bool {
        self.refused.is_none() && self.chapters.iter().all(|c| c.compiled)
    }

    /// The verdict of exercise `id`.
    pub fn verdict(&self, id: &str) -> Option<&Verdict> {
        self.exercises.iter().find(|v| v.id == id)
    }

    /// This result with every text cut to [`MOST_CHARS`] characters and
    /// each list of flags, notes and warnings to [`MOST_LINES`] (and a line
    /// saying how many more). A student makes both as large as they like
    /// (a panic message of one 16 MiB line, a hundred thousand files added
    /// each flagged by its path), and every output repeats them: the HTML
    /// report twice, the gradebook, JUnit, the cache. Bounded here, no
    /// student makes the class's report too large to open.
    pub fn bounded(mut self) -> StudentResult {
        let texts = (self.refused.iter_mut())
            .chain(
                self.chapters
                    .iter_mut()
                    .flat_map(|c| (c.compile_error.iter_mut()).chain(c.trouble.iter_mut())),
            )
            .chain(
                self.exercises
                    .iter_mut()
                    .flat_map(|v| (v.message.iter_mut()).chain(v.feedback.iter_mut())),
            );
        texts.for_each(cut);
        for list in [&mut self.flags, &mut self.notes, &mut self.warnings] {
            if list.len() > MOST_LINES {
                let more = list.len() - MOST_LINES;
                list.truncate(MOST_LINES);
                list.push(format!("and {more} more"));
            }
            list.iter_mut().for_each(cut);
        }
        self
    }

    /// What stopped any chapter's run, one line per chapter.
    pub fn troubles(&self) -> Vec<String> {
        self.chapters
            .iter()
            .filter_map(|c| {
                let what = c.trouble.clone().or_else(|| {
                    (c.compile_error.as_ref()).map(|e| format!("does not compile: {e}"))
                })?;
                Some(format!("{}: {what}", c.folder))
            })
            .collect()
    }
}

/// The most characters a result keeps of one text (a message, a flag):
/// far more than any of the grader's own, or an honest panic's.
pub const MOST_CHARS: usize = 1000;

/// The most flags, notes or warnings a result keeps.
pub const MOST_LINES: usize = 100;

/// `text` cut to [`MOST_CHARS`] characters, with `…` where it was cut.
fn cut(text: &mut String) {
    if let Some((at, _)) = text.char_indices().nth(MOST_CHARS) {
        text.truncate(at);
        text.push('…');
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_result_keeps_bounded_texts_and_lists_whatever_a_student_made() {
        let long = "é".repeat(1 << 20);
        let result = StudentResult {
            flags: (0..100_000)
                .map(|i| format!("added chapters/x/{i}.md"))
                .collect(),
            notes: vec![long.clone()],
            chapters: vec![ChapterRun {
                compile_error: Some(long.clone()),
                trouble: Some(long.clone()),
                ..ChapterRun::default()
            }],
            exercises: vec![Verdict {
                message: Some(long.clone()),
                feedback: Some(format!("test t: {long}")),
                ..Verdict::default()
            }],
            ..StudentResult::default()
        }
        .bounded();
        assert_eq!(result.flags.len(), MOST_LINES + 1);
        assert_eq!(result.flags[MOST_LINES], "and 99900 more");
        assert_eq!(result.flags[0], "added chapters/x/0.md", "short texts kept");
        let run = &result.chapters[0];
        let verdict = &result.exercises[0];
        for text in [
            &result.notes[0],
            run.compile_error.as_ref().unwrap(),
            run.trouble.as_ref().unwrap(),
            verdict.message.as_ref().unwrap(),
            verdict.feedback.as_ref().unwrap(),
        ] {
            assert_eq!(text.chars().count(), MOST_CHARS + 1, "cut, with its …");
            assert!(text.ends_with('…'));
        }
    }
}
