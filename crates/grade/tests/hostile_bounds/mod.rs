//! The hostile class's tests of the bounds on what a student's runs may
//! write: beyond their build folder inside the sandbox (`/dev`), out of it
//! onto the teacher's disk (the probe kept for each chapter), and into the
//! class's outputs (messages and flags). The class is `hostile.rs`'s,
//! graded once.

use super::{flags, graded, row, score};

#[test]
fn a_probe_padded_past_any_honest_size_is_refused_and_never_kept() {
    let Some(padded) = row("n-padded") else {
        return;
    };
    // Kept, it would have earned its honest 3/3 and put its size on the
    // teacher's disk once per chapter graded.
    assert_eq!(score(padded), ("0", "3"), "{padded:?}");
    assert!(
        padded["why"].contains("more than the 64 MiB grading keeps"),
        "{padded:?}"
    );
}

#[test]
fn dev_and_dev_shm_take_no_more_than_their_bounds() {
    let Some(beyond) = row("o-beyond") else {
        return;
    };
    // Its `Ray::at` panics where a write beyond the bounds went through.
    assert_eq!(score(beyond), ("3", "3"), "{beyond:?}");
    assert_eq!(beyond["troubles"], "", "{beyond:?}");
}

#[test]
fn a_megabyte_panic_and_thousands_of_flags_leave_the_outputs_small() {
    let Some(graded) = graded() else { return };
    let verbose = &graded.rows["p-verbose"];
    assert_eq!(score(verbose), ("2", "3"), "ch01-at panics: {verbose:?}");
    let flags = flags(verbose);
    assert!(flags.len() <= 101, "{} flags", flags.len());
    let more = flags
        .last()
        .and_then(|f| f.strip_prefix("and ")?.strip_suffix(" more"));
    assert!(
        more.is_some_and(|n| n.parse::<usize>().is_ok_and(|n| n >= 1900)),
        "{:?}",
        flags.last()
    );
    for (column, cell) in verbose {
        assert!(cell.len() < 20_000, "{column}: {} bytes", cell.len());
    }
    let report = std::fs::read_to_string(graded.report.join("index.html")).unwrap();
    assert!(report.len() < 1 << 20, "the report: {} bytes", report.len());
}

#[test]
fn failure_pictures_leave_the_sandbox_only_up_to_a_chapters_bound() {
    let Some(graded) = graded() else { return };
    let pictures = &graded.rows["q-pictures"];
    assert_eq!(score(pictures), ("3", "3"), "{pictures:?}");
    let kept = graded.report.join("q-pictures/01-rays");
    let entries = std::fs::read_dir(&kept).unwrap().flatten();
    let bytes: u64 = entries.map(|e| e.metadata().unwrap().len()).sum();
    assert!(bytes <= 8 << 20, "{bytes} bytes of pictures kept");
    let flags = flags(pictures);
    assert!(
        flags
            .iter()
            .any(|f| f.contains("beyond the 8 MiB a chapter's may hold")),
        "{flags:?}"
    );
}

#[test]
fn sources_made_to_be_slow_to_scan_are_scanned_in_one_pass() {
    // Before, each of its three files took days of the grader's time, and
    // the class's grading never ended.
    let Some(slow) = row("r-slow-scan") else {
        return;
    };
    assert_eq!(score(slow), ("3", "3"), "{slow:?}");
    let flags = flags(slow);
    let first = "chapters/01-rays/src/slow1.rs:1: include! reaches outside its folder";
    assert!(flags.iter().any(|f| f.starts_with(first)), "{flags:?}");
}

#[test]
fn a_flood_of_made_up_failures_is_read_in_one_pass() {
    let Some(flood) = row("s-flood") else {
        return;
    };
    assert_eq!(score(flood), ("3", "3"), "{flood:?}");
    // Before, reading one of its test runs took half an hour; building and
    // testing chapter 1 takes a few minutes.
    let seconds: f64 = flood["seconds"].parse().unwrap();
    assert!(seconds < 900.0, "{seconds} s");
}
