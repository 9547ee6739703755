//! The Rust listings of a chapter's text, kept equal to tests that compile.
//!
//! A chapter's `README.md` shows short Rust examples. Each is also the body
//! of a test in the chapter's test binary, between `// ANCHOR: name` and
//! `// ANCHOR_END: name` (the Rust Book's markers), and the text names it
//! on the line before the listing:
//!
//! ````text
//! <!-- listing: tests/chapter03/listings.rs:arrival -->
//! ```rust
//! ...
//! ```
//! ````
//!
//! [`check`] fails when a listing and its test differ, so the text cannot
//! drift from the code. They used to be doctests, which `cargo test -p`
//! compiles anew on every run: about 0.45 s a chapter, 40% of `cargo test
//! -p ch01-rays` after an edit (1.02 s, now 0.60 s). In the test binary
//! they are compiled incrementally with the chapter's other tests.

use std::fmt::Write as _;
use std::path::Path;

/// The comment that names a listing's test: `<!-- listing: FILE:ANCHOR -->`.
const MARKER: &str = "<!-- listing: ";

/// Checks every ```` ```rust ```` listing of `chapter`'s `README.md` (the
/// folder of a chapter, as `env!("CARGO_MANIFEST_DIR")` gives it in its
/// tests): each is named on the line before it, and equals the anchored
/// lines of the file it names (indented or not). The listings checked, or
/// everything that is wrong, with the README's line numbers.
pub fn check(chapter: &Path) -> Result<usize, String> {
    let readme = chapter.join("README.md");
    let text = std::fs::read_to_string(&readme)
        .map_err(|e| format!("cannot read {}: {e}", readme.display()))?;
    let mut problems = String::new();
    let mut checked = 0;
    for listing in rust_listings(&text) {
        let at = format!("{}:{}", readme.display(), listing.line);
        match check_one(chapter, &listing) {
            Ok(()) => checked += 1,
            Err(problem) => {
                let _ = writeln!(problems, "{at}: {problem}");
            }
        }
    }
    if problems.is_empty() {
        Ok(checked)
    } else {
        Err(problems)
    }
}

/// [`check`] as a test: panics with everything that is wrong, or unless
/// exactly `expected` listings were checked (so that a listing taken out of
/// the text, or a test file that lost one, is noticed).
#[track_caller]
pub fn assert_checked(chapter: &str, expected: usize) {
    match check(Path::new(chapter)) {
        Ok(checked) => assert_eq!(
            checked, expected,
            "the Rust listings of {chapter}/README.md"
        ),
        Err(problems) => panic!("{problems}"),
    }
}

/// A ```` ```rust ```` block of a text.
struct Listing {
    /// The line of its opening fence, from 1.
    line: usize,
    /// The line before the fence (where its marker belongs).
    before: String,
    /// Its lines, without the fences.
    lines: Vec<String>,
}

/// The text's ```` ```rust ```` blocks (`rust,ignore` and the like too:
/// every Rust listing is checked).
fn rust_listings(text: &str) -> Vec<Listing> {
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let fence = lines[i].trim_start();
        if fence.starts_with("```rust") {
            let end = (i + 1..lines.len()).find(|&j| lines[j].trim_start().starts_with("```"));
            let end = end.unwrap_or(lines.len());
            found.push(Listing {
                line: i + 1,
                before: if i > 0 {
                    lines[i - 1].trim().to_owned()
                } else {
                    String::new()
                },
                lines: lines[i + 1..end].iter().map(|l| l.to_string()).collect(),
            });
            i = end;
        }
        i += 1;
    }
    found
}

/// Is `listing` named, and equal to the anchored lines it names?
fn check_one(chapter: &Path, listing: &Listing) -> Result<(), String> {
    let named = (listing.before.strip_prefix(MARKER))
        .and_then(|rest| rest.strip_suffix("-->"))
        .map(str::trim)
        .ok_or_else(|| {
            format!(
                "a Rust listing with no test: put `{MARKER}tests/FILE.rs:NAME -->` on the line \
                 before it, and the listing between `// ANCHOR: NAME` and `// ANCHOR_END: NAME` \
                 in a test of that file"
            )
        })?;
    let (file, anchor) =
        (named.rsplit_once(':')).ok_or_else(|| format!("`{named}` should be FILE:ANCHOR"))?;
    let source = std::fs::read_to_string(chapter.join(file))
        .map_err(|e| format!("cannot read {file}, which it names: {e}"))?;
    let anchored = anchored_lines(&source, anchor).ok_or_else(|| {
        format!("{file} has no `// ANCHOR: {anchor}` … `// ANCHOR_END: {anchor}`")
    })?;
    if anchored == listing.lines {
        return Ok(());
    }
    let line = (anchored.iter().zip(&listing.lines))
        .position(|(a, b)| a != b)
        .unwrap_or(anchored.len().min(listing.lines.len()));
    let shown = |lines: &[String]| {
        lines
            .get(line)
            .map_or("(nothing)", |l| l.as_str())
            .to_owned()
    };
    Err(format!(
        "differs from {file}:{anchor} at the listing's line {}:\n  text: {}\n  test: {}",
        line + 1,
        shown(&listing.lines),
        shown(&anchored)
    ))
}

/// The lines between `// ANCHOR: name` and `// ANCHOR_END: name` in
/// `source`, without the indentation they share.
fn anchored_lines(source: &str, name: &str) -> Option<Vec<String>> {
    let lines: Vec<&str> = source.lines().collect();
    let is = |line: &str, marker: &str| line.trim() == format!("// {marker}: {name}");
    let start = lines.iter().position(|l| is(l, "ANCHOR"))? + 1;
    let end = start + lines[start..].iter().position(|l| is(l, "ANCHOR_END"))?;
    let body = &lines[start..end];
    let indent = (body.iter().filter(|l| !l.trim().is_empty()))
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    Some(
        body.iter()
            .map(|l| l.get(indent..).unwrap_or("").to_owned())
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chapter folder with `readme` and `tests/t.rs`.
    fn chapter(readme: &str, test: &str) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("tests")).unwrap();
        std::fs::write(dir.path().join("README.md"), readme).unwrap();
        std::fs::write(dir.path().join("tests/t.rs"), test).unwrap();
        dir
    }

    const TEST: &str = "#[test]\nfn at() {\n    // ANCHOR: at\n    let x = 1;\n\n    \
                        assert_eq!(x, 1);\n    // ANCHOR_END: at\n}\n";

    #[test]
    fn a_listing_equal_to_its_test_passes() {
        let readme = "# Text\n\n<!-- listing: tests/t.rs:at -->\n```rust\nlet x = 1;\n\nassert_eq!(x, 1);\n```\n";
        assert_eq!(check(chapter(readme, TEST).path()), Ok(1));
    }

    #[test]
    fn a_listing_that_differs_names_its_line_and_both_versions() {
        let readme =
            "<!-- listing: tests/t.rs:at -->\n```rust\nlet x = 2;\n\nassert_eq!(x, 1);\n```\n";
        let error = check(chapter(readme, TEST).path()).unwrap_err();
        assert!(
            error.contains("README.md:2: differs from tests/t.rs:at at the listing's line 1"),
            "{error}"
        );
        assert!(
            error.contains("text: let x = 2;") && error.contains("test: let x = 1;"),
            "{error}"
        );
        let shorter = "<!-- listing: tests/t.rs:at -->\n```rust\nlet x = 1;\n```\n";
        let error = check(chapter(shorter, TEST).path()).unwrap_err();
        assert!(error.contains("at the listing's line 2"), "{error}");
    }

    #[test]
    fn an_unnamed_listing_or_a_missing_anchor_is_an_error() {
        let unnamed = "Text.\n```rust\nlet x = 1;\n```\n";
        let error = check(chapter(unnamed, TEST).path()).unwrap_err();
        assert!(
            error.contains("README.md:2: a Rust listing with no test"),
            "{error}"
        );
        let missing = "<!-- listing: tests/t.rs:nowhere -->\n```rust,ignore\nlet x = 1;\n```\n";
        let error = check(chapter(missing, TEST).path()).unwrap_err();
        assert!(error.contains("no `// ANCHOR: nowhere`"), "{error}");
        let no_file = "<!-- listing: tests/u.rs:at -->\n```rust\nlet x = 1;\n```\n";
        let error = check(chapter(no_file, TEST).path()).unwrap_err();
        assert!(error.contains("cannot read tests/u.rs"), "{error}");
    }

    #[test]
    fn text_blocks_are_not_listings() {
        let readme = "```text\nnot rust\n```\n\n```toml\na = 1\n```\n";
        assert_eq!(check(chapter(readme, TEST).path()), Ok(0));
    }
}
