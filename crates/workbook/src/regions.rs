//! Exercise regions: the code a student writes, and how a handout takes it out.
//!
//! A chapter's source marks the code a student writes as an *exercise
//! region*: the whole body of a function (or a whole expression in tail
//! position), between two comment lines:
//!
//! ```text
//! pub fn area(width: f32, height: f32) -> f32 {
//!     // EXERCISE(ch00-area): the rectangle's area
//!     crate::workbench::exercise::solution_begins("ch00-area");
//!     width * height
//!     // END EXERCISE
//! }
//! ```
//!
//! * The opening line is `// EXERCISE(<id>): <hint>`, alone on its line. The
//!   id is `chNN-<name>`, where `NN` is the chapter the file belongs to; ids
//!   are unique. The hint is one line, shown to the student.
//! * The closing line is `// END EXERCISE`. Regions do not nest.
//! * Regions live in the chapters' Rust files (`chapters/**/*.rs`).
//! * Everything between them is the solution. Its first line is
//!   `crate::workbench::exercise::solution_begins("<id>");`, which lets
//!   `cargo test` take the solution out at run time (see the toolkit's
//!   `exercise` module); the handout takes that line out with the rest.
//!   Since the markers are comments, the reference workspace compiles and behaves as if they were
//!   not there.
//!
//! In a handout, the solution becomes `todo!("<id>: <hint>")`, which
//! type-checks wherever a whole body stood, and panics with a message that
//! names the exercise. The markers stay, so a handout can be handed out
//! again and `workbook progress` can tell solved exercises from open ones.
//! A file that lost a solution starts with `#![allow(unused)]`: until the
//! student writes it, its parameters and helpers are unused, and the
//! warnings would only be noise.

pub const START: &str = "// EXERCISE(";
/// The closing line of an exercise region (after indentation).
pub const END: &str = "// END EXERCISE";
/// The line put at the top of a file whose solutions were taken out.
pub const ALLOW_UNUSED: &str =
    "#![allow(unused)] // handout: unused until you write the exercises below";

/// One exercise region of a source file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Region {
    /// `chNN-name`, unique in the workspace.
    pub id: String,
    /// What to write, in one line.
    pub hint: String,
    /// Index (from 0) of the opening marker line.
    pub start: usize,
    /// Index of the closing marker line.
    pub end: usize,
    /// The indentation of the markers.
    pub indent: String,
    /// The lines between the markers.
    pub body: Vec<String>,
}

impl Region {
    /// The chapter number of the id (`ch03-lambert` → 3).
    pub fn chapter(&self) -> Option<u32> {
        self.id.strip_prefix("ch")?.get(..2)?.parse().ok()
    }

    /// Is the body still the handout's `todo!`, i.e. not written yet?
    pub fn is_open(&self) -> bool {
        let code: Vec<&str> = self
            .body
            .iter()
            .map(|l| l.trim())
            .filter(|l| !l.is_empty() && !l.starts_with("//"))
            .collect();
        code.len() == 1 && code[0].starts_with("todo!(")
    }

    /// The panic message of the handout's `todo!`: `not yet implemented: <id>: <hint>`.
    pub fn message(&self) -> String {
        format!("not yet implemented: {}", self.todo_text())
    }

    fn todo_text(&self) -> String {
        format!("{}: {}", self.id, self.hint)
    }

    /// The line that replaces the body: `todo!("<id>: <hint>")`, with braces
    /// doubled (todo! reads its argument as a format string).
    pub fn todo_line(&self) -> String {
        let text = self.todo_text().replace('{', "{{").replace('}', "}}");
        format!("{}todo!({text:?})", self.indent)
    }
}

/// The exercise regions of a source file, in order. An error names the line
/// (from 1) of a malformed, nested or unclosed marker.
pub fn regions(source: &str) -> Result<Vec<Region>, String> {
    let mut found = Vec::new();
    let mut open: Option<Region> = None;
    for (index, line) in source.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix(START) {
            if let Some(region) = &open {
                return Err(format!(
                    "line {}: an exercise region starts inside {} (opened on line {})",
                    index + 1,
                    region.id,
                    region.start + 1
                ));
            }
            let indent = &line[..line.len() - trimmed.len()];
            open = Some(opening(index, indent, rest)?);
        } else if trimmed.trim_end() == END {
            let Some(mut region) = open.take() else {
                return Err(format!(
                    "line {}: `{END}` without an opening `{START}...`",
                    index + 1
                ));
            };
            region.end = index;
            found.push(region);
        } else if let Some(region) = &mut open {
            region.body.push(line.to_owned());
        }
    }
    match open {
        Some(region) => Err(format!(
            "line {}: exercise {} is never closed with `{END}`",
            region.start + 1,
            region.id
        )),
        None => Ok(found),
    }
}

/// The region that an opening marker on line `index` starts; `rest` is
/// what follows [`START`]: `<id>): <hint>`.
fn opening(index: usize, indent: &str, rest: &str) -> Result<Region, String> {
    let (id, hint) = rest.split_once("):").ok_or_else(|| {
        format!(
            "line {}: expected `{START}<id>): <hint>`, found {:?}",
            index + 1,
            format!("{START}{rest}")
        )
    })?;
    let id = id.trim();
    if !is_exercise_id(id) {
        return Err(format!(
            "line {}: an exercise id is `chNN-name` (lower case, digits, dashes), found {id:?}",
            index + 1
        ));
    }
    Ok(Region {
        id: id.to_owned(),
        hint: hint.trim().to_owned(),
        start: index,
        end: index,
        indent: indent.to_owned(),
        body: Vec::new(),
    })
}

/// Is `id` of the form `chNN-name` (lower case, digits, dashes)?
fn is_exercise_id(id: &str) -> bool {
    id.is_ascii()
        && id.len() > 5
        && id.starts_with("ch")
        && id[2..4].bytes().all(|b| b.is_ascii_digit())
        && id.as_bytes()[4] == b'-'
        && id
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-')
}

/// The source with the bodies of the selected regions replaced by `todo!`,
/// and [`ALLOW_UNUSED`] on top if any was. Unselected regions are kept as
/// they are. Returns the source unchanged if nothing was selected.
pub fn hand_out(source: &str, select: impl Fn(&Region) -> bool) -> Result<String, String> {
    replace_bodies(source, |r| select(r).then(|| r.todo_line()))
}

/// The source with the bodies of some regions replaced: `body(region)` is
/// the new body (whole lines, indented as in the source) or None to keep it.
/// A file with a replaced body gets [`ALLOW_UNUSED`] on top; one with none
/// is returned unchanged.
pub fn replace_bodies(
    source: &str,
    body: impl Fn(&Region) -> Option<String>,
) -> Result<String, String> {
    let regions = regions(source)?;
    let chosen: Vec<(&Region, String)> =
        regions.iter().filter_map(|r| Some((r, body(r)?))).collect();
    if chosen.is_empty() {
        return Ok(source.to_owned());
    }
    let lines: Vec<&str> = source.lines().collect();
    let mut out = String::with_capacity(source.len());
    if !source.starts_with(ALLOW_UNUSED) {
        out.push_str(ALLOW_UNUSED);
        out.push('\n');
    }
    let mut next = 0;
    for (region, body) in chosen {
        for line in &lines[next..=region.start] {
            out.push_str(line);
            out.push('\n');
        }
        out.push_str(body.trim_end_matches('\n'));
        out.push('\n');
        next = region.end;
    }
    for line in &lines[next..] {
        out.push_str(line);
        out.push('\n');
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "\
//! A module.

pub fn lambert(a: f32, b: f32) -> f32 {
    // EXERCISE(ch03-lambert): a × max(0, b) {not a format}
    let c = b.max(0.0);
    a * c
    // END EXERCISE
}

pub fn other() -> u32 {
    // EXERCISE(ch03-other): one
    1
    // END EXERCISE
}
";

    #[test]
    fn finds_regions_with_id_hint_and_body() {
        let found = regions(SOURCE).unwrap();
        assert_eq!(found.len(), 2);
        assert_eq!(found[0].id, "ch03-lambert");
        assert_eq!(found[0].hint, "a × max(0, b) {not a format}");
        assert_eq!((found[0].start, found[0].end), (3, 6));
        assert_eq!(found[0].body, ["    let c = b.max(0.0);", "    a * c"]);
        assert_eq!(found[0].chapter(), Some(3));
        assert!(!found[0].is_open());
    }

    #[test]
    fn handing_out_replaces_only_the_selected_bodies() {
        let out = hand_out(SOURCE, |r| r.id == "ch03-lambert").unwrap();
        assert!(out.starts_with(ALLOW_UNUSED));
        assert!(out.contains(
            "    // EXERCISE(ch03-lambert): a × max(0, b) {not a format}\n    \
             todo!(\"ch03-lambert: a × max(0, b) {{not a format}}\")\n    // END EXERCISE\n}"
        ));
        assert!(!out.contains("a * c"));
        assert!(out.contains("    1\n"), "the other region is kept");
        let again = regions(&out).unwrap();
        assert!(again[0].is_open() && !again[1].is_open());
        // Handing out a handout changes nothing.
        assert_eq!(hand_out(&out, |r| r.id == "ch03-lambert").unwrap(), out);
        // Nothing selected, nothing changed.
        assert_eq!(hand_out(SOURCE, |_| false).unwrap(), SOURCE);
    }

    #[test]
    fn a_body_can_be_replaced_by_any_lines() {
        let out = replace_bodies(SOURCE, |r| (r.id == "ch03-other").then(|| "    2\n".into()));
        let out = out.unwrap();
        assert!(out.contains("    // EXERCISE(ch03-other): one\n    2\n    // END EXERCISE\n"));
        assert!(out.contains("    a * c\n"), "the other region is kept");
        assert_eq!(regions(&out).unwrap().len(), 2);
    }

    #[test]
    fn malformed_markers_are_errors_with_a_line() {
        let unclosed = "fn f() {\n    // EXERCISE(ch01-f): x\n    1\n}\n";
        assert!(regions(unclosed).unwrap_err().starts_with("line 2:"));
        let stray = "fn f() {\n    1\n    // END EXERCISE\n}\n";
        assert!(regions(stray).unwrap_err().starts_with("line 3:"));
        let nested = "// EXERCISE(ch01-a): x\n// EXERCISE(ch01-b): y\n";
        assert!(regions(nested).unwrap_err().starts_with("line 2:"));
        let bad_id = "// EXERCISE(lambert): x\n// END EXERCISE\n";
        assert!(regions(bad_id).unwrap_err().contains("chNN-name"));
        let no_hint = "// EXERCISE(ch01-a)\n// END EXERCISE\n";
        assert!(regions(no_hint).unwrap_err().starts_with("line 1:"));
    }
}
