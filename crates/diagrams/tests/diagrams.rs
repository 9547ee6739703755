//! The committed diagrams are what `cargo run -p diagrams` writes now, the
//! numbers they show are the numbers their chapters' texts state, and each
//! is shown in its chapter's README with alt text.
//!
//! What makes these tests fail, on purpose:
//! * a change to a chapter's maths or scene that changes a diagram (say the
//!   default scene's glass with ior 1.33: a new critical angle, new weights
//!   in the ray tree), until `cargo run -p diagrams` has written it anew;
//! * a diagram whose number the README does not state word for word (the
//!   same change: the README still says 41.81° and 0.912), or a README
//!   edited so that it no longer says what the picture shows;
//! * an SVG under `chapters/*/diagrams/` that the program does not write,
//!   or a diagram no README shows;
//! * a diagram without a title, a description or the light background, or
//!   with text smaller than 13 px.
//!
//! Each check returns the problems it finds, and the last tests feed it a
//! doctored diagram to show that it does find them.

use std::path::Path;

use diagrams::svg::{BACKGROUND, MIN_FONT, plain};
use diagrams::{Diagram, all, workspace_root};

/// The chapter's README.
fn readme(chapter: &str) -> String {
    let path = workspace_root()
        .join("chapters")
        .join(chapter)
        .join("README.md");
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

/// The chapter's text and its answers (`crates/workbook/answers/NN-name.md`,
/// which `workbook hint ID --level 4` shows after an attempt): a diagram's
/// worked numbers may be stated in either.
fn chapter_text(chapter: &str) -> String {
    let answers = workspace_root()
        .join("crates/workbook/answers")
        .join(format!("{chapter}.md"));
    readme(chapter) + "\n" + &std::fs::read_to_string(answers).unwrap_or_default()
}

/// The README's prose: without its images (whose alt text describes the
/// diagrams, so it would always agree with them), and with every run of
/// white space made one space (the text wraps its lines where a diagram
/// does not).
fn prose(readme: &str) -> String {
    readme
        .lines()
        .filter(|line| !line.trim_start().starts_with("!["))
        .flat_map(str::split_whitespace)
        .collect::<Vec<_>>()
        .join(" ")
}

/// The text an SVG shows: its tags taken out, its entities put back.
fn shown_text(svg: &str) -> String {
    let mut text = String::new();
    let mut in_tag = false;
    for c in svg.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => text.push(c),
            _ => {}
        }
    }
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// Facts that the picture does not show or the README does not state.
fn unstated_facts(diagram: &Diagram, readme: &str) -> Vec<String> {
    let shown = shown_text(&diagram.svg);
    let mut problems = Vec::new();
    for fact in &diagram.facts {
        if !shown.contains(&plain(fact)) {
            problems.push(format!(
                "{}: the picture does not show {fact:?}",
                diagram.name
            ));
        }
        if !readme.contains(fact.as_str()) {
            problems.push(format!(
                "{}: the picture shows {fact:?}, which chapters/{}/README.md (nor its answers) \
                 does not state",
                diagram.name, diagram.chapter
            ));
        }
    }
    problems
}

/// Where the README does not show the diagram, or shows it without alt text.
fn missing_reference(diagram: &Diagram, readme: &str) -> Option<String> {
    let link = diagram.link();
    let shown_with_alt = readme.match_indices(&link).any(|(at, _)| {
        let before = &readme[..at];
        before.rfind("![").is_some_and(|open| {
            let alt = &before[open + 2..];
            !alt.trim().is_empty() && !alt.contains("](")
        })
    });
    (!shown_with_alt).then(|| {
        format!(
            "chapters/{}/README.md does not show {} as ![alt text]{link}",
            diagram.chapter, diagram.name
        )
    })
}

/// What a diagram lacks to be readable on any page.
fn unreadable(diagram: &Diagram) -> Vec<String> {
    let svg = &diagram.svg;
    let mut problems = Vec::new();
    for (needed, what) in [
        ("<title>", "a <title>"),
        ("<desc>", "a <desc>"),
        ("font-family=\"sans-serif\"", "a sans-serif font"),
        ("viewBox=\"0 0 600 ", "a viewBox 600 wide"),
    ] {
        if !svg.contains(needed) {
            problems.push(format!("{}: no {what}", diagram.name));
        }
    }
    let background = "<rect x=\"0\" y=\"0\" width=\"600\" height=";
    let opaque = svg
        .lines()
        .find(|line| line.starts_with("<rect"))
        .is_some_and(|line| line.starts_with(background) && line.contains(BACKGROUND));
    if !opaque {
        problems.push(format!(
            "{}: its first shape is not the opaque background",
            diagram.name
        ));
    }
    for size in svg.split("font-size=\"").skip(1) {
        let value: f64 = size[..size.find('"').unwrap_or(0)].parse().unwrap_or(0.0);
        if value < MIN_FONT {
            problems.push(format!(
                "{}: text of {value} px, under {MIN_FONT}",
                diagram.name
            ));
        }
    }
    problems
}

#[test]
fn there_are_at_least_twelve_diagrams() {
    let diagrams = all();
    assert!(diagrams.len() >= 12, "only {} diagrams", diagrams.len());
    let mut names: Vec<_> = diagrams.iter().map(|d| d.path()).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), diagrams.len(), "two diagrams share a file");
}

#[test]
fn the_committed_files_are_what_the_program_writes() {
    let root = workspace_root();
    let stale: Vec<String> = all()
        .iter()
        .filter(|d| std::fs::read_to_string(root.join(d.path())).ok().as_deref() != Some(&d.svg))
        .map(|d| d.path().display().to_string())
        .collect();
    assert!(
        stale.is_empty(),
        "these diagrams are missing or differ from what the chapters' maths draws now: {stale:?}; \
         run `cargo run -p diagrams` and look at them"
    );
}

#[test]
fn every_svg_in_a_diagrams_folder_is_written_by_the_program() {
    let root = workspace_root();
    let written: Vec<_> = all().iter().map(|d| root.join(d.path())).collect();
    let mut strays = Vec::new();
    for chapter in std::fs::read_dir(root.join("chapters")).expect("the chapters") {
        let folder = chapter.expect("a chapter").path().join("diagrams");
        let Ok(files) = std::fs::read_dir(&folder) else {
            continue;
        };
        for file in files {
            let path = file.expect("a file").path();
            let is_svg = path.extension().is_some_and(|e| e == "svg");
            if is_svg && !written.iter().any(|w| same_file(w, &path)) {
                strays.push(path.display().to_string());
            }
        }
    }
    assert!(strays.is_empty(), "no diagram writes these: {strays:?}");
}

fn same_file(a: &Path, b: &Path) -> bool {
    a.canonicalize().ok() == b.canonicalize().ok()
}

#[test]
fn the_numbers_a_diagram_shows_are_the_ones_its_chapter_states() {
    let problems: Vec<String> = all()
        .iter()
        .flat_map(|d| unstated_facts(d, &prose(&chapter_text(d.chapter))))
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_diagrams_that_must_quote_their_chapter_do() {
    // The numbers the issue names: these diagrams must carry them as facts,
    // so that the test above compares them with the text.
    let diagrams = all();
    let facts = |name: &str| {
        diagrams
            .iter()
            .find(|d| d.name == name)
            .map(|d| d.facts.join(" | "))
            .unwrap_or_else(|| panic!("no diagram {name}"))
    };
    assert!(
        facts("critical-angle").contains("41.81°"),
        "{}",
        facts("critical-angle")
    );
    assert!(facts("pixel-to-plane").contains("(x + ½, y + ½)"));
    assert!(facts("pixel-to-plane").contains("(0.5, 0.5)"));
    assert!(facts("camera-frame").contains("(−1.5, 0.5, −1)"));
    assert!(facts("ray-tree").contains("0.912"), "{}", facts("ray-tree"));
    assert!(facts("ray-tree").contains("0.058"), "{}", facts("ray-tree"));
    assert!(facts("sphere-roots").contains("enters at t = 1"));
    assert!(facts("spot-cone").contains("≈ 0.580"));
}

#[test]
fn every_diagram_is_shown_in_its_chapter_with_alt_text() {
    let problems: Vec<String> = all()
        .iter()
        .filter_map(|d| missing_reference(d, &readme(d.chapter)))
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn every_diagram_is_readable_on_a_light_or_a_dark_page() {
    let problems: Vec<String> = all().iter().flat_map(unreadable).collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// A copy of the critical-angle diagram with its number changed, as if the
/// maths had moved and the text had not.
fn doctored() -> Diagram {
    let mut diagram = all()
        .into_iter()
        .find(|d| d.name == "critical-angle")
        .expect("the critical angle diagram");
    diagram.svg = diagram
        .svg
        .replace("41.81°", "48.75°")
        .replace("font-size=\"13\"", "font-size=\"9\"");
    diagram.facts = diagram
        .facts
        .iter()
        .map(|f| f.replace("41.81°", "48.75°"))
        .collect();
    diagram.name = "doctored";
    diagram
}

#[test]
fn a_number_the_text_does_not_state_is_caught() {
    let diagram = doctored();
    let problems = unstated_facts(&diagram, &prose(&readme(diagram.chapter)));
    assert!(
        problems
            .iter()
            .any(|p| p.contains("48.75°") && p.contains("does not state")),
        "{problems:?}"
    );
    assert!(missing_reference(&diagram, &readme(diagram.chapter)).is_some());
    assert!(unreadable(&diagram).iter().any(|p| p.contains("9 px")));
}

#[test]
fn a_number_the_picture_does_not_show_is_caught() {
    let mut diagram = doctored();
    diagram.facts.push("θ_c = 41.81°".to_owned());
    let problems = unstated_facts(&diagram, "θ_c = 41.81°");
    assert!(
        problems
            .iter()
            .any(|p| p.contains("does not show \"θ_c = 41.81°\"")),
        "{problems:?}"
    );
}
