//! Every relative link and picture of the built book leads somewhere: to a
//! file that mdBook wrote, and to a heading of it if it names one.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

/// The links of the HTML under `html` that lead nowhere, one line each:
/// the page, the link, and what is missing.
pub fn broken_links(html: &Path) -> Result<Vec<String>, String> {
    let mut pages = Vec::new();
    collect_pages(html, &mut pages)?;
    let mut ids: HashMap<PathBuf, Vec<String>> = HashMap::new();
    let mut broken = Vec::new();
    // The 404 page's links start at the site's root, where a server puts it.
    pages.retain(|page| page.file_name().is_none_or(|name| name != "404.html"));
    for page in &pages {
        let text = fs::read_to_string(page).map_err(|e| format!("{}: {e}", page.display()))?;
        for target in targets(&text) {
            if let Some(problem) = check(page, &target, &mut ids) {
                let name = page.strip_prefix(html).unwrap_or(page).display();
                broken.push(format!("{name}: {target}: {problem}"));
            }
        }
    }
    broken.sort();
    broken.dedup();
    Ok(broken)
}

fn collect_pages(dir: &Path, pages: &mut Vec<PathBuf>) -> Result<(), String> {
    let entries = fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for entry in entries {
        let path = entry.map_err(|e| e.to_string())?.path();
        if path.is_dir() {
            collect_pages(&path, pages)?;
        } else if path.extension().is_some_and(|e| e == "html") {
            pages.push(path);
        }
    }
    Ok(())
}

/// The `href` and `src` values of `html` that point inside the book.
pub fn targets(html: &str) -> Vec<String> {
    let mut found = Vec::new();
    for attribute in ["href=\"", "src=\""] {
        for (at, _) in html.match_indices(attribute) {
            let rest = &html[at + attribute.len()..];
            let value = &rest[..rest.find('"').unwrap_or(0)];
            let external = ["http:", "https:", "mailto:", "javascript:", "data:", "{{"]
                .iter()
                .any(|scheme| value.starts_with(scheme));
            if !value.is_empty() && !external {
                found.push(value.to_string());
            }
        }
    }
    found
}

/// What is wrong with `target` on `page`, if anything.
fn check(page: &Path, target: &str, ids: &mut HashMap<PathBuf, Vec<String>>) -> Option<String> {
    let (path, fragment) = match target.split_once('#') {
        Some((path, fragment)) => (path, Some(fragment)),
        None => (target, None),
    };
    let path = path.split('?').next().unwrap_or(path);
    let mut file = if path.is_empty() {
        page.to_path_buf()
    } else {
        page.parent()?.join(path.replace("%20", " "))
    };
    if file.is_dir() {
        file = file.join("index.html");
    }
    if !file.is_file() {
        return Some("no such file".into());
    }
    let fragment =
        fragment.filter(|f| !f.is_empty() && file.extension().is_some_and(|e| e == "html"))?;
    let known = ids.entry(file.clone()).or_insert_with(|| {
        let text = fs::read_to_string(&file).unwrap_or_default();
        ids_of(&text)
    });
    (!known.iter().any(|id| id == fragment)).then(|| format!("no heading #{fragment} there"))
}

/// The `id`s of the elements of `html`.
fn ids_of(html: &str) -> Vec<String> {
    html.match_indices(" id=\"")
        .map(|(at, m)| {
            let rest = &html[at + m.len()..];
            rest[..rest.find('"').unwrap_or(0)].to_string()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_inside_the_book_are_found_and_external_ones_skipped() {
        let html = r#"<a href="a.html#x">a</a><img src="p.png"><a href="https://e.org">e</a><a href="mailto:m">m</a>"#;
        assert_eq!(
            targets(html),
            vec!["a.html#x".to_string(), "p.png".to_string()]
        );
    }

    #[test]
    fn a_missing_file_and_a_missing_heading_are_broken() {
        let dir = std::env::temp_dir().join(format!("book-links-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        fs::write(dir.join("a.html"), r#"<h2 id="x">X</h2><a href="a.html#x">ok</a><a href="a.html#y">no heading</a><a href="b.html">no file</a>"#).unwrap();
        let broken = broken_links(&dir).unwrap();
        fs::remove_dir_all(&dir).unwrap();
        assert_eq!(
            broken,
            vec![
                "a.html: a.html#y: no heading #y there".to_string(),
                "a.html: b.html: no such file".to_string()
            ]
        );
    }
}
