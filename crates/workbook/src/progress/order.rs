//! The chapter's tests in the order the chapter writes them, so that of
//! several failures the one shown first is the most basic: libtest reports
//! failures by name, and `an_air_bubble_…` would come before
//! `entering_glass_…`, whose message names the mistake.

use std::path::Path;

use super::TestOutput;

/// The test functions under a chapter's `tests/` folder in reading order:
/// test targets by name, and in each the functions as they come, a module
/// (`mod name;`) read where it is declared.
pub fn test_order(tests_dir: &Path) -> Vec<String> {
    let mut targets: Vec<_> = std::fs::read_dir(tests_dir)
        .map(|entries| entries.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    targets.sort();
    let mut names = Vec::new();
    for target in targets {
        if target.is_dir() {
            read_functions(&target.join("main.rs"), &mut names);
        } else if target.extension().is_some_and(|e| e == "rs") {
            read_functions(&target, &mut names);
        }
    }
    names
}

/// Appends the names of the functions of `file` (and of the modules it
/// declares, from files beside it) to `names`.
fn read_functions(file: &Path, names: &mut Vec<String>) {
    let Ok(text) = std::fs::read_to_string(file) else {
        return;
    };
    // `mod name;` in main.rs is the file name.rs beside it; in other.rs,
    // other/name.rs.
    let beside = file.parent().unwrap_or(Path::new("."));
    let folder = match file.file_stem().and_then(|s| s.to_str()) {
        Some("main" | "mod" | "lib") | None => beside.to_owned(),
        Some(stem) => beside.join(stem),
    };
    for line in text.lines().map(str::trim).map(without_visibility) {
        if let Some(name) = line
            .strip_prefix("fn ")
            .and_then(|rest| rest.split('(').next())
        {
            names.push(name.to_owned());
        } else if let Some(module) = line.strip_prefix("mod ").and_then(|m| m.strip_suffix(';')) {
            read_functions(&folder.join(format!("{module}.rs")), names);
        }
    }
}

/// `line` without a leading `pub`, `pub(crate)` or `pub(super)`: a test
/// that a snapshot's list of precise tests calls from another module is
/// `pub(crate) fn`, and keeps its place in the order.
fn without_visibility(line: &str) -> &str {
    ["pub(crate) ", "pub(super) ", "pub "]
        .iter()
        .find_map(|p| line.strip_prefix(p))
        .unwrap_or(line)
}

/// Puts the failed tests and their panics of `output` in the chapter's
/// order (`order`, from [`test_order`]); tests it does not know keep their
/// place after those it does.
pub fn in_chapter_order(output: &mut TestOutput, order: &[String]) {
    let rank = |test: &str| {
        let name = test.rsplit("::").next().unwrap_or(test);
        order.iter().position(|n| n == name).unwrap_or(usize::MAX)
    };
    output.failed_tests.sort_by_key(|t| rank(t));
    output.panics.sort_by_key(|(t, _)| rank(t));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failures_come_in_the_order_the_chapter_writes_its_tests() {
        let dir = std::env::temp_dir().join(format!("order-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("chapter06")).unwrap();
        std::fs::write(
            dir.join("chapter06/main.rs"),
            "mod split;\n#[test]\nfn entering_glass() {}\n#[test]\nfn an_air_bubble() {}\n",
        )
        .unwrap();
        std::fs::write(
            dir.join("chapter06/split.rs"),
            "pub(crate) fn weights_add_up() {}\nmod short;\n",
        )
        .unwrap();
        // A module of a module: split/short.rs.
        std::fs::create_dir_all(dir.join("chapter06/split")).unwrap();
        std::fs::write(dir.join("chapter06/split/short.rs"), "pub fn folds() {}\n").unwrap();
        let order = test_order(&dir);
        assert_eq!(
            order,
            ["weights_add_up", "folds", "entering_glass", "an_air_bubble"]
        );
        let mut output = TestOutput {
            failed_tests: vec![
                "an_air_bubble".into(),
                "entering_glass".into(),
                "other".into(),
            ],
            panics: vec![
                ("an_air_bubble".into(), "no total reflection".into()),
                ("entering_glass".into(), "η inverted".into()),
            ],
            ..TestOutput::default()
        };
        in_chapter_order(&mut output, &order);
        assert_eq!(
            output.failed_tests,
            ["entering_glass", "an_air_bubble", "other"]
        );
        assert_eq!(output.panics[0].1, "η inverted");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
