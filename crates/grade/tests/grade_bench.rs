//! The class benchmark of `grade` (issue 29): 20 handouts in mixed
//! states, and the seconds per student once the reference is prepared and
//! a first student graded. A measurement, not a check: it asserts nothing
//! about the time and runs only when asked. Run it with
//!
//! ```text
//! RAYBOOK_GRADE_BENCH=1 cargo test -p grade --test grade_bench -- --nocapture
//! ```
//!
//! `RAYBOOK_BENCH_CHAPTERS` chooses the chapters graded (default `1-3`;
//! `1-7` for the whole workbook).

mod grade_support;

use std::path::{Path, PathBuf};
use std::time::Instant;

use grade_support::{handout, snapshot_reference};

#[test]
fn twenty_handouts_in_mixed_states() {
    if std::env::var_os("RAYBOOK_GRADE_BENCH").is_none() {
        eprintln!("grade_bench: a benchmark of minutes; set RAYBOOK_GRADE_BENCH=1 to run it");
        return;
    }
    let chapters = std::env::var("RAYBOOK_BENCH_CHAPTERS").unwrap_or_else(|_| "1-3".into());
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("grade-bench");
    let _ = std::fs::remove_dir_all(&base);
    let reference = snapshot_reference(&base.join("reference"));
    let (first, class) = (base.join("first"), base.join("class"));
    handout(&reference, &first.join("warm-up"), 3);
    let states = mixed_states(&reference, &class);
    let out = base.join("out");

    let start = Instant::now();
    let warm_up = grade(&reference, &out, &first, &chapters);
    let prepared = start.elapsed();
    let start = Instant::now();
    let text = grade(&reference, &out, &class, &chapters);
    let took = start.elapsed();
    eprintln!("{warm_up}\n{text}");
    eprintln!(
        "class benchmark, chapters {chapters}: reference and a first student {:.0} s; \
         then {} students in {:.0} s: {:.1} s per student ({} cores)\nstates: {states:?}",
        prepared.as_secs_f64(),
        states.len(),
        took.as_secs_f64(),
        took.as_secs_f64() / states.len() as f64,
        std::thread::available_parallelism().map_or(1, |n| n.get()),
    );
}

/// Writes 20 handouts in `class`: untouched, chapters solved up to 1, 2 or
/// all, a compile error, a classic mistake, an endless loop. Their states.
fn mixed_states(reference: &Path, class: &Path) -> Vec<String> {
    let states = [
        (0, ""),
        (0, ""),
        (0, ""),
        (1, ""),
        (1, ""),
        (1, ""),
        (1, ""),
        (2, ""),
        (2, ""),
        (2, ""),
        (2, ""),
        (7, ""),
        (7, ""),
        (7, ""),
        (7, ""),
        (7, "compile error"),
        (7, "compile error"),
        (7, "mistake"),
        (7, "mistake"),
        (7, "endless loop"),
    ];
    let mut names = Vec::new();
    for (i, (solved, edit)) in states.into_iter().enumerate() {
        let dir = class.join(format!("student-{i:02}"));
        handout(reference, &dir, solved);
        let lib = dir.join("chapters/01-rays/src/lib.rs");
        let source = std::fs::read_to_string(&lib).unwrap();
        let body = match edit {
            "compile error" => Some("        let _: u32 = \"not a number\";\n        todo!()"),
            "mistake" => Some("        self.origin - self.direction * t"),
            "endless loop" => Some("        loop {}"),
            _ => None,
        };
        if let Some(body) = body {
            let edited = workbook::regions::replace_bodies(&source, |r| {
                (r.id == "ch01-at").then(|| body.to_owned())
            });
            std::fs::write(&lib, edited.unwrap()).unwrap();
        }
        names.push(format!("solved through {solved} {edit}").trim().to_owned());
    }
    names
}

/// `grade CLASS` with the chapters given; what it printed.
fn grade(reference: &Path, out: &Path, class: &Path, chapters: &str) -> String {
    grade_support::grade_chapters(reference, out, &[class.as_os_str()], chapters)
}
