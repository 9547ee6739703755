//! The outputs of a grading run, each written atomically (to a temporary
//! file beside it, then renamed into place), each naming the reference's
//! version and commit: the CSV gradebook, a Gradescope `results.json` per
//! student, JUnit XML for the class, and the HTML class report.

mod csv;
mod gradescope;
mod html;
mod junit;
pub mod points;

use std::path::{Path, PathBuf};

use crate::judging::reference::Reference;
use crate::judging::verdict::StudentResult;
use crate::report::points::Points;
use crate::sandbox::beneath::clean_line;

pub use gradescope::results_json;

/// What every output needs: the reference, the points, the results.
pub struct Class<'a> {
    pub reference: &'a Reference,
    pub points: &'a Points,
    pub students: &'a [StudentResult],
}

impl Class<'_> {
    /// The reference's version and commit, as every output names it.
    pub fn label(&self) -> String {
        self.reference.record.label()
    }

    /// A student's score and the most they could score.
    pub fn score(&self, student: &StudentResult) -> (f64, f64) {
        let exercises = &self.reference.tests.exercises;
        let max: f64 = exercises.iter().map(|e| self.points.of(&e.id)).sum();
        let score: f64 = (exercises.iter())
            .filter(|e| student.verdict(&e.id).is_some_and(|v| v.passed))
            .map(|e| self.points.of(&e.id))
            .sum();
        // A sum of no f64 is -0.0: shown as 0.
        (score + 0.0, max + 0.0)
    }
}

/// Writes every output into `out`; the paths written.
pub fn write_all(out: &Path, class: &Class) -> Result<Vec<PathBuf>, String> {
    let mut written = vec![
        write(&out.join("grades.csv"), csv::gradebook(class))?,
        write(&out.join("junit.xml"), junit::junit(class))?,
    ];
    for student in class.students {
        let path = out
            .join("gradescope")
            .join(format!("{}.json", student.slug));
        write(&path, results_json(class, student))?;
    }
    written.push(out.join("gradescope/"));
    written.push(html::write_report(&out.join("report"), class)?);
    Ok(written)
}

/// Writes `text` to `path` atomically; the path.
pub fn write(path: &Path, text: String) -> Result<PathBuf, String> {
    ch00_toolkit::image::write_atomically(path, text.as_bytes())
        .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(path.to_owned())
}

/// The class in a few lines: a student a line.
pub fn print_table(class: &Class) {
    println!(
        "{:<24} {:>9}  {:<8}  {:<5}  {:>6}",
        "student", "score", "compiled", "flags", "time"
    );
    for student in class.students {
        let (score, max) = class.score(student);
        let score = format!("{}/{}", points(score), points(max));
        let compiled = match (&student.refused, student.compiled()) {
            (Some(_), _) => "-",
            (None, true) => "yes",
            (None, false) => "no",
        };
        let time = format!("{:.0} s", student.seconds);
        let flags = student.flags.len();
        println!(
            "{:<24} {score:>9}  {compiled:<8}  {flags:<5}  {time:>6}",
            clean_line(&student.name)
        );
    }
}

/// The reference, and where the outputs are.
pub fn print_written(class: &Class, written: &[PathBuf]) {
    println!("reference: raybook {}", class.label());
    let unsandboxed = crate::sandbox::bwrap::UNSANDBOXED;
    if (class.students.iter()).any(|s| s.warnings.iter().any(|w| w == unsandboxed)) {
        println!("WARNING: {}", crate::sandbox::bwrap::UNSANDBOXED);
    }
    for path in written {
        println!("wrote {}", path.display());
    }
}

/// Copies the pictures `student`'s result lists (paths relative to a
/// report folder, in the student's own folder there) from the report
/// folder `from` to the report folder `to`, whose folder of the student's
/// holds only them afterwards. A picture that is not a regular file of
/// the student's folder in `from` is refused.
pub fn copy_pictures(student: &StudentResult, from: &Path, to: &Path) -> Result<(), String> {
    let _ = std::fs::remove_dir_all(to.join(&student.slug));
    let pictures = student.chapters.iter().flat_map(|c| &c.pictures);
    for diff in pictures.filter_map(|p| p.diff.as_ref()) {
        let relative = Path::new(diff);
        let inside = relative.starts_with(&student.slug)
            && (relative.components()).all(|c| matches!(c, std::path::Component::Normal(_)));
        let source = from.join(relative);
        let regular = std::fs::symlink_metadata(&source).is_ok_and(|m| m.is_file());
        if !inside || !regular {
            return Err(format!(
                "the picture {diff} of {} is not a file of their folder in {}",
                student.name,
                from.display()
            ));
        }
        let bytes =
            std::fs::read(&source).map_err(|e| format!("cannot read {}: {e}", source.display()))?;
        ch00_toolkit::image::write_atomically(&to.join(relative), &bytes)
            .map_err(|e| format!("cannot write {}: {e}", to.join(relative).display()))?;
    }
    Ok(())
}

/// Points as a teacher writes them: `2`, `1.5`.
pub fn points(value: f64) -> String {
    if value.fract() == 0.0 {
        format!("{value:.0}")
    } else {
        format!("{value}")
    }
}
