//! The gradebook: one row per student, one column per exercise (the points
//! earned), with the chapters' test counts, the flags and the reference's
//! version and commit on every row, for a spreadsheet or an LMS import.

use super::{Class, points};
use crate::judging::verdict::StudentResult;

/// The gradebook's text (RFC 4180: commas, quoted fields, CRLF).
pub fn gradebook(class: &Class) -> String {
    let exercises = &class.reference.tests.exercises;
    let chapters = class.students.iter().flat_map(|s| &s.chapters);
    let mut folders: Vec<&str> = chapters.map(|c| c.folder.as_str()).collect();
    folders.sort();
    folders.dedup();
    let mut header: Vec<String> = [
        "student",
        "status",
        "score",
        "max_score",
        "compiled",
        "seconds",
    ]
    .map(String::from)
    .to_vec();
    for folder in &folders {
        header.push(format!("{folder} passed"));
        header.push(format!("{folder} failed"));
    }
    header.extend(exercises.iter().map(|e| e.id.clone()));
    header.extend(["flags", "troubles", "warnings", "reference"].map(String::from));
    header.extend(["seed", "why"].map(String::from));
    let mut text = line(&header);
    for student in class.students {
        text.push_str(&line(&row(class, student, &folders)));
    }
    text
}

/// A student's row, in the header's columns.
fn row(class: &Class, student: &StudentResult, folders: &[&str]) -> Vec<String> {
    let (score, max) = class.score(student);
    let status = match &student.refused {
        Some(reason) => format!("not graded: {reason}"),
        None => "graded".to_owned(),
    };
    let graded = student.refused.is_none();
    let yes_no = |b: bool| if b { "yes" } else { "no" }.to_owned();
    let mut cells = vec![
        student.name.clone(),
        status,
        points(score),
        points(max),
        if graded {
            yes_no(student.compiled())
        } else {
            String::new()
        },
        format!("{:.1}", student.seconds),
    ];
    for folder in folders {
        let run = student.chapters.iter().find(|c| c.folder == *folder);
        cells.push(run.map_or(String::new(), |r| r.passed.to_string()));
        cells.push(run.map_or(String::new(), |r| (r.failed + r.unfinished).to_string()));
    }
    for exercise in &class.reference.tests.exercises {
        let earned = student.verdict(&exercise.id).map(|v| {
            if v.passed {
                points(class.points.of(&exercise.id))
            } else {
                "0".to_owned()
            }
        });
        cells.push(earned.unwrap_or_default());
    }
    cells.push(student.flags.join("; "));
    cells.push(student.troubles().join("; "));
    cells.push(student.warnings.join("; "));
    cells.push(class.label());
    // The seed the values were judged with, and each exercise without its
    // points: the first drawn input that disagrees and both values.
    cells.push(student.seed.to_string());
    let why = (student.exercises.iter())
        .filter(|v| !v.passed)
        .map(|v| format!("{}: {}", v.id, v.message.as_deref().unwrap_or("fails")));
    cells.push(why.collect::<Vec<_>>().join("; "));
    cells
}

/// One CSV record, its fields quoted where they need it, ended by CRLF.
fn line(cells: &[String]) -> String {
    let quoted: Vec<String> = cells.iter().map(|c| field(c)).collect();
    format!("{}\r\n", quoted.join(","))
}

/// A field, quoted (quotes doubled) if it holds a comma, a quote or a line
/// break; a leading `=`, `+`, `-`, `@`, tab or carriage return is prefixed
/// with `'`, so that a spreadsheet never runs a student's folder name as a
/// formula (some strip a leading tab or carriage return, then read what
/// follows as one: OWASP's "CSV injection").
fn field(cell: &str) -> String {
    // One line a cell, whatever a name or a reason holds.
    let cell = &crate::sandbox::beneath::clean_line(cell);
    let cell = if cell.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{cell}")
    } else {
        cell.to_owned()
    };
    if cell.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", cell.replace('"', "\"\""))
    } else {
        cell
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_when_needed_and_formulas_are_defused() {
        assert_eq!(field("alice"), "alice");
        assert_eq!(field("a,b"), "\"a,b\"");
        assert_eq!(field("say \"hi\""), "\"say \"\"hi\"\"\"");
        assert_eq!(field("=SUM(A1)"), "'=SUM(A1)");
        assert_eq!(line(&["a".into(), "b\nc".into()]), "a,b?c\r\n", "one line");
        assert_eq!(field("\t=1+2"), "'\t=1+2");
        assert_eq!(field("\r=cmd"), "?=cmd");
        assert_eq!(
            field("x\nzz-fake,3,3"),
            "\"x?zz-fake,3,3\"",
            "no forged row"
        );
        assert_eq!(field("a\tb"), "a\tb", "a tab inside is left alone");
    }
}
