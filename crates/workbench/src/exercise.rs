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
