//! The order a chapter's text asks for its exercises in, and which of a
//! chapter's open exercises is the next: so that the table's first failure
//! and the advice's "next" are about the same exercise.

use std::path::{Path, PathBuf};

use super::TestOutput;
use crate::regions::Region;
use crate::workbench::chapters::ChapterEntry;

/// The exercises of `chapter` in the order its README asks for them: as
/// its `## Exercises` section lists them (`` **`ch04-any-hit`: …** ``),
/// then any other in the order the text derives them (its
/// `<!-- derives: ID -->` marks).
pub fn lesson_order(root: &Path, chapter: &ChapterEntry) -> Vec<String> {
    let readme = std::fs::read_to_string(root.join(chapter.path()).join("README.md"));
    order_in(
        &readme.unwrap_or_default(),
        &format!("ch{:02}-", chapter.number()),
    )
}

/// [`lesson_order`] of the README `text`, whose exercise ids start with
/// `prefix` (`ch04-`).
fn order_in(text: &str, prefix: &str) -> Vec<String> {
    let mut ids: Vec<String> = Vec::new();
    let mut push = |id: &str| {
        if !ids.iter().any(|known| known == id) {
            ids.push(id.to_owned());
        }
    };
    let exercises = text
        .split("\n## ")
        .find(|section| section.starts_with("Exercises"))
        .unwrap_or("");
    for quoted in exercises.split('`').skip(1).step_by(2) {
        let is_id = quoted.starts_with(prefix)
            && quoted.len() > prefix.len()
            && quoted
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-');
        if is_id {
            push(quoted);
        }
    }
    for line in text.lines() {
        let id = line
            .trim()
            .strip_prefix("<!-- derives: ")
            .and_then(|l| l.strip_suffix(" -->"));
        if let Some(id) = id {
            push(id);
        }
    }
    ids
}

/// Does the panic `message` come from exercise `id`'s `todo!("id: …")`?
pub fn names(message: &str, id: &str) -> bool {
    message.contains(&format!("{id}:"))
}

/// The next exercise to write of `open` (a chapter's exercises not yet
/// written), given the chapter's `output`: the first in the text's
/// `order` whose `todo!` a failing test ran into, or else the first in
/// the text's order. The table's first failure is then a test of it.
pub fn next_exercise<'a>(
    open: &[&'a (PathBuf, usize, Region)],
    order: &[String],
    output: Option<&TestOutput>,
) -> Option<&'a (PathBuf, usize, Region)> {
    let rank = |r: &Region| {
        order
            .iter()
            .position(|id| *id == r.id)
            .unwrap_or(usize::MAX)
    };
    let mut sorted = open.to_vec();
    sorted.sort_by_key(|(_, _, r)| rank(r));
    let panics = output.map_or(&[][..], |o| &o.panics[..]);
    let met = |(_, _, r): &&&(PathBuf, usize, Region)| {
        panics.iter().any(|(_, message)| names(message, &r.id))
    };
    sorted.iter().find(met).or(sorted.first()).copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_exercises_list_orders_them_then_the_derivations() {
        let text = "# Chapter 4\n<!-- derives: ch04-shadow-ray -->\n<!-- derives: ch04-any-hit -->\n\
                    <!-- derives: ch04-offset -->\n## Exercises\n\n1. **`ch04-any-hit`: is anything \
                    in the way?** (`any_hit`)\n2. **`ch04-shadow-ray`: the ray** (`ch04-x y`)\n\
                    ## After\n`ch04-late`\n";
        assert_eq!(
            order_in(text, "ch04-"),
            ["ch04-any-hit", "ch04-shadow-ray", "ch04-offset"]
        );
    }

    #[test]
    fn the_next_exercise_is_the_first_in_the_texts_order_that_a_failing_test_met() {
        let source = "fn f() {\n    // EXERCISE(ch03-spot): s\n    todo!()\n    // END EXERCISE\n}\n\
                      fn g() {\n    // EXERCISE(ch03-lambert): l\n    todo!()\n    // END EXERCISE\n}\n";
        let exercises: Vec<(PathBuf, usize, Region)> = crate::regions::regions(source)
            .unwrap()
            .into_iter()
            .map(|r| (PathBuf::from("lib.rs"), r.start + 1, r))
            .collect();
        let open: Vec<_> = exercises.iter().collect();
        let order = ["ch03-lambert".to_owned(), "ch03-spot".to_owned()];
        let id = |e: Option<&(PathBuf, usize, Region)>| e.map(|(_, _, r)| r.id.clone());
        // No test ran into a todo!: the text's first.
        assert_eq!(
            id(next_exercise(&open, &order, None)).unwrap(),
            "ch03-lambert"
        );
        // Only the spot's todo! was met: it is the one the failures are about.
        let output = TestOutput {
            panics: vec![(
                "light_loop".into(),
                "not yet implemented: ch03-spot: the cone".into(),
            )],
            ..TestOutput::default()
        };
        assert_eq!(
            id(next_exercise(&open, &order, Some(&output))).unwrap(),
            "ch03-spot"
        );
        assert!(names("not yet implemented: ch03-spot: x", "ch03-spot"));
        assert!(!names("not yet implemented: ch03-spot-x: x", "ch03-spot"));
    }
}
