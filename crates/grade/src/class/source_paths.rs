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

/// The most of them listed for one file, then a line saying there are more.
pub const MOST_FOUND: usize = 100;

/// What in `text` (the file `file`, relative to the handout, of the
/// student's folder `folder`) reaches outside `folder`: one line each, at
/// most [`MOST_FOUND`]. The text is read in one pass, whatever it holds (a
/// student's file of 16 MiB made of `#[` or `include!(x)` would otherwise
/// be read again from each of them: days of the grader's time).
pub fn reaching(text: &str, file: &Path, folder: &Path) -> Vec<String> {
    let mut found = Vec::new();
    // The line of byte `at`: one more than the line breaks before it.
    let breaks: Vec<usize> = text.match_indices('\n').map(|(at, _)| at).collect();
    let line_of = |at: usize| breaks.partition_point(|&b| b < at) + 1;
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
            if found.len() == MOST_FOUND {
                found.push(format!("{}: more of them, not listed", file.display()));
                break;
            }
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
        // Go on after the attribute: a `#[` inside it ends at the same `]`,
        // so its `path`s are among this one's; and a text with no `]` is
        // read once, not once for every `#[` in it.
        from = text.len() - body.len() + end;
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

/// The longest path a literal is read for: its end is looked for no
/// further, so that a literal never closed costs a short look, not a read
/// to the end of the file (for each of a million of them). The paths of a
/// handout's sources are a few dozen bytes; a longer one is not read, so
/// it is flagged, never missed.
const LONGEST: usize = 256;

/// The first [`LONGEST`] bytes of `text` (or fewer, to end on a character).
fn window(text: &str) -> &str {
    let mut end = text.len().min(LONGEST);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// The string literal at the start of `text`, if it is followed by one of
/// `ends` (after blanks or a comma): a plain path; else none.
fn literal_alone(text: &str, ends: [char; 3]) -> Option<String> {
    let text = text.trim_start();
    let (value, rest) = if let Some(raw) = text.strip_prefix('r') {
        let hashes = raw.len() - raw.trim_start_matches('#').len();
        let body = raw[hashes..].strip_prefix('"')?;
        let close = format!("\"{}", "#".repeat(hashes));
        let end = window(body).find(&close)?;
        (body[..end].to_owned(), &body[end + close.len()..])
    } else {
        let body = text.strip_prefix('"')?;
        let end = window(body).find('"')?;
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

    /// Texts made to be slow to scan: an attribute never closed after
    /// each `#[`, a raw string never closed after each `include!`, and a
    /// flag on every line of a long file (each line counted from the top).
    fn slow_texts(size: usize) -> [String; 3] {
        let repeat = |unit: &str| unit.repeat(size / unit.len());
        [
            repeat("#["),
            repeat("include!(r#\""),
            repeat("include!(x)\n"),
        ]
    }

    #[test]
    fn a_file_made_to_be_slow_to_scan_is_scanned_in_one_pass() {
        for text in slow_texts(4 << 20) {
            let start = std::time::Instant::now();
            let found = flags(&text);
            let took = start.elapsed();
            assert!(found.len() <= MOST_FOUND + 1, "{} flags", found.len());
            // One pass takes a second at most; a read from each of them
            // took a minute for a 256 KiB file, and grows as its square.
            assert!(took.as_secs() < 20, "{:?}: {took:?}", &text[..12]);
        }
        let many = flags(&slow_texts(1 << 20)[2]);
        assert_eq!(many.len(), MOST_FOUND + 1);
        assert!(many[MOST_FOUND - 1].starts_with("chapters/01-rays/src/lib.rs:100: include!"));
        assert!(many[MOST_FOUND].ends_with("more of them, not listed"));
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
