//! What grading found for one student: kept in the rerun cache as JSON,
//! and read by every output (the points are applied when they are written,
//! so that editing the points file needs no new run).

use serde::{Deserialize, Serialize};

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

/// An exercise's verdict.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Verdict {
    /// `ch03-lambert`.
    pub id: String,
    /// Its chapter's folder.
    pub chapter: String,
    /// Does every test that grades it pass?
    pub passed: bool,
    /// If not, the first failing test's message, as progress shows it.
    pub message: Option<String>,
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
