//! Sources that reach outside their folder: a `#[path]` attribute, an
//! `include!`, `include_str!` or `include_bytes!` whose path is absolute,
//! leaves the student's chapter folder (its sources may read its README and
//! scenes), or is not a plain string at all (built by
//! `concat!`, `env!` or a macro's argument, so that where it leads cannot be
//! read from the source).
//!
//! The sandbox already hides what they would reach (the reference, other
//! students, the teacher's files: `sandbox/bwrap.rs`); the flag tells the
//! teacher that someone tried. The scan reads the text, not a parse: a
//! comment that shows such a line is flagged too, which a teacher sees at
//! a glance.

use std::path::{Component, Path, PathBuf};

/// The macros that read a file at compile time.
const INCLUDES: [&str; 3] = ["include_bytes", "include_str", "include"];

/// What in `text` (the file `file`, relative to the handout, of the
/// student's folder `folder`) reaches outside `folder`: one line each.
pub fn reaching(text: &str, file: &Path, folder: &Path) -> Vec<String> {
    let mut found = Vec::new();
    let line_of = |at: usize| text[..at].matches('\n').count() + 1;
    let here = file.parent().unwrap_or(Path::new(""));
    for (at, what, argument) in includes(text).into_iter().chain(paths(text)) {
        // A module's #[path] is relative to the file's folder; inside an
        // inline module of a file other than a mod.rs, lib.rs or main.rs,
        // to the folder named like the file. Both are checked.
        let mut bases = vec![here.to_owned()];
        if what == "#[path]" && !is_mod_file(file) {
            bases.push(here.join(file.file_stem().unwrap_or_default()));
        }
        let why = match argument {
            None => Some("not a plain string, so where it leads cannot be read"),
            Some(path) if Path::new(&path).is_absolute() => Some("an absolute path"),
            Some(path) if bases.iter().any(|b| !within(&b.join(&path), folder)) => {
                Some("outside the student's folder")
            }
            Some(_) => None,
        };
        if let Some(why) = why {
            found.push(format!(
                "{}:{}: {what} reaches outside its folder ({why})",
                file.display(),
                line_of(at)
            ));
        }
    }
    found
}

/// Is `file` a mod.rs, lib.rs or main.rs?
fn is_mod_file(file: &Path) -> bool {
    let name = file.file_name().and_then(|n| n.to_str()).unwrap_or("");
    matches!(name, "mod.rs" | "lib.rs" | "main.rs")
}

/// Does `path` (relative, `..` resolved by name) stay inside `folder`?
fn within(path: &Path, folder: &Path) -> bool {
    let mut resolved = PathBuf::new();
    for part in path.components() {
        match part {
            Component::ParentDir => {
                if !resolved.pop() {
                    return false;
                }
            }
            Component::Normal(name) => resolved.push(name),
            Component::CurDir => {}
            Component::RootDir | Component::Prefix(_) => return false,
        }
    }
    resolved.starts_with(folder)
}

/// Each `include!`-like macro call: where, which, and its path if it is a
/// plain string literal.
fn includes(text: &str) -> Vec<(usize, &'static str, Option<String>)> {
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(offset) = text[from..].find("include") {
        let at = from + offset;
        from = at + "include".len();
        let before = text[..at].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let Some(name) = INCLUDES.iter().find(|n| text[at..].starts_with(**n)) else {
            continue;
        };
        let rest = text[at + name.len()..].trim_start();
        let Some(rest) = rest.strip_prefix('!') else {
            continue;
        };
        let rest = rest.trim_start();
        let Some(rest) = rest.strip_prefix(['(', '[', '{']) else {
            continue;
        };
        let what = match *name {
            "include" => "include!",
            "include_str" => "include_str!",
            _ => "include_bytes!",
        };
        found.push((at, what, literal_alone(rest, [')', ']', '}'])));
    }
    found
}

/// Each `path = …` inside an attribute `#[…]` or `#![…]`.
fn paths(text: &str) -> Vec<(usize, &'static str, Option<String>)> {
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(offset) = text[from..].find('#') {
        let at = from + offset;
        from = at + 1;
        let rest = text[from..].trim_start();
        let rest = rest.strip_prefix('!').unwrap_or(rest).trim_start();
        let Some(body) = rest.strip_prefix('[') else {
            continue;
        };
        let end = body.find(']').map_or(body.len(), |e| e + 1);
        let attribute = &body[..end];
        let mut search = 0;
        while let Some(p) = attribute[search..].find("path") {
            let start = search + p;
            search = start + 4;
            let before = attribute[..start].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                continue;
            }
            let after = attribute[search..].trim_start();
            if let Some(value) = after.strip_prefix('=') {
                found.push((
                    at,
                    "#[path]",
                    literal_alone(value.trim_start(), [']', ',', ')']),
                ));
            }
        }
    }
    found
}

/// The string literal at the start of `text`, if it is followed by one of
/// `ends` (after blanks or a comma): a plain path; else none.
fn literal_alone(text: &str, ends: [char; 3]) -> Option<String> {
    let text = text.trim_start();
    let (value, rest) = if let Some(raw) = text.strip_prefix('r') {
        let hashes = raw.len() - raw.trim_start_matches('#').len();
        let body = raw[hashes..].strip_prefix('"')?;
        let close = format!("\"{}", "#".repeat(hashes));
        let end = body.find(&close)?;
        (body[..end].to_owned(), &body[end + close.len()..])
    } else {
        let body = text.strip_prefix('"')?;
        let end = body.find('"')?;
        let value = &body[..end];
        if value.contains('\\') {
            return None;
        }
        (value.to_owned(), &body[end + 1..])
    };
    let rest = rest.trim_start();
    let rest = rest.strip_prefix(',').unwrap_or(rest).trim_start();
    rest.starts_with(ends).then_some(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flags(text: &str) -> Vec<String> {
        let file = Path::new("chapters/01-rays/src/lib.rs");
        reaching(text, file, Path::new("chapters/01-rays"))
    }

    #[test]
    fn paths_and_includes_that_leave_the_folder_are_found() {
        let honest = "#![doc = include_str!(\"../README.md\")]\n#[path = \"b.rs\"]\nmod b;\n\
                      const X: &str = include_str!(\"../scenes/default.toml\");";
        assert!(flags(honest).is_empty(), "{:?}", flags(honest));
        let absolute = flags("#[path = \"/work/ref/chapters/01-rays/src/lib.rs\"]\nmod answer;");
        assert_eq!(absolute.len(), 1);
        assert!(absolute[0].starts_with("chapters/01-rays/src/lib.rs:1: #[path]"));
        assert!(absolute[0].contains("an absolute path"));
        let up = flags("\n\nconst S: &str = include_str! ( \"../../02-hits/src/lib.rs\" );");
        assert_eq!(up.len(), 1);
        assert!(
            up[0].contains(":3: include_str!") && up[0].contains("outside"),
            "{up:?}"
        );
        let built = flags("const B: &[u8] = include_bytes!(concat!(env!(\"HOME\"), \"/x\"));");
        assert!(built[0].contains("not a plain string"), "{built:?}");
        let attr = flags("#[cfg_attr(all(), path = r\"/etc/passwd\")]\nmod x;");
        assert!(attr[0].contains("an absolute path"), "{attr:?}");
        assert!(flags("include!(\"/abs/other.rs\");")[0].contains("include!"));
        assert!(flags("let path = \"/etc\"; my_include(\"/x\");").is_empty());
        // A non-mod file's #[path] is relative to its folder (or, in an
        // inline module, to the folder named like it): both must stay in.
        let camera = Path::new("chapters/01-rays/src/camera.rs");
        let nested = reaching(
            "#[path = \"../x.rs\"]\nmod x;",
            camera,
            Path::new("chapters/01-rays"),
        );
        assert!(nested.is_empty(), "{nested:?}");
        let sideways = reaching(
            "#[path = \"../../02-hits/src/lib.rs\"]\nmod other;",
            camera,
            Path::new("chapters/01-rays"),
        );
        assert!(sideways[0].contains("outside"), "{sideways:?}");
    }
}
