//! Each test's outcome, by name, from what libtest prints.
//!
//! `progress::parse` counts the passes and names the failures; grading
//! needs to know that each test of an exercise *passed*, which a test that
//! never ran (its binary crashed, or was killed at the time limit) did not.
//! So it reads libtest's `test NAME ... ok` lines too. A test is named by
//! its test target and its name, `tests/chapter03/main.rs::snapshot_default`,
//! since two targets of a chapter may hold tests of the same name.

use std::collections::BTreeMap;

/// The outcome of each test that reported one: true if it passed.
pub type Outcomes = BTreeMap<String, bool>;

/// Reads the outcomes from the output of `cargo test` (which names each
/// target on a `Running` or `Doc-tests` line before its tests), or of one
/// test binary run directly, whose target is `target`.
pub fn outcomes(text: &str, target: &str) -> Outcomes {
    let mut found = Outcomes::new();
    let mut current = target.to_owned();
    for line in text.lines() {
        let trimmed = line.trim();
        if let Some(named) = running_target(trimmed) {
            current = named;
        } else if let Some(rest) = line.strip_prefix("test ") {
            let verdict = [(" ... ok", true), (" ... FAILED", false)]
                .into_iter()
                .find_map(|(suffix, ok)| Some((rest.strip_suffix(suffix)?, ok)));
            if let Some((name, ok)) = verdict {
                found.insert(key(&current, name), ok);
            }
        }
    }
    found
}

/// The key of test `name` of `target`.
pub fn key(target: &str, name: &str) -> String {
    format!("{target}::{name}")
}

/// The test's name in a key: what libtest and `progress::parse` call it.
pub fn name_of(key: &str) -> &str {
    key.split_once("::").map_or(key, |(_, name)| name)
}

/// The target named by cargo's `Running tests/chapter03/main.rs (path)`,
/// `Running unittests src/lib.rs (path)` or `Doc-tests ch03_lambert`.
fn running_target(line: &str) -> Option<String> {
    if line.starts_with("Doc-tests ") {
        return Some("doc-tests".to_owned());
    }
    let rest = line.strip_prefix("Running ")?;
    let (source, _) = rest.split_once(" (")?;
    Some(
        source
            .strip_prefix("unittests ")
            .unwrap_or(source)
            .to_owned(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const OUTPUT: &str = "\
     Running unittests src/lib.rs (target/debug/deps/ch03_lambert-1)

running 1 test
test tests::inner ... ok

test result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.00s

     Running tests/chapter03/main.rs (target/debug/deps/chapter03-2)

running 3 tests
test spot_is_smooth ... ok
test cosine_law ... FAILED
test slow_one has been running for over 60 seconds
test ignored_one ... ignored

   Doc-tests ch03_lambert
test chapters/03-lambert/src/../README.md - (line 37) ... ok
";

    #[test]
    fn each_test_is_keyed_by_its_target_and_ignored_ones_are_left_out() {
        let found = outcomes(OUTPUT, "unknown");
        let expected = [
            (
                "doc-tests::chapters/03-lambert/src/../README.md - (line 37)",
                true,
            ),
            ("src/lib.rs::tests::inner", true),
            ("tests/chapter03/main.rs::cosine_law", false),
            ("tests/chapter03/main.rs::spot_is_smooth", true),
        ];
        let expected: Outcomes = expected.map(|(k, v)| (k.to_owned(), v)).into();
        assert_eq!(found, expected);
        assert_eq!(name_of("tests/chapter03/main.rs::cosine_law"), "cosine_law");
    }

    #[test]
    fn a_binary_run_alone_is_keyed_by_the_target_given() {
        let found = outcomes("test a ... ok\ntest b ... FAILED\n", "tests/x.rs");
        assert_eq!(found.get("tests/x.rs::a"), Some(&true));
        assert_eq!(found.get("tests/x.rs::b"), Some(&false));
    }
}
