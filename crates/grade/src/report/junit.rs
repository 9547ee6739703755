//! The class as JUnit XML, which CI servers and many LMSs read: a test
//! suite per student, a test case per exercise (failed with the first
//! failing test's message), the reference named in each suite's
//! properties. A student who was not graded has one case in error.

use super::Class;
use crate::judging::verdict::StudentResult;

/// The JUnit XML text of the class.
pub fn junit(class: &Class) -> String {
    let suites: Vec<String> = class.students.iter().map(|s| suite(class, s)).collect();
    let failures: usize = class.students.iter().map(|s| counts(class, s).1).sum();
    let tests: usize = class.students.iter().map(|s| counts(class, s).0).sum();
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <testsuites name=\"raybook grade\" tests=\"{tests}\" failures=\"{failures}\">\n{}</testsuites>\n",
        suites.concat()
    )
}

/// Test cases and failures (or errors) of a student's suite.
fn counts(class: &Class, student: &StudentResult) -> (usize, usize) {
    if student.refused.is_some() {
        return (1, 1);
    }
    let exercises = &class.reference.tests.exercises;
    let failed = (exercises.iter())
        .filter(|e| !student.verdict(&e.id).is_some_and(|v| v.passed))
        .count();
    (exercises.len(), failed)
}

/// A student's test suite.
fn suite(class: &Class, student: &StudentResult) -> String {
    let (tests, failed) = counts(class, student);
    let (failures, errors) = if student.refused.is_some() {
        (0, failed)
    } else {
        (failed, 0)
    };
    let mut xml = format!(
        "  <testsuite name=\"{}\" tests=\"{tests}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{:.1}\">\n",
        escape(&student.name),
        student.seconds
    );
    xml.push_str(&format!(
        "    <properties>\n      <property name=\"reference\" value=\"{}\"/>\n",
        escape(&class.label())
    ));
    let named = (student.flags.iter().map(|f| ("flag", f)))
        .chain(student.warnings.iter().map(|w| ("warning", w)));
    for (name, value) in named {
        xml.push_str(&format!(
            "      <property name=\"{name}\" value=\"{}\"/>\n",
            escape(value)
        ));
    }
    xml.push_str("    </properties>\n");
    if let Some(reason) = &student.refused {
        xml.push_str(&format!(
            "    <testcase classname=\"{0}\" name=\"handout\">\n      <error message=\"{1}\">{1}</error>\n    </testcase>\n",
            escape(&student.name),
            escape(reason)
        ));
    } else {
        for exercise in &class.reference.tests.exercises {
            xml.push_str(&case(student, &exercise.id, &exercise.chapter));
        }
    }
    xml + "  </testsuite>\n"
}

/// An exercise's test case.
fn case(student: &StudentResult, id: &str, chapter: &str) -> String {
    let classname = escape(&format!("{}.{chapter}", student.name));
    let verdict = student.verdict(id);
    let open = format!("    <testcase classname=\"{classname}\" name=\"{id}\"");
    match verdict {
        Some(v) if v.passed => format!(
            "{open}>\n      <system-out>{}</system-out>\n    </testcase>\n",
            escape(&v.explained())
        ),
        _ => {
            let message = verdict.and_then(|v| v.message.as_deref());
            let message = escape(message.unwrap_or("not graded"));
            let body = escape(&verdict.map_or("not graded".to_owned(), |v| v.explained()));
            format!(
                "{open}>\n      <failure message=\"{message}\">{body}</failure>\n    </testcase>\n"
            )
        }
    }
}

/// Text made safe for XML content and attributes; characters XML 1.0
/// cannot hold (control characters a panic message may print) are dropped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\t' | '\r' => out.push(' '),
            c if (c as u32) < 0x20 || c == '\u{fffe}' || c == '\u{ffff}' => {}
            // A bidirectional control reorders what the reader sees.
            c if crate::sandbox::beneath::is_unsafe(c) => out.push('?'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_and_control_characters_are_escaped() {
        assert_eq!(
            escape("a<b> & \"c\"\u{1b}[0m\nd"),
            "a&lt;b&gt; &amp; &quot;c&quot;[0m&#10;d"
        );
    }
}
