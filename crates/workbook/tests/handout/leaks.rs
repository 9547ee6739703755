//! What a handout gives away: no file of it holds half an exercise's
//! solution, hints stop short of the code, and each answer stands in its
//! answers file only, not in the chapter's text or the exercise's contract.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use workbook::handout::workspace_regions;
use workbook::workbench::chapters;

use super::{exercise_chapters, root, workbook};

/// A line as the leak test compares it: trimmed, runs of whitespace made
/// one space; `None` for a comment, a short line (under 16 characters) or
/// an exercise's marker call, which are no part of a solution.
fn solution_line(line: &str) -> Option<String> {
    let line = line.split_whitespace().collect::<Vec<_>>().join(" ");
    let code =
        !line.starts_with("//") && !line.starts_with('#') && !line.contains("solution_begins(");
    (code && line.chars().count() >= 16).then_some(line)
}

/// The files of a handout that the leak test reads: every `.rs`, `.toml`,
/// `.md`, `.txt` and `.json` file outside `target/`, relative to `dir`.
fn readable_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() && path.file_name().is_some_and(|n| n != "target") {
                folders.push(path);
            } else if path
                .extension()
                .is_some_and(|e| ["rs", "toml", "md", "txt", "json"].iter().any(|x| e == *x))
            {
                files.push(path);
            }
        }
    }
    files
}

#[test]
fn no_file_of_a_fresh_handout_holds_half_an_exercises_solution() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("handout-leaks");
    let _ = std::fs::remove_dir_all(&dir);
    workbook::handout::write_tree(&root(), &dir, |_| true).unwrap();
    assert!(
        !dir.join("chapters/06-refraction/mistakes.toml").exists(),
        "the chapters' mistakes.toml are the teacher's"
    );
    let files: Vec<(PathBuf, BTreeSet<String>)> = readable_files(&dir)
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            (path, text.lines().filter_map(solution_line).collect())
        })
        .collect();
    let mut leaks = Vec::new();
    for (_, _, region) in workspace_regions(&root()).unwrap() {
        let solution: BTreeSet<String> = region
            .body
            .iter()
            .filter_map(|l| solution_line(l))
            .collect();
        for (path, lines) in &files {
            let found: Vec<&String> = solution.intersection(lines).collect();
            if !solution.is_empty() && 2 * found.len() > solution.len() {
                let file = path.strip_prefix(&dir).unwrap().display();
                leaks.push(format!(
                    "{}: {file} holds {} of its {} solution lines, such as {:?}",
                    region.id,
                    found.len(),
                    solution.len(),
                    found[0]
                ));
            }
        }
    }
    assert!(
        leaks.is_empty(),
        "a handout gives solutions away:\n{}",
        leaks.join("\n")
    );
}

#[test]
fn every_exercise_has_a_hint_then_its_derivation_and_never_its_code() {
    for (_, _, region) in workspace_regions(&root()).unwrap() {
        let id = region.id.as_str();
        let (ok, nudge) = workbook(&["hint", id]);
        assert!(ok && nudge.contains(&region.hint), "{id}: {nudge}");
        // Each level adds what the todo!'s text does not say: the nudge,
        // the contract of the function that holds the exercise.
        let todo_text = format!("{id}: {}", region.hint);
        let added: Vec<&str> = (nudge.lines())
            .filter(|l| l.trim_start().starts_with("///") && !todo_text.contains(l.trim()))
            .collect();
        assert!(
            nudge.contains("fn ") && added.len() >= 2,
            "{id}: the nudge adds no contract to the todo!'s text:\n{nudge}"
        );
        assert!(
            nudge.contains(&format!("workbook hint {id} --level 2")),
            "{nudge}"
        );
        let (ok, derivation) = workbook(&["hint", id, "--level", "2"]);
        assert!(ok, "{derivation}");
        assert!(
            derivation.starts_with(nudge.split("\nmore help").next().unwrap())
                && derivation.len() > nudge.len(),
            "{id}: level 2 does not add to level 1:\n{derivation}"
        );
        assert!(
            derivation.contains("\n#"),
            "{id}: its chapter's README marks no section `<!-- derives: {id} -->`:\n{derivation}"
        );
        for line in region.body.iter().filter_map(|l| solution_line(l)) {
            assert!(
                !derivation.contains(&line),
                "{id}: the hint gives away {line:?}"
            );
        }
    }
    let (ok, unknown) = workbook(&["hint", "ch02-spher"]);
    assert!(
        !ok && unknown.contains("the exercises are ch01-at"),
        "{unknown}"
    );
}

/// Every text a student reads beside the code: each chapter's README (a
/// later chapter may restate an earlier one's answer as it builds on it)
/// and the book's appendices, by file name.
fn texts_a_student_reads() -> Vec<(PathBuf, String)> {
    let mut files: Vec<PathBuf> = chapters::all()
        .iter()
        .map(|c| root().join(c.path()).join("README.md"))
        .collect();
    let appendix = root().join("book/appendix");
    for entry in std::fs::read_dir(&appendix).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "md") {
            files.push(path);
        }
    }
    files
        .into_iter()
        .map(|f| {
            let text = std::fs::read_to_string(&f).unwrap();
            (f, text)
        })
        .collect()
}

/// The answer comes after an attempt (`workbook hint ID --level 4`), not
/// beside the question: every exercise has one in its chapter's
/// answers file (`crates/workbook/answers/NN-name.md`, not in the chapter's
/// folder), and no line of it stands in any chapter's text, in an
/// appendix, in the contract that `hint` level 1 shows or in the `todo!`.
#[test]
fn every_exercise_has_an_answer_and_neither_its_text_nor_its_contract_shows_it() {
    let texts = texts_a_student_reads();
    for (file, line, region) in workspace_regions(&root()).unwrap() {
        let id = region.id.as_str();
        let chapter = exercise_chapters()
            .into_iter()
            .find(|c| Some(c.number()) == region.chapter())
            .unwrap();
        let folder = root().join(chapter.path());
        let answers_file = workbook::hint::answers_path(chapter);
        let answers = std::fs::read_to_string(root().join(&answers_file)).unwrap();
        let answer = workbook::hint::answer_in(&answers, id)
            .unwrap_or_else(|| panic!("{id}: {} has no `## {id}`", answers_file.display()));
        assert!(
            !folder.join("answers.md").exists(),
            "{id}: no answers file stands in the chapter's folder, beside its questions"
        );
        assert!(answer.trim().len() > 80, "{id}: a short answer: {answer}");
        let readme = std::fs::read_to_string(folder.join("README.md")).unwrap();
        let source = std::fs::read_to_string(root().join(&file)).unwrap();
        let contract = workbook::hint::contract(&source, line).unwrap();
        for shown in answer
            .lines()
            .map(str::trim)
            .filter(|l| l.chars().count() >= 24)
        {
            assert!(
                !readme.contains(shown),
                "{id}: its answer stands in the chapter's README: {shown:?}"
            );
            assert!(
                !contract.contains(shown),
                "{id}: its answer stands in its contract: {shown:?}"
            );
            assert!(
                !region.hint.contains(shown),
                "{id}: its answer stands in its todo!: {shown:?}"
            );
            for (text, words) in &texts {
                assert!(
                    !words.contains(shown),
                    "{id}: its answer stands in {}: {shown:?}",
                    text.display()
                );
            }
        }
    }
}
