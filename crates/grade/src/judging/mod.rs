//! What a student is judged against, and how: the reference prepared and
//! its base copy built (`judging/reference.rs`), the probe run on drawn inputs
//! (`judging/probe.rs`), the rule that turns values and pictures into verdicts
//! (`rule.rs`), the tests of each exercise and their outcomes, for the
//! feedback (`exercise_tests.rs`, `judging/outcomes.rs`), and the verdicts
//! themselves (`verdict.rs`).

/// The version of what grading caches (the tests of each exercise, each
/// student's result): a new one when what they mean changes, so that a
/// cache of an older workbook is never read as this one's, and when the
/// grader stops an attack it let through, so that a result it cached for
/// unchanged files is judged again (3: probes past 64 MiB refused, texts
/// and flags bounded).
pub const CACHE_FORMAT: &str = "grade-cache-3";

pub mod exercise_tests;
pub mod outcomes;
pub mod probe;
pub mod reference;
pub mod rule;
pub mod verdict;
