//! `workbook hint ID`: graded help for an exercise, never its code.
//!
//! Each level adds to the one before something the `todo!` does not say.
//! Level 1 is a nudge: what to compute, the exercise's own hint, and the
//! contract of the function that holds it (its signature and doc comment:
//! what it gets, what it returns, its edge cases). Level 2
//! is the section of the chapter's README that derives it: the README
//! marks it with a line `<!-- derives: ID -->`, and the whole section under
//! the heading above that line is shown. Level 3 runs the chapter's tests
//! and names those that wait for the exercise (they reach its `todo!`), or
//! that fail while it is written, with the file that holds each test.
//! Level 4 is the answer, from the chapter's answers file
//! (`crates/workbook/answers/NN-name.md`, its section `## ID`), offered
//! only once the student has tried: the exercise's body is no longer the
//! handout's `todo!` and the chapter compiles (its tests ran at level 3).
//! The answers are in the handout, among the workbook's own files and not
//! in the chapter's folder beside the question, so this is no secret kept:
//! it is the order of things. The chapter's text derives and asks, and the
//! answer comes after an attempt.

use std::path::Path;
use std::process::ExitCode;

use crate::progress::TestOutput;
use crate::regions::Region;
use crate::workbench::chapters::{self, ChapterEntry};
use crate::workspace::{current_workspace, workspace_regions};

/// `workbook hint ID [--level N]`.
#[derive(clap::Args, Debug, Clone)]
pub struct HintArgs {
    /// The exercise, as `workbook progress` and the `todo!` name it, such
    /// as ch02-sphere.
    pub id: String,

    /// How much help: 1, a nudge (what to compute); 2, the section of the
    /// chapter's text that derives it; 3, the tests that check it; 4, the
    /// answer, once you have tried (your code is in place of the `todo!`
    /// and compiles).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=4))]
    pub level: u8,
}

/// Runs `workbook hint`.
pub fn main(args: &HintArgs) -> ExitCode {
    match hint(args) {
        Ok(text) => {
            print!("{text}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The help `args` asks for, as text.
pub fn hint(args: &HintArgs) -> Result<String, String> {
    let root = current_workspace()?;
    let regions = workspace_regions(&root)?;
    let Some((file, line, region)) = regions.iter().find(|(_, _, r)| r.id == args.id) else {
        let ids: Vec<&str> = regions.iter().map(|(_, _, r)| r.id.as_str()).collect();
        return Err(format!(
            "no exercise {:?}; the exercises are {}",
            args.id,
            ids.join(", ")
        ));
    };
    let chapter = region
        .chapter()
        .and_then(|n| {
            chapters::all()
                .iter()
                .find(|c| c.number() == n && !c.companion)
        })
        .ok_or_else(|| format!("{}: no chapter in chapters/chapters.toml", region.id))?;
    let mut text = format!(
        "{} in {}:{}: {}\n",
        region.id,
        file.display(),
        line,
        region.hint
    );
    let source = std::fs::read_to_string(root.join(file)).unwrap_or_default();
    text += &match contract(&source, *line) {
        Some(contract) => {
            format!("\nwhat it gets and returns (the contract above it):\n{contract}")
        }
        None => String::new(),
    };
    if args.level >= 2 {
        text += &derivation(&root, chapter, region)?;
    }
    if args.level >= 3 {
        let output = run_tests(&root, chapter)?;
        text += &tests_of(&root, chapter, region, &output);
        text += &match (args.level, offered(region, &output)) {
            (3, Ok(())) => format!(
                "\nthe answer, now that you have tried: workbook hint {} --level 4\n",
                region.id
            ),
            (3, Err(_)) => format!(
                "\nthe answer (workbook hint {} --level 4) comes once you have tried: your \
                 code in place of the todo!, compiling\n",
                region.id
            ),
            (_, Ok(())) => answer(&root, chapter, region, &output)?,
            (_, Err(why)) => format!("\n{why}\n"),
        };
    }
    if args.level < 3 {
        text += &format!(
            "\nmore help: workbook hint {} --level {}\n",
            region.id,
            args.level + 1
        );
    }
    Ok(text)
}

/// Is the answer to `region` offered, given the chapter's test run
/// `output`? Once the student has tried: its body is no longer the
/// handout's `todo!`, and the chapter compiles. Else why not yet.
pub fn offered(region: &Region, output: &TestOutput) -> Result<(), String> {
    if region.is_open() {
        return Err(format!(
            "the answer to {} comes after your attempt: write it in place of its todo! \
             (levels 1 to 3 say what it must do); once it compiles, this shows the answer \
             to compare with",
            region.id
        ));
    }
    if let Some(error) = &output.compile_error {
        return Err(format!(
            "your attempt at {} does not compile yet ({error}): the answer comes once it does",
            region.id
        ));
    }
    Ok(())
}

/// The answer to `region` from its chapter's answers file
/// ([`answers_path`]), after an attempt whose tests ran with `output`.
fn answer(
    root: &Path,
    chapter: &ChapterEntry,
    region: &Region,
    output: &TestOutput,
) -> Result<String, String> {
    let path = answers_path(chapter);
    let answers = std::fs::read_to_string(root.join(&path))
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let answer = answer_in(&answers, &region.id)
        .ok_or_else(|| format!("{} holds no section `## {}`", path.display(), region.id))?;
    let verdict = if output.passed_all() {
        "every test of the chapter passes: your code is an answer; the text's, to compare"
    } else {
        "you have tried; the answer"
    };
    Ok(format!("\n{verdict} ({}):\n\n{answer}", path.display()))
}

/// The folder, relative to the workspace root, that holds each chapter's
/// answers: with the workbook's own files, so that a student at work in a
/// chapter's folder finds the text's questions there and not their answers.
pub const ANSWERS: &str = "crates/workbook/answers";

/// The file that holds `chapter`'s answers, relative to the workspace
/// root: `crates/workbook/answers/NN-name.md`.
pub fn answers_path(chapter: &ChapterEntry) -> std::path::PathBuf {
    Path::new(ANSWERS).join(format!("{}.md", chapter.folder))
}

/// The section of an answers file for exercise `id`: the lines under the
/// heading `## id` up to the next heading of that level.
pub fn answer_in(answers: &str, id: &str) -> Option<String> {
    let heading = format!("## {id}");
    let mut lines = answers.lines().skip_while(|l| l.trim_end() != heading);
    lines.next()?;
    let section: Vec<&str> = lines.take_while(|l| !l.starts_with("## ")).collect();
    Some(section.join("\n").trim().to_owned() + "\n")
}

/// The contract of the function that holds the exercise whose marker is
/// on line `line` (from 1) of `source`: its doc comment and signature,
/// indented, or None if no function encloses it.
pub fn contract(source: &str, line: usize) -> Option<String> {
    let lines: Vec<&str> = source.lines().collect();
    let above = &lines[..line.saturating_sub(1).min(lines.len())];
    let is_fn = |l: &str| {
        let l = l.trim_start();
        let l = l.strip_prefix("pub ").unwrap_or(l);
        let l = l.strip_prefix("pub(crate) ").unwrap_or(l);
        l.starts_with("fn ")
    };
    let start = above.iter().rposition(|l| is_fn(l))?;
    let end = (start..above.len()).find(|&i| above[i].trim_end().ends_with('{'))?;
    let mut doc = start;
    while doc > 0 {
        let previous = above[doc - 1].trim_start();
        if !(previous.starts_with("///") || previous.starts_with("#[")) {
            break;
        }
        doc -= 1;
    }
    let shown = above[doc..=end]
        .iter()
        .filter(|l| !l.trim_start().starts_with("#["))
        .map(|l| format!("  {}", l.trim()))
        .collect::<Vec<_>>();
    Some(shown.join("\n") + "\n")
}

/// The section of the chapter's README that derives `region`.
fn derivation(root: &Path, chapter: &ChapterEntry, region: &Region) -> Result<String, String> {
    let path = chapter.path().join("README.md");
    let readme = std::fs::read_to_string(root.join(&path))
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let marker = format!("<!-- derives: {} -->", region.id);
    match section_with(&readme, &marker) {
        Some(section) => Ok(format!("\nFrom {}:\n\n{section}", path.display())),
        None => Ok(format!(
            "\n{} marks no section for {}: read it from the top of the chapter.\n",
            path.display(),
            region.id
        )),
    }
}

/// The Markdown sections that hold the line `marker`, in the order they
/// come: each from the nearest heading above the marker to the next
/// heading of the same level or higher, the marker line left out.
pub fn section_with(markdown: &str, marker: &str) -> Option<String> {
    let lines: Vec<&str> = markdown.lines().collect();
    let level = |l: &str| {
        let hashes = l.chars().take_while(|c| *c == '#').count();
        (hashes > 0 && l[hashes..].starts_with(' ')).then_some(hashes)
    };
    let sections: Vec<String> = (0..lines.len())
        .filter(|&at| lines[at].trim() == marker)
        .map(|at| {
            let start = (0..at)
                .rev()
                .find(|&i| level(lines[i]).is_some())
                .unwrap_or(0);
            let depth = level(lines[start]).unwrap_or(1);
            let end = (at + 1..lines.len())
                .find(|&i| level(lines[i]).is_some_and(|d| d <= depth))
                .unwrap_or(lines.len());
            let mut section: Vec<&str> = lines[start..end].to_vec();
            section.retain(|l| l.trim() != marker);
            let text = section.join("\n").replace("\n\n\n", "\n\n");
            text.trim_end().to_owned() + "\n"
        })
        .collect();
    (!sections.is_empty()).then(|| sections.join("\n"))
}

/// `cargo test -p` of the chapter, read.
fn run_tests(root: &Path, chapter: &ChapterEntry) -> Result<TestOutput, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = std::process::Command::new(cargo)
        .args([
            "test",
            "-p",
            &chapter.package(),
            "--no-fail-fast",
            "--color",
            "never",
        ])
        .current_dir(root)
        .output()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    Ok(crate::progress::parse(&text))
}

/// The chapter's tests that check `region` (from their run `parsed`):
/// those that reach its `todo!` while it is not written; once it is, those
/// that fail, with their messages.
fn tests_of(root: &Path, chapter: &ChapterEntry, region: &Region, parsed: &TestOutput) -> String {
    let package = chapter.package();
    if let Some(error) = &parsed.compile_error {
        return format!("\n{package} does not compile yet: {error}\n");
    }
    let todo = format!("{}:", region.id);
    let waiting: Vec<&(String, String)> = parsed
        .panics
        .iter()
        .filter(|(_, message)| message.contains(&todo))
        .collect();
    let (intro, tests) = if !waiting.is_empty() {
        ("the tests that wait for it (they reach its todo!)", waiting)
    } else if parsed.failed > 0 {
        (
            "it is written; the chapter's failing tests",
            parsed.panics.iter().collect(),
        )
    } else {
        return format!("\nevery test of {package} passes\n");
    };
    let mut text = format!("\n{intro}:\n");
    for (test, message) in tests {
        let name = test.rsplit("::").next().unwrap_or(test);
        let place = defined_in(&root.join(chapter.path()).join("tests"), name)
            .map(|p| p.strip_prefix(root).unwrap_or(&p).display().to_string())
            .unwrap_or_else(|| "its tests".into());
        text += &format!(
            "  {test} ({place})\n    {}\n",
            message.lines().next().unwrap_or("")
        );
    }
    text
}

/// The test file under `dir` that defines `fn name`.
fn defined_in(dir: &Path, name: &str) -> Option<std::path::PathBuf> {
    let needle = format!("fn {name}(");
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).ok()? {
            let path = entry.ok()?.path();
            if path.is_dir() {
                folders.push(path);
            } else if std::fs::read_to_string(&path).is_ok_and(|t| t.contains(&needle)) {
                return Some(path);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::{answer_in, contract, offered, section_with};
    use crate::progress::TestOutput;
    use crate::regions::regions;

    #[test]
    fn the_answer_comes_after_an_attempt_that_compiles() {
        let source = |body: &str| {
            let text = format!(
                "fn f() -> f32 {{\n    // EXERCISE(ch03-lambert): l\n{body}\n    // END EXERCISE\n}}\n"
            );
            regions(&text).unwrap().remove(0)
        };
        let failing = TestOutput {
            failed: 1,
            ..TestOutput::default()
        };
        let open = source("    todo!(\"ch03-lambert: l\")");
        let why = offered(&open, &failing).unwrap_err();
        assert!(why.contains("after your attempt"), "{why}");
        let tried = source("    0.5");
        assert_eq!(offered(&tried, &failing), Ok(()));
        let broken = TestOutput {
            compile_error: Some("error[E0308]: mismatched types".into()),
            ..TestOutput::default()
        };
        let why = offered(&tried, &broken).unwrap_err();
        assert!(why.contains("does not compile yet"), "{why}");
    }

    #[test]
    fn an_answer_is_the_section_under_its_id() {
        let answers = "# Answers\n\nintro\n\n## ch03-spot\n\nS(s) = ...\n\n### aside\n\nmore\n\n## ch03-lambert\n\nk_d ...\n";
        assert_eq!(
            answer_in(answers, "ch03-spot").unwrap(),
            "S(s) = ...\n\n### aside\n\nmore\n"
        );
        assert_eq!(answer_in(answers, "ch03-lambert").unwrap(), "k_d ...\n");
        assert_eq!(answer_in(answers, "ch03-light-loop"), None);
    }

    #[test]
    fn the_nudge_shows_the_contract_of_the_function_around_the_exercise() {
        let source = "use x;\n\n/// Not this one.\nfn other() {}\n\n/// The cone's factor.\n///\n/// * 1 inside.\n\
                      #[must_use]\npub fn spot_factor(\n    axis: Vec3,\n) -> f32 {\n    let a = 1;\n    \
                      // EXERCISE(ch03-spot): the factor\n    todo!()\n    // END EXERCISE\n}\n";
        let marker = source
            .lines()
            .position(|l| l.contains("EXERCISE("))
            .unwrap()
            + 1;
        let shown = contract(source, marker).unwrap();
        assert_eq!(
            shown,
            "  /// The cone's factor.\n  ///\n  /// * 1 inside.\n  pub fn spot_factor(\n  axis: Vec3,\n  ) -> f32 {\n"
        );
        assert!(!shown.contains("the factor") && !shown.contains("let a"));
        assert_eq!(contract("// EXERCISE(x): y\n", 1), None);
    }

    const README: &str = "# Chapter\n\nintro\n\n## The sphere\n\n<!-- derives: ch02-sphere -->\nA ray meets a sphere where...\n\n### The roots\n\nt = ...\n\n## Triangles\n\nnot this\n";

    #[test]
    fn the_section_runs_from_its_heading_to_the_next_of_its_level() {
        let section = section_with(README, "<!-- derives: ch02-sphere -->").unwrap();
        assert!(section.starts_with("## The sphere\n"), "{section}");
        assert!(section.contains("### The roots"), "{section}");
        assert!(
            !section.contains("Triangles") && !section.contains("derives"),
            "{section}"
        );
        assert_eq!(section_with(README, "<!-- derives: ch02-plane -->"), None);
        let twice = README.replace(
            "### The roots\n",
            "### The roots\n<!-- derives: ch02-plane -->\n",
        );
        let twice = twice.replace(
            "## Triangles\n",
            "## Triangles\n<!-- derives: ch02-plane -->\n",
        );
        let both = section_with(&twice, "<!-- derives: ch02-plane -->").unwrap();
        assert!(
            both.starts_with("### The roots\n") && both.contains("\n## Triangles\n"),
            "{both}"
        );
    }
}
