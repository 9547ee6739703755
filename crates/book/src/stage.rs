//! The book's sources, laid out in `target/book/src` at the paths they
//! have in the workspace: the pages `book/SUMMARY.md` lists, the pictures
//! they show, and nothing else (no source file, so no solution).

use std::fs;
use std::path::{Component, Path, PathBuf};

/// Lays out the book under `book` (book.toml, src/); the number of pages.
pub fn stage(root: &Path, book: &Path) -> Result<usize, String> {
    let src = book.join("src");
    if src.exists() {
        fs::remove_dir_all(&src).map_err(|e| format!("cannot clear {}: {e}", src.display()))?;
    }
    copy(&root.join("book/book.toml"), &book.join("book.toml"))?;
    let summary = read(&root.join("book/SUMMARY.md"))?;
    write(&src.join("SUMMARY.md"), &summary)?;
    let pages = links_in("book/SUMMARY.md", &summary);
    for (line, page) in &pages {
        let file = root.join(page);
        if !file.is_file() {
            return Err(format!("book/SUMMARY.md:{line}: no page {page}"));
        }
        stage_page(root, &src, Path::new(page))?;
    }
    Ok(pages.len())
}

/// One page: its text with its includes expanded, and its pictures.
fn stage_page(root: &Path, src: &Path, page: &Path) -> Result<(), String> {
    let text = read(&root.join(page))?;
    let dir = page.parent().unwrap_or(Path::new(""));
    let text = readme_links_to_index(&expand_includes(root, page, &text)?);
    for (line, picture) in pictures(&text) {
        if picture.starts_with("http") {
            continue;
        }
        let path = inside(root, &dir.join(&picture)).ok_or_else(|| {
            format!(
                "{}:{line}: {picture} is outside the workspace",
                page.display()
            )
        })?;
        if !root.join(&path).is_file() {
            return Err(format!("{}:{line}: no picture {picture}", page.display()));
        }
        copy(&root.join(&path), &src.join(&path))?;
    }
    write(&src.join(page), &text)
}

/// `text` with its links to a `README.md` sent to `index.md`: mdBook makes
/// a README page `index.html`, but turns a link to it into `README.html`.
pub fn readme_links_to_index(text: &str) -> String {
    let mut fenced = false;
    let mut out = String::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        }
        let mut rest = line;
        while let (false, Some(start)) = (fenced, rest.find("](")) {
            let end = rest[start..].find(')').map_or(rest.len(), |e| start + e);
            let target = &rest[start..end];
            out.push_str(&rest[..start]);
            out.push_str(&target.replace("README.md", "index.md"));
            rest = &rest[end..];
        }
        out.push_str(rest);
        out.push('\n');
    }
    out
}

/// The targets of the Markdown links `[...](target)` of `text`, with their
/// lines, outside code blocks; `name` only names the file in messages.
pub fn links_in(_name: &str, text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (line, content) in prose_lines(text) {
        let mut rest = content;
        while let Some(start) = rest.find("](") {
            rest = &rest[start + 2..];
            let end = rest.find(')').unwrap_or(rest.len());
            let target = rest[..end].split('#').next().unwrap_or("").trim();
            if !target.is_empty() && !target.contains("://") {
                found.push((line, target.to_string()));
            }
            rest = &rest[end..];
        }
    }
    found
}

/// The pictures `![alt](path)` and `<img src="path">` of `text`, with lines.
pub fn pictures(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (line, content) in prose_lines(text) {
        for (i, _) in content.match_indices("![") {
            let rest = &content[i..];
            let Some(open) = rest.find("](") else {
                continue;
            };
            let rest = &rest[open + 2..];
            let end = rest.find(')').unwrap_or(rest.len());
            found.push((line, rest[..end].trim().to_string()));
        }
        for (i, _) in content.match_indices("<img ") {
            let rest = &content[i..];
            if let Some(at) = rest.find("src=\"") {
                let rest = &rest[at + 5..];
                let end = rest.find('"').unwrap_or(rest.len());
                found.push((line, rest[..end].to_string()));
            }
        }
    }
    found
}

/// The lines of `text` (numbered from 1) outside fenced code blocks.
fn prose_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let mut fenced = false;
    text.lines().enumerate().filter_map(move |(i, line)| {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            return None;
        }
        (!fenced).then_some((i + 1, line))
    })
}

/// `text` (of `page`) with each `{{#include FILE:ANCHOR}}` replaced by the
/// lines between `ANCHOR: name` and `ANCHOR_END: name` in FILE (relative to
/// the page), or by all of FILE. A missing file or anchor is an error, and
/// so is a listing that would show an exercise's solution.
pub fn expand_includes(root: &Path, page: &Path, text: &str) -> Result<String, String> {
    let dir = page.parent().unwrap_or(Path::new(""));
    let mut out = String::new();
    for (i, line) in text.lines().enumerate() {
        let here = format!("{}:{}", page.display(), i + 1);
        match line
            .trim()
            .strip_prefix("{{#include ")
            .and_then(|l| l.strip_suffix("}}"))
        {
            None if line.contains("{{#") => {
                return Err(format!(
                    "{here}: only {{{{#include FILE:ANCHOR}}}} is supported"
                ));
            }
            None => out.push_str(line),
            Some(what) => {
                let (file, anchor) = match what.trim().split_once(':') {
                    Some((file, anchor)) => (file, Some(anchor)),
                    None => (what.trim(), None),
                };
                let path = inside(root, &dir.join(file))
                    .ok_or_else(|| format!("{here}: {file} is outside the workspace"))?;
                let source = read(&root.join(&path)).map_err(|e| format!("{here}: {e}"))?;
                let listing =
                    listing(&source, anchor).map_err(|e| format!("{here}: {file}: {e}"))?;
                out.push_str(listing.trim_end_matches('\n'));
            }
        }
        out.push('\n');
    }
    Ok(out)
}

/// The lines of `source` between the anchor's markers (all of it without
/// an anchor), without any marker line; refused if they reach into an
/// exercise region (`// EXERCISE(id)` to `// END EXERCISE`).
pub fn listing(source: &str, anchor: Option<&str>) -> Result<String, String> {
    let mut inside_anchor = anchor.is_none();
    let mut found = anchor.is_none();
    let mut in_exercise = false;
    let mut lines = Vec::new();
    for line in source.lines() {
        let marker = line
            .trim_start()
            .trim_start_matches("//")
            .trim_start_matches('#')
            .trim();
        if line.contains("EXERCISE(") {
            in_exercise = true;
        }
        if let Some(name) = anchor {
            if marker == format!("ANCHOR: {name}") {
                (inside_anchor, found) = (true, true);
                continue;
            }
            if marker == format!("ANCHOR_END: {name}") {
                inside_anchor = false;
                continue;
            }
        }
        if marker.starts_with("ANCHOR") {
            continue;
        }
        if inside_anchor && in_exercise {
            return Err(
                "the listing reaches into an exercise: the book must not publish its solution"
                    .into(),
            );
        }
        if line.contains("END EXERCISE") {
            in_exercise = false;
        }
        if inside_anchor {
            lines.push(line);
        }
    }
    if !found {
        return Err(format!("no anchor {}", anchor.unwrap_or_default()));
    }
    Ok(lines.join("\n"))
}

/// `path` with `.` and `..` worked out, if it stays inside the workspace.
fn inside(_root: &Path, path: &Path) -> Option<PathBuf> {
    let mut parts = Vec::new();
    for component in path.components() {
        match component {
            Component::Normal(part) => parts.push(part),
            Component::CurDir => {}
            Component::ParentDir => {
                parts.pop()?;
            }
            _ => return None,
        }
    }
    Some(parts.iter().collect())
}

fn read(path: &Path) -> Result<String, String> {
    fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    make_parent(path)?;
    fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn copy(from: &Path, to: &Path) -> Result<(), String> {
    make_parent(to)?;
    fs::copy(from, to)
        .map(|_| ())
        .map_err(|e| format!("cannot copy {} to {}: {e}", from.display(), to.display()))
}

fn make_parent(path: &Path) -> Result<(), String> {
    let parent = path.parent().expect("a file in a folder");
    fs::create_dir_all(parent).map_err(|e| format!("cannot make {}: {e}", parent.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "fn a() {}\n// ANCHOR: ray\npub struct Ray;\n// ANCHOR_END: ray\n\
        fn b() {\n    // EXERCISE(ch01-x): hint\n    // ANCHOR: answer\n    secret();\n    // ANCHOR_END: answer\n    // END EXERCISE\n}\n";

    #[test]
    fn a_listing_is_the_anchor_s_lines_only() {
        assert_eq!(listing(SOURCE, Some("ray")).unwrap(), "pub struct Ray;");
    }

    #[test]
    fn a_missing_anchor_and_an_exercise_are_refused() {
        assert_eq!(listing(SOURCE, Some("nope")).unwrap_err(), "no anchor nope");
        let answer = listing(SOURCE, Some("answer")).unwrap_err();
        assert!(answer.contains("exercise"), "{answer}");
        assert!(listing(SOURCE, None).unwrap_err().contains("exercise"));
    }

    #[test]
    fn links_and_pictures_are_found_outside_code_blocks() {
        let text =
            "see [a](x/README.md#top) and ![b](p.png)\n```\n[no](y.md)\n```\n<img src=\"q.svg\">\n";
        assert_eq!(
            links_in("t", text),
            vec![(1, "x/README.md".into()), (1, "p.png".into())]
        );
        assert_eq!(
            pictures(text),
            vec![(1, "p.png".into()), (5, "q.svg".into())]
        );
    }

    #[test]
    fn links_to_a_readme_go_to_its_index_outside_code() {
        let text = "[a](../x/README.md#h) in README.md) [b](README.md)\n```\n[c](README.md)\n```\n";
        let expected =
            "[a](../x/index.md#h) in README.md) [b](index.md)\n```\n[c](README.md)\n```\n";
        assert_eq!(readme_links_to_index(text), expected);
    }

    #[test]
    fn paths_leaving_the_workspace_are_refused() {
        let root = Path::new("/w");
        assert_eq!(
            inside(root, Path::new("chapters/01/../../snapshots/a.png")),
            Some("snapshots/a.png".into())
        );
        assert_eq!(inside(root, Path::new("../x")), None);
    }
}
