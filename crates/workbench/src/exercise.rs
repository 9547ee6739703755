//! How the maintainers' check takes an exercise out without building the
//! workbook a second time.
//!
//! In the reference, every exercise's solution starts with
//! `crate::workbench::exercise::solution_begins("<id>");`. A handout takes that
//! line out with the rest of the solution, so a student never sees it.
//!
//! In a debug build (the one `cargo test` makes), the call panics exactly as
//! the handout's `todo!("<id>: …")` would, when the environment variable
//! [`TAKE_OUT`] lists the exercise. So the reference's own test binaries,
//! run with `RAYBOOK_TAKE_OUT=ch03-lambert,ch03-spot`, show what the tests
//! of a handout without those two solutions would show, and nothing has to
//! be compiled again. (Mutation testers such as mutagen switch their mutants
//! on at run time in the same way.) In a release build the call does
//! nothing, so renders and benchmarks do not pay for it.

/// The environment variable that lists the exercises to take out, by id,
/// separated by commas.
pub const TAKE_OUT: &str = "RAYBOOK_TAKE_OUT";

/// Marks the start of exercise `id`'s solution: in a debug build, panics
/// with the handout's `todo!` message when [`TAKE_OUT`] lists `id`, at the
/// caller's line, where the handout's `todo!` would stand.
#[inline]
#[track_caller]
pub fn solution_begins(id: &str) {
    if cfg!(debug_assertions) && taken_out().iter().any(|t| t == id) {
        panic!("not yet implemented: {id}: (taken out by {TAKE_OUT})");
    }
}

/// The ids that [`TAKE_OUT`] lists, read once.
fn taken_out() -> &'static [String] {
    static IDS: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    IDS.get_or_init(|| {
        std::env::var(TAKE_OUT)
            .unwrap_or_default()
            .split(',')
            .map(|id| id.trim().to_owned())
            .filter(|id| !id.is_empty())
            .collect()
    })
}

/// The words by which a test's message blames an earlier exercise that the
/// test builds on (see [`builds_on`]); `handout --check-mistakes` reads them.
pub const BUILDS_ON: &str = "this test builds on exercise ";

/// A test of a later exercise checks first the earlier exercise `id` that it
/// builds on: when `right` is false, it fails here, naming `id` and saying
/// what is wrong with it (`what`), instead of blaming its own exercise for
/// the wrong number that `id` would hand on.
#[track_caller]
pub fn builds_on(id: &str, right: bool, what: impl std::fmt::Display) {
    if !right {
        panic!(
            "{BUILDS_ON}{id}, and {id} is wrong: {what}. Fix {id} first; this test cannot judge its own exercise before."
        );
    }
}

/// The exercises that the messages in `output` blame through [`builds_on`].
pub fn blamed_by_builds_on(output: &str) -> Vec<&str> {
    output
        .match_indices(BUILDS_ON)
        .filter_map(|(at, _)| {
            let rest = &output[at + BUILDS_ON.len()..];
            rest.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
                .next()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builds_on_names_the_earlier_exercise_and_check_reads_it_back() {
        builds_on("ch03-spot", true, "never shown");
        let message =
            std::panic::catch_unwind(|| builds_on("ch03-spot", false, "cos of 10 radians"))
                .unwrap_err()
                .downcast::<String>()
                .unwrap();
        assert!(
            message.contains("ch03-spot, and ch03-spot is wrong: cos of 10 radians"),
            "{message}"
        );
        let output = format!("thread 'x' panicked:\n{message}\nand\n{message}");
        assert_eq!(blamed_by_builds_on(&output), ["ch03-spot", "ch03-spot"]);
        assert!(blamed_by_builds_on("nothing blamed").is_empty());
    }
}
