//! A student's grading in the `results.json` schema of Gradescope's
//! autograders: the total score, the time taken, a text for the whole
//! submission, and one test per exercise with its name, score, max_score,
//! status and output.

use serde_json::{Value, json};

use super::Class;
use crate::judging::verdict::StudentResult;
use crate::sandbox::beneath::clean_line;

/// The `results.json` text of `student`.
pub fn results_json(class: &Class, student: &StudentResult) -> String {
    let (score, _) = class.score(student);
    let mut tests = Vec::new();
    if student.refused.is_none() {
        for (index, exercise) in class.reference.tests.exercises.iter().enumerate() {
            let verdict = student.verdict(&exercise.id);
            let passed = verdict.is_some_and(|v| v.passed);
            let max = class.points.of(&exercise.id);
            let output = match verdict.filter(|v| v.message.is_some()) {
                Some(v) => v.for_student(),
                None if passed => match exercise.tests.len() {
                    1 => "passes the test that grades it".to_owned(),
                    n => format!("passes the {n} tests that grade it"),
                },
                None => "not graded".to_owned(),
            };
            tests.push(json!({
                "name": format!("{}: {}", exercise.id, exercise.hint),
                "number": format!("{}", index + 1),
                "score": if passed { max } else { 0.0 },
                "max_score": max,
                "status": if passed { "passed" } else { "failed" },
                "output": output,
                "visibility": "visible",
            }));
        }
    }
    if let Some(reason) = &student.refused {
        // Shown to the student, so that they know to hand in again.
        let (_, max) = class.score(student);
        tests.push(json!({
            "name": "grading",
            "score": 0.0,
            "max_score": max,
            "status": "failed",
            "output": format!("Not graded: {}", clean_line(reason)),
            "visibility": "visible",
        }));
    }
    let results = json!({
        "score": score,
        "execution_time": student.seconds.round() as u64,
        "output": summary(class, student),
        "stdout_visibility": "hidden",
        "tests": Value::Array(tests),
    });
    serde_json::to_string_pretty(&results).expect("JSON values serialize") + "\n"
}

/// The text for the whole submission: the reference, and whatever the
/// student should know (not graded, flags, troubles, warnings).
fn summary(class: &Class, student: &StudentResult) -> String {
    let mut lines = vec![format!("Graded against raybook {}.", class.label())];
    if student.refused.is_none() {
        lines.push(
            "Each exercise is judged by what your code computes on inputs drawn at grading \
             time, against the reference's; your chapter's tests' messages are feedback."
                .to_owned(),
        );
    }
    if let Some(reason) = &student.refused {
        lines.push(format!("Not graded: {}", clean_line(reason)));
    }
    for trouble in student.troubles() {
        lines.push(format!("Chapter {trouble}"));
    }
    if !student.flags.is_empty() {
        lines.push(
            "Flagged for your teacher (files grading takes from the reference, which it \
             used instead; what grading refused to read; what your runs left):"
                .to_owned(),
        );
        lines.extend(student.flags.iter().map(|f| format!("  {}", clean_line(f))));
    }
    lines.extend(student.warnings.iter().map(|w| clean_line(w)));
    lines.join("\n")
}
