//! `grade` on a fixture class (issue 29): seven handouts made in the
//! test from a snapshot of the reference with `workbook handout` and small
//! edits, and five folders that are not handouts. (The snapshot keeps the
//! test's reference still while others edit the workspace.)
//!
//! Points come from the values each exercise's code computed on inputs
//! drawn from a seed (the probe; `judging/rule.rs` states the rule), so each
//! student gets exactly what their honest work earns:
//!
//! | folder          | what it is                                   | expected row                         |
//! |-----------------|----------------------------------------------|--------------------------------------|
//! | `complete`      | chapters 1–3 written                         | every exercise, no flag              |
//! | `half`          | chapter 1 written, ch02-plane too            | chapter 1's and ch02-plane, no more  |
//! | `broken`        | all written, chapter 2 does not compile      | chapter 1's; 2 and 3 do not compile  |
//! | `endless`       | all written, chapter 3's lambert loops       | all but ch03-lambert (timed out)     |
//! | `cheater`       | chapter 1 written, a chapter 2 test gutted   | chapter 1's only, flagged            |
//! | `picture`       | all written, a reference picture replaced    | every exercise, flagged              |
//! | `mistaken`      | all written, a classic mistake in lambert    | all but ch03-lambert, its diff shown |
//!
//! `half` also holds a symlink in its sources and code that tries to write
//! outside its copy. And `empty/`, `notes.txt`, `outside` (a symlink out
//! of the class), `other-version/`, `not-a-handout/`: each not graded,
//! with its reason.
//! Every student folder must be byte for byte as it was.
//!
//! It takes minutes (it builds seven copies of chapters 1–3), so it runs
//! only when asked, with `RAYBOOK_GRADE_FIXTURE=1`; CI runs it as its own
//! step (a plain `cargo test` says it was not asked and does nothing):
//!
//! ```text
//! RAYBOOK_GRADE_FIXTURE=1 cargo test -p grade --test grade_fixture -- --nocapture
//! ```

mod grade_support;

use std::path::{Path, PathBuf};
use std::time::Instant;

use grade_support::{Row, class_fingerprint, grade, handout, read_csv, snapshot_reference};

/// The exercises of chapters 1 to 3.
const CH01: [&str; 3] = ["ch01-at", "ch01-frame", "ch01-ray-through"];
const CH02: [&str; 5] = [
    "ch02-closest",
    "ch02-plane",
    "ch02-sphere",
    "ch02-nearest",
    "ch02-triangle",
];
const CH03: [&str; 3] = ["ch03-lambert", "ch03-light-loop", "ch03-spot"];

#[test]
fn a_fixture_class_gets_the_right_rows_and_every_folder_is_left_as_it_was() {
    if std::env::var_os("RAYBOOK_GRADE_FIXTURE").is_none() {
        eprintln!(
            "grade_fixture: set RAYBOOK_GRADE_FIXTURE=1 to grade the fixture class (minutes)"
        );
        return;
    }
    let start = Instant::now();
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("grade-fixture");
    let _ = std::fs::remove_dir_all(&base);
    let reference = snapshot_reference(&base.join("reference"));
    let class = base.join("class");
    make_class(&reference, &class);
    let before = class_fingerprint(&class);
    let out = base.join("out");

    let first = grade(&reference, &out, &[class.as_os_str()]);
    assert_eq!(
        class_fingerprint(&class),
        before,
        "a student folder changed"
    );
    eprintln!("first run: {:.0?}\n{first}", start.elapsed());
    // Where the system allows namespaces, grading says nothing of them and
    // a student's code cannot write outside its copy.
    if !first.contains("note: ") {
        assert!(
            !base.join("escaped").exists(),
            "a student's test wrote outside its copy"
        );
    }
    let gradebook = std::fs::read_to_string(out.join("grades.csv")).unwrap();
    eprintln!("grades.csv:\n{gradebook}");
    let rows = read_csv(&out.join("grades.csv"));
    check_rows(&rows);
    // The teacher keeps the seed the inputs were drawn from.
    let seed = std::fs::read_to_string(out.join("seed.txt")).unwrap();
    assert_eq!(rows["complete"]["seed"], seed.trim());
    check_outputs(&out, &rows);

    // A rerun grades no one; after an edit, only the student who made it.
    let again = grade(&reference, &out, &[class.as_os_str()]);
    assert!(
        again.contains("students: 0 graded in") && again.contains("7 unchanged"),
        "{again}"
    );
    assert_eq!(
        read_csv(&out.join("grades.csv")),
        rows,
        "same rows from the cache"
    );
    let lib = class.join("broken/chapters/02-hits/src/plane.rs");
    let fixed = std::fs::read_to_string(&lib).unwrap().replace(BROKEN, "");
    std::fs::write(&lib, fixed).unwrap();
    let third = grade(&reference, &out, &[class.as_os_str()]);
    assert!(
        third.contains("students: 1 graded in") && third.contains("6 unchanged"),
        "{third}"
    );
    let broken = &read_csv(&out.join("grades.csv"))["broken"];
    assert!(
        passes(broken, &CH02) && broken["compiled"] == "yes",
        "{broken:?}"
    );

    // Gradescope's way: one submission, its results.json (in an output
    // folder of its own, which leaves the class's report as it is).
    let results = base.join("results.json");
    let one = class.join("complete");
    grade(
        &reference,
        &base.join("one"),
        &[
            "--one".as_ref(),
            one.as_os_str(),
            "--gradescope".as_ref(),
            results.as_os_str(),
        ],
    );
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&results).unwrap()).unwrap();
    assert_eq!(json["score"], 11.0, "{json}");
    eprintln!("whole test: {:.0?}", start.elapsed());
}

/// What `broken` adds to chapter 2: a type error.
const BROKEN: &str = "\npub fn broken() -> u32 {\n    \"not a number\"\n}\n";

/// Writes the fixture class from the reference snapshot.
fn make_class(reference: &Path, class: &Path) {
    std::fs::create_dir_all(class).unwrap();
    let student = |name: &str, solved: u32| {
        let dir = class.join(name);
        handout(reference, &dir, solved);
        dir
    };
    student("complete", 3);

    let half = student("half", 1);
    let plane = "chapters/02-hits/src/plane.rs";
    std::fs::copy(reference.join(plane), half.join(plane)).unwrap();
    // A symlink among their sources, to a file outside: never followed.
    std::os::unix::fs::symlink("/etc/hostname", half.join("chapters/01-rays/src/secret.rs"))
        .unwrap();
    // Their code tries to write outside its copy (it cannot, confined).
    let lib = half.join("chapters/01-rays/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    let escape = class.parent().unwrap().join("escaped");
    let writes = workbook::regions::replace_bodies(&source, |r| {
        (r.id == "ch01-at").then(|| {
            format!(
                "        static ONCE: std::sync::Once = std::sync::Once::new();\n        \
                 ONCE.call_once(|| {{ let _ = std::fs::write({escape:?}, \"out\"); }});\n        \
                 self.origin + t * self.direction"
            )
        })
    });
    std::fs::write(&lib, writes.unwrap()).unwrap();

    let broken = student("broken", 3);
    append(&broken.join(plane), BROKEN);

    let endless = student("endless", 3);
    let lib = endless.join("chapters/03-lambert/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    let looping = workbook::regions::replace_bodies(&source, |r| {
        (r.id == "ch03-lambert").then(|| format!("{}loop {{}}", r.indent))
    });
    std::fs::write(&lib, looping.unwrap()).unwrap();

    let cheater = student("cheater", 1);
    let tests = cheater.join("chapters/02-hits/tests/chapter02/main.rs");
    std::fs::write(tests, "#[test]\nfn everything_passes() {}\n").unwrap();

    let picture = student("picture", 3);
    std::fs::copy(
        reference.join("snapshots/03-lambert/default.snap.png"),
        picture.join("snapshots/01-rays/default.snap.png"),
    )
    .unwrap();

    let mistaken = student("mistaken", 3);
    let files = workbook::handout::check::mistakes_files(reference).unwrap();
    let mistakes = files.iter().flat_map(|(_, f)| &f.mistake);
    let albedo = mistakes
        .into_iter()
        .find(|m| m.what == "the albedo left out");
    let albedo = albedo.expect("chapter 3's mistakes.toml: the albedo left out");
    let lib = mistaken.join("chapters/03-lambert/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    let mistake = workbook::regions::replace_bodies(&source, |r| {
        (r.id == albedo.exercise).then(|| albedo.body.clone())
    });
    std::fs::write(&lib, mistake.unwrap()).unwrap();

    bad_inputs(reference, class);
}

/// The folders that are not handouts to grade.
fn bad_inputs(reference: &Path, class: &Path) {
    std::fs::create_dir(class.join("empty")).unwrap();
    std::fs::write(class.join("notes.txt"), "grade them kindly\n").unwrap();
    std::os::unix::fs::symlink(reference, class.join("outside")).unwrap();
    let other = class.join("other-version");
    std::fs::create_dir_all(other.join("chapters")).unwrap();
    for file in ["Cargo.toml", "chapters/chapters.toml"] {
        std::fs::copy(reference.join(file), other.join(file)).unwrap();
    }
    let record = "version = \"0.0.9\"\ncommit = \"0123456789abcdef\"\n";
    std::fs::write(other.join(".raybook-handout.toml"), record).unwrap();
    std::fs::create_dir(class.join("not-a-handout")).unwrap();
    std::fs::write(class.join("not-a-handout/essay.md"), "# My ray tracer\n").unwrap();
}

fn append(file: &Path, text: &str) {
    let mut source = std::fs::read_to_string(file).unwrap();
    source.push_str(text);
    std::fs::write(file, source).unwrap();
}

/// Does the row give each of `ids` its point?
fn passes(row: &Row, ids: &[&str]) -> bool {
    ids.iter().all(|id| row[*id] == "1")
}

/// Does the row give none of `ids` a point?
fn fails(row: &Row, ids: &[&str]) -> bool {
    ids.iter().all(|id| row[*id] == "0")
}

/// Each student's row says what the module's table says.
fn check_rows(rows: &std::collections::BTreeMap<String, Row>) {
    let row = |name: &str| &rows[name];
    let all: Vec<&str> = CH01.iter().chain(&CH02).chain(&CH03).copied().collect();
    for name in ["complete", "picture"] {
        let r = row(name);
        assert!(
            passes(r, &all) && r["score"] == "11" && r["compiled"] == "yes",
            "{r:?}"
        );
    }
    assert_eq!(
        row("complete")["flags"],
        "",
        "a handout as made has no flag"
    );
    assert!(row("picture")["flags"].contains("edited snapshots/01-rays/default.snap.png"));

    // Its own plane earns its point: exercises are judged one by one.
    let half = row("half");
    assert!(passes(half, &CH01) && fails(half, &CH03), "{half:?}");
    assert!(
        passes(half, &["ch02-plane"]) && fails(half, &CH02[2..]),
        "{half:?}"
    );
    assert_eq!(
        (half["score"].as_str(), half["compiled"].as_str()),
        ("4", "yes")
    );

    let broken = row("broken");
    assert!(passes(broken, &CH01) && fails(broken, &CH02) && fails(broken, &CH03));
    assert_eq!(broken["compiled"], "no");
    assert!(
        broken["troubles"].contains("02-hits: does not compile"),
        "{broken:?}"
    );

    // Each exercise is probed in a run of its own: the endless lambert
    // costs only itself.
    let endless = row("endless");
    assert!(
        passes(endless, &CH01) && passes(endless, &CH02) && passes(endless, &CH03[1..]),
        "{endless:?}"
    );
    assert_eq!(endless["ch03-lambert"], "0");
    assert!(endless["why"].contains("ch03-lambert: no values: its probe timed out"));
    assert!(
        endless["flags"].contains("03-lambert: its tests never finished"),
        "the teacher is told: {endless:?}"
    );
    assert!(
        endless["troubles"].contains("03-lambert: the tests timed out"),
        "{endless:?}"
    );

    // A mistake costs only its own exercise: the chapter's seeded scenes
    // differ, but that is explained by lambert's values, which disagree.
    let mistaken = row("mistaken");
    assert!(
        passes(mistaken, &CH01) && passes(mistaken, &CH02) && passes(mistaken, &CH03[1..]),
        "{mistaken:?}"
    );
    assert_eq!(mistaken["ch03-lambert"], "0");
    assert!(
        mistaken["why"].contains("ch03-lambert: disagrees on drawn input"),
        "{mistaken:?}"
    );

    let cheater = row("cheater");
    assert!(passes(cheater, &CH01) && fails(cheater, &CH02) && fails(cheater, &CH03));
    assert_eq!(cheater["score"], "3", "{cheater:?}");
    assert!(
        cheater["flags"].contains("edited chapters/02-hits/tests/chapter02/main.rs"),
        "{cheater:?}"
    );

    let refused = [
        ("empty", "an empty folder"),
        ("notes.txt", "a file, not a folder"),
        ("outside", "a symlink leading outside the class folder"),
        ("other-version", "a handout of raybook 0.0.9"),
        ("not-a-handout", "not a raybook handout"),
    ];
    for (name, reason) in refused {
        let status = &row(name)["status"];
        assert!(
            status.starts_with("not graded: ") && status.contains(reason),
            "{name}: {status}"
        );
    }
    for r in rows.values() {
        assert!(r["reference"].starts_with("0.1.0 @ "), "{r:?}");
    }
}

/// The other outputs: a Gradescope results.json per student, JUnit XML,
/// the HTML report with every picture it shows.
fn check_outputs(out: &Path, rows: &std::collections::BTreeMap<String, Row>) {
    let json = std::fs::read(out.join("gradescope/endless.json")).unwrap();
    let json: serde_json::Value = serde_json::from_slice(&json).unwrap();
    let tests = json["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 11);
    let lambert = tests
        .iter()
        .find(|t| t["name"].as_str().unwrap().starts_with("ch03-lambert"));
    let lambert = lambert.unwrap();
    assert_eq!(
        (lambert["score"].as_f64(), lambert["max_score"].as_f64()),
        (Some(0.0), Some(1.0))
    );
    assert!(
        lambert["output"].as_str().unwrap().contains("timed out"),
        "{lambert}"
    );
    assert!(
        json["output"]
            .as_str()
            .unwrap()
            .contains("raybook 0.1.0 @ ")
    );

    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert_eq!(junit.matches("<testsuite ").count(), rows.len());
    assert!(junit.contains("<property name=\"reference\" value=\"0.1.0 @ "));

    let html = std::fs::read_to_string(out.join("report/index.html")).unwrap();
    let mut pictures = 0;
    for src in html
        .split("src=\"")
        .skip(1)
        .map(|s| &s[..s.find('"').unwrap()])
    {
        assert!(
            out.join("report").join(src).is_file(),
            "the report shows a missing {src}"
        );
        pictures += 1;
    }
    assert!(
        html.contains("mistaken/03-lambert/default.diff.png"),
        "the diff is shown"
    );
    assert!(pictures > 10, "{pictures} pictures");
}
