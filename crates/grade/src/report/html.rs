//! The class report: one static HTML page that opens from the file system
//! (no server, no script), with the pictures beside it in plain folders.
//! At the top, the class in a table: each student's score, whether their
//! code compiled, each exercise passed or not (the message on hover), the
//! flags. Below, a section per student: what went wrong, chapter by
//! chapter, and their pictures: each that differs from the reference as
//! the snapshot check draws it (reference | difference mask | theirs), and
//! the chapter's reference picture where theirs match it.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use super::junit::escape;
use super::{Class, points};
use crate::judging::verdict::{ChapterRun, StudentResult};
use workbench::chapters;

/// The page's style: readable, compact, pictures pixelated when enlarged.
const STYLE: &str = "body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}\
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 6px;text-align:center}\
td.name{text-align:left}.ok{background:#d8f3d8}.no{background:#f8d7d7}.off{background:#eee}\
.flag{color:#a40;font-weight:bold}section{border-top:2px solid #888;margin-top:1.5em}\
figure{display:inline-block;margin:4px 12px 4px 0;vertical-align:top}\
figure img{image-rendering:pixelated;border:1px solid #999}\
img.diff{width:720px}img.ref{width:240px}figcaption{font-size:12px;color:#555}\
code{background:#f4f4f4;padding:0 3px}ul{margin:.2em 0}";

/// Writes `index.html` into `dir` (with the reference's pictures beside
/// it); its path.
pub fn write_report(dir: &Path, class: &Class) -> Result<PathBuf, String> {
    let pictures = reference_pictures(dir, class)?;
    let mut html = format!(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>raybook: the class</title><style>{STYLE}</style></head><body>\n\
         <h1>The class</h1>\n<p>Graded against raybook <b>{}</b>; chapters {}. \
         Points from <code>points.toml</code>.</p>\n",
        escape(&class.label()),
        escape(
            &pictures
                .iter()
                .map(|(f, _)| f.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        )
    );
    let unsandboxed = class.students.iter().flat_map(|s| &s.warnings);
    if let Some(warning) = unsandboxed
        .into_iter()
        .find(|w| *w == crate::sandbox::bwrap::UNSANDBOXED)
    {
        let _ = writeln!(html, "<p class=\"flag\">WARNING: {}.</p>", escape(warning));
    }
    html.push_str(&table(class));
    for student in class.students {
        html.push_str(&section(class, student, &pictures));
    }
    html.push_str("</body></html>\n");
    super::write(&dir.join("index.html"), html)
}

/// Copies each graded chapter's reference picture (its `verify` snapshot,
/// else its first) to `_reference/<folder>.png`; the chapters with the
/// picture's path relative to `dir`.
fn reference_pictures(dir: &Path, class: &Class) -> Result<Vec<(String, String)>, String> {
    let mut found = Vec::new();
    for folder in class.reference.tests.chapters.keys() {
        let snapshots = class.reference.base.copy.join("snapshots").join(folder);
        let verify = chapters::find(folder).and_then(|c| c.verify.clone());
        let chosen = match verify {
            Some(v) => snapshots.join(format!("{}.snap.png", v.snapshot)),
            None => first_png(&snapshots).unwrap_or_default(),
        };
        let relative = format!("_reference/{folder}.png");
        if let Ok(bytes) = std::fs::read(&chosen) {
            ch00_toolkit::image::write_atomically(&dir.join(&relative), &bytes)
                .map_err(|e| format!("cannot write {relative}: {e}"))?;
        }
        found.push((folder.clone(), relative));
    }
    Ok(found)
}

/// The first `.snap.png` of a folder, by name.
fn first_png(folder: &Path) -> Option<PathBuf> {
    let mut pngs: Vec<PathBuf> = std::fs::read_dir(folder)
        .ok()?
        .filter_map(|e| Some(e.ok()?.path()))
        .filter(|p| p.to_string_lossy().ends_with(".snap.png"))
        .collect();
    pngs.sort();
    pngs.into_iter().next()
}

/// The class table.
fn table(class: &Class) -> String {
    let exercises = &class.reference.tests.exercises;
    let mut html = String::from("<table><tr><th>student</th><th>score</th><th>compiled</th>");
    for e in exercises {
        let _ = write!(
            html,
            "<th title=\"{}\">{}</th>",
            escape(&e.hint),
            escape(&e.id)
        );
    }
    html.push_str("<th>flags</th><th>time</th></tr>\n");
    for student in class.students {
        html.push_str(&row(class, student));
    }
    html + "</table>\n"
}

/// A student's row of the class table.
fn row(class: &Class, student: &StudentResult) -> String {
    let (score, max) = class.score(student);
    let mut html = format!(
        "<tr><td class=\"name\"><a href=\"#{}\">{}</a></td>",
        escape(&student.slug),
        escape(&student.name)
    );
    let exercises = &class.reference.tests.exercises;
    if let Some(reason) = &student.refused {
        let _ = writeln!(
            html,
            "<td>–</td><td colspan=\"{}\" class=\"off\">not graded: {}</td><td></td><td></td></tr>",
            exercises.len() + 1,
            escape(reason)
        );
        return html;
    }
    let compiled = if student.compiled() {
        ("ok", "yes")
    } else {
        ("no", "no")
    };
    let _ = write!(
        html,
        "<td>{}/{}</td><td class=\"{}\">{}</td>",
        points(score),
        points(max),
        compiled.0,
        compiled.1
    );
    for e in exercises {
        let verdict = student.verdict(&e.id);
        let (class_name, mark) = match verdict {
            Some(v) if v.passed => ("ok", "✓"),
            _ => ("no", "✗"),
        };
        let title = verdict.map_or("not graded".to_owned(), |v| v.explained());
        let _ = write!(
            html,
            "<td class=\"{class_name}\" title=\"{}\">{mark}</td>",
            escape(&title)
        );
    }
    let flags = match student.flags.len() {
        0 => String::new(),
        n => format!("<span class=\"flag\">⚑ {n}</span>"),
    };
    let _ = writeln!(
        html,
        "<td>{flags}</td><td>{:.0} s</td></tr>",
        student.seconds
    );
    html
}

/// A student's section: not graded, flags, warnings, notes, chapters.
fn section(class: &Class, student: &StudentResult, pictures: &[(String, String)]) -> String {
    let mut html = format!(
        "<section id=\"{}\"><h2>{}</h2>\n",
        escape(&student.slug),
        escape(&student.name)
    );
    if let Some(reason) = &student.refused {
        let _ = writeln!(html, "<p class=\"flag\">Not graded: {}</p>", escape(reason));
    }
    let lists = [
        (
            "flag",
            "Changed files that decide a verdict (graded on the reference's)",
            &student.flags,
        ),
        ("", "Warnings", &student.warnings),
        (
            "",
            "Other files changed (put back from the reference)",
            &student.notes,
        ),
    ];
    for (class_name, title, items) in lists.into_iter().filter(|(_, _, i)| !i.is_empty()) {
        let _ = write!(html, "<p class=\"{class_name}\">{title}:</p><ul>");
        for item in items {
            let _ = write!(html, "<li><code>{}</code></li>", escape(item));
        }
        html.push_str("</ul>\n");
    }
    for run in &student.chapters {
        let picture = pictures.iter().find(|(f, _)| *f == run.folder);
        html.push_str(&chapter(
            class,
            student,
            run,
            picture.map(|(_, p)| p.as_str()),
        ));
    }
    html + "</section>\n"
}

/// A chapter of a student's section: counts, trouble, exercises, pictures.
fn chapter(
    class: &Class,
    student: &StudentResult,
    run: &ChapterRun,
    reference: Option<&str>,
) -> String {
    let unfinished = match run.unfinished {
        0 => String::new(),
        n => format!(", {n} never finished"),
    };
    let mut html = format!(
        "<h3>{}: {} passed, {} failed{unfinished}</h3>\n",
        escape(&run.folder),
        run.passed,
        run.failed
    );
    if let Some(trouble) = run.trouble.as_ref().or(run.compile_error.as_ref()) {
        let _ = writeln!(html, "<p class=\"flag\">{}</p>", escape(trouble));
    }
    html.push_str("<ul>");
    for e in class
        .reference
        .tests
        .exercises
        .iter()
        .filter(|e| e.chapter == run.folder)
    {
        let verdict = student.verdict(&e.id);
        let text = match verdict {
            Some(v) if v.passed => format!("✓ {}", v.explained()),
            Some(v) => format!("✗ {}", v.explained()),
            None => "not graded".to_owned(),
        };
        let _ = write!(
            html,
            "<li><code>{}</code> {}</li>",
            escape(&e.id),
            escape(&text)
        );
    }
    html.push_str("</ul>\n");
    for picture in &run.pictures {
        if let Some(diff) = &picture.diff {
            let _ = writeln!(
                html,
                "<figure><img class=\"diff\" src=\"{0}\" alt=\"{1}\"><figcaption>{1}: \
                 reference | difference mask | theirs</figcaption></figure>",
                escape(diff),
                escape(&picture.name)
            );
        }
    }
    if let Some(reference) = reference {
        let caption = if !run.compiled {
            "reference (theirs does not compile)"
        } else if run.pictures.is_empty() && run.failed + run.unfinished == 0 {
            "reference: theirs match it"
        } else {
            "reference"
        };
        let _ = writeln!(
            html,
            "<figure><img class=\"ref\" src=\"{}\" alt=\"reference\"><figcaption>{caption}</figcaption></figure>",
            escape(reference)
        );
    }
    html
}
