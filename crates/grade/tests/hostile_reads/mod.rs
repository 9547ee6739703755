//! The hostile class's tests of the probe's channel, of what grading reads
//! of a student's folders, of names that forge output, of code that runs
//! before `main`, and of the judging (printed passes, a lookup table, a
//! stored picture). The class is `hostile.rs`'s, graded once.

use std::path::Path;

use super::{NEWLINE, Row, flags, graded, gradescope, row, score};

#[test]
fn a_probe_that_swaps_its_folders_for_links_gets_nothing_through_them() {
    let Some(swapper) = row("d-swapper") else {
        return;
    };
    assert_eq!(score(swapper), ("0", "3"), "{swapper:?}");
    let flags = flags(swapper);
    let flagged = |what: &str| flags.iter().any(|f| f.contains(what));
    assert!(flagged("symlink at target/probe"), "{flags:?}");
    assert!(
        flagged("target/snapshot-failures/01-rays: a symlink"),
        "{flags:?}"
    );
    assert!(
        flagged("ch01-at: its probe's record is not one the probe writes"),
        "{flags:?}"
    );
    // The teacher's pictures it led to are unchanged (`nothing_outside…`)
    // and none of them reached the report (`a_symlink_or_a_fifo…`).
}

#[test]
fn a_record_that_is_a_link_is_flagged_never_quoted_or_waited_for() {
    let Some(graded) = graded() else { return };
    for name in ["e-record-secret", "f-record-stdin", "g-record-zero"] {
        let row = &graded.rows[name];
        assert_eq!(score(row), ("3", "3"), "{row:?}");
        let flags = flags(row);
        assert!(
            flags
                .iter()
                .any(|f| f.contains("the handout's record") && f.contains("a symlink")),
            "{name}: {flags:?}"
        );
    }
    let flags = flags(&graded.rows["e-record-secret"]);
    assert!(
        flags
            .iter()
            .any(|f| f.contains("oversized file chapters/01-rays/src/big.bin")),
        "{flags:?}"
    );
    let flags = self::flags(&graded.rows["f-record-stdin"]);
    assert!(
        flags
            .iter()
            .any(|f| f.contains("a FIFO at chapters/01-rays/src/pipe.rs")),
        "{flags:?}"
    );
    assert!(
        !graded.csv.contains(&graded.secret),
        "the gradebook quotes it"
    );
    let json = gradescope("e-record-secret").unwrap();
    assert!(
        !json.contains(&graded.secret),
        "its Gradescope output quotes it"
    );
}

#[test]
fn nothing_of_the_probe_reaches_what_a_student_sees() {
    let Some(graded) = graded() else { return };
    let panicker = &graded.rows["h-panicker"];
    assert_eq!(score(panicker), ("2", "3"), "{panicker:?}");
    let out = graded.report.parent().unwrap();
    let seed = std::fs::read_to_string(out.join("seed.txt")).unwrap();
    for entry in std::fs::read_dir(out.join("gradescope")).unwrap() {
        let json = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        for private in [
            seed.trim(),
            "--seed",
            "raybook-probes",
            "--out-fd",
            "arguments",
        ] {
            assert!(!json.contains(private), "{private} in {json}");
        }
    }
    let json = gradescope("h-panicker").unwrap();
    assert!(
        json.contains("your code panicked when the grader called it"),
        "{json}"
    );
    let flags = flags(panicker);
    assert!(
        flags
            .iter()
            .any(|f| f.contains("a control character in its name")),
        "{flags:?}"
    );
}

#[test]
fn a_name_with_a_line_break_or_escapes_forges_no_row_or_screen() {
    let Some(graded) = graded() else { return };
    assert!(
        !graded.rows.contains_key("zz-fake"),
        "{:?}",
        graded.rows.keys()
    );
    let cleaned = NEWLINE.replace('\n', "?");
    assert_eq!(score(&graded.rows[&cleaned]), ("0", "3"));
    for text in [&graded.printed, &graded.csv] {
        assert!(!text.lines().any(|l| l.starts_with("zz-fake")), "{text}");
        assert!(!text.contains('\u{1b}'), "an escape reached the output");
    }
}

#[test]
fn code_before_main_or_a_second_main_earns_nothing_and_stops_no_one() {
    let Some(graded) = graded() else { return };
    let early = &graded.rows["j-early"];
    assert_eq!(score(early), ("0", "3"), "the forged values: {early:?}");
    let forged = flags(early);
    assert!(
        forged
            .iter()
            .any(|f| f.contains("is not one the probe writes")),
        "{forged:?}"
    );
    let settings = &graded.rows["k-settings"];
    assert_eq!(
        (score(settings), settings["compiled"].as_str()),
        (("0", "3"), "no"),
        "{settings:?}"
    );
    let flags = flags(settings);
    assert!(
        flags.iter().any(|f| f.contains("edited Cargo.toml")),
        "{flags:?}"
    );
    assert!(!Path::new("/tmp/raybook-evil-macro-ran").exists());
    assert_eq!(score(&graded.rows["zz-honest"]), ("3", "3"));
}

/// The points of chapter 1's exercises in a row.
fn points(row: &Row) -> Vec<&str> {
    ["ch01-at", "ch01-frame", "ch01-ray-through"]
        .iter()
        .map(|id| row[*id].as_str())
        .collect()
}

#[test]
fn printed_passes_earn_nothing() {
    let Some(printer) = row("l-printer") else {
        return;
    };
    // Its tests "passed" (a grader reading them gave it every point); its
    // probes wrote no values.
    assert_eq!(points(printer), ["0", "0", "0"], "{printer:?}");
    assert_ne!(printer["01-rays passed"], "0", "{printer:?}");
    assert!(
        printer["why"].contains("ch01-frame: no values"),
        "{printer:?}"
    );
}

#[test]
fn a_lookup_table_and_a_stored_picture_earn_only_the_honest_points() {
    let Some(forger) = row("m-forger") else {
        return;
    };
    assert_eq!(points(forger), ["0", "0", "1"], "{forger:?}");
    assert!(
        forger["why"].contains("ch01-at: disagrees on drawn input"),
        "{forger:?}"
    );
    // Where the sandbox let it overwrite the picture, that is flagged.
    let json = gradescope("m-forger").unwrap();
    let overwrote = !json.contains("wrote=false");
    assert!(
        !overwrote
            || forger["flags"]
                .contains("changed during the run: snapshots/01-rays/default.snap.png"),
        "{forger:?}"
    );
}
