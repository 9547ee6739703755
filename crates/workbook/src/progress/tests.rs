//! Progress end to end, in a workspace of empty chapters, with a `cargo`
//! that logs when each chapter's tests start and end and passes or fails
//! them as told.

use std::fs;
use std::path::PathBuf;
use std::time::SystemTime;

use super::*;

#[test]
fn the_edited_chapter_is_tested_first_then_the_others_in_order() {
    let all: Vec<usize> = (0..8).collect();
    assert_eq!(run_order(&all, Some(2))[..4], [2, 0, 1, 3]);
    assert_eq!(run_order(&all, None), all);
    // Chapters 1 and 2 unchanged: shown, not tested.
    assert_eq!(run_order(&all[2..], Some(4)), [4, 2, 3, 5, 6, 7]);
    assert_eq!(run_order(&all[5..], Some(2)), [5, 6, 7]);
}

/// A workspace of the chapters' folders, and beside it a `cargo` that
/// writes `start PACKAGE` and `end PACKAGE` to `log` and fails a package
/// for which a file `fail-PACKAGE` exists. A run lasts 0.4 s, so that two
/// chapters run at a time overlap in the log even on a loaded machine.
struct Fake {
    dir: tempfile::TempDir,
}

impl Fake {
    fn new() -> Fake {
        let dir = tempfile::tempdir().unwrap();
        let fake = Fake { dir };
        for chapter in chapters::all() {
            fake.edit(chapter.folder.as_str());
        }
        fs::write(fake.root().join("Cargo.toml"), "[workspace]\n").unwrap();
        human_pause();
        let cargo = fake.dir.path().join("cargo");
        fs::write(
            &cargo,
            "#!/bin/sh\n\
             # cargo test -p PACKAGE --color never\n\
             here=$(dirname \"$0\")\n\
             echo \"start $3\" >> \"$here/log\"\n\
             sleep 0.4\n\
             echo \"end $3\" >> \"$here/log\"\n\
             if [ -e \"$here/fail-$3\" ]; then\n\
               echo 'test it_works ... FAILED'\n\
               echo 'test result: FAILED. 2 passed; 1 failed; 0 ignored'\n\
               exit 101\n\
             fi\n\
             echo 'test result: ok. 3 passed; 0 failed; 0 ignored'\n",
        )
        .unwrap();
        use std::os::unix::fs::PermissionsExt;
        fs::set_permissions(&cargo, fs::Permissions::from_mode(0o755)).unwrap();
        fake
    }

    fn root(&self) -> PathBuf {
        self.dir.path().join("workspace")
    }

    /// Writes the chapter's source anew.
    fn edit(&self, folder: &str) {
        let file = self.root().join("chapters").join(folder).join("src/lib.rs");
        fs::create_dir_all(file.parent().unwrap()).unwrap();
        fs::write(file, format!("// {:?}\n", SystemTime::now())).unwrap();
        human_pause();
    }

    fn fail(&self, package: &str) {
        fs::write(self.dir.path().join(format!("fail-{package}")), "").unwrap();
    }

    /// Runs progress; true if every chapter run passed. Returns what the
    /// fake cargo logged during the run.
    fn progress(&self) -> (bool, Vec<String>) {
        let log = self.dir.path().join("log");
        let _ = fs::remove_file(&log);
        let cargo = self.dir.path().join("cargo");
        let args = ProgressArgs::default();
        let passed = progress_in(&self.root(), cargo.as_os_str(), &args, None).unwrap();
        let log = fs::read_to_string(log).unwrap_or_default();
        (passed, log.lines().map(str::to_owned).collect())
    }
}

/// The time between a save and the next run of progress that no person
/// beats: an input saved within `cache::CLOCK_MARGIN` of a run's start
/// counts as saved after it (and the test would see it tested again).
fn human_pause() {
    std::thread::sleep(std::time::Duration::from_millis(30));
}

/// The chapters started, by number (two started at once may log in
/// either order).
fn starts(log: &[String]) -> Vec<&str> {
    let started = log.iter().filter_map(|l| l.strip_prefix("start ch"));
    let mut numbers: Vec<&str> = started.map(|p| &p[..2]).collect();
    numbers.sort();
    numbers
}

/// Did the chapter `a`'s tests end before `b`'s started?
fn before(log: &[String], a: &str, b: &str) -> bool {
    let at = |what: &str| log.iter().position(|l| l.starts_with(what)).unwrap();
    at(&format!("end ch{a}")) < at(&format!("start ch{b}"))
}

#[test]
fn unchanged_chapters_are_shown_and_the_edited_one_answers_first_alone() {
    let fake = Fake::new();
    // The first run: no result to reuse, none known to pass, so one
    // chapter at a time, in order.
    let (passed, log) = fake.progress();
    assert!(passed);
    assert_eq!(
        starts(&log),
        ["01", "02", "03", "04", "05", "06", "07", "08"]
    );
    let mut one_at_a_time = ["01", "02", "03", "04", "05", "06", "07", "08"].windows(2);
    assert!(one_at_a_time.all(|w| before(&log, w[0], w[1])), "{log:?}");
    // Nothing changed: nothing is tested.
    let (passed, log) = fake.progress();
    assert!(passed && log.is_empty(), "{log:?}");

    // An edit in chapter 3: chapters 1 and 2 are shown as they were,
    // chapter 3 is tested alone, then the others, two at a time (they
    // passed last time).
    fake.edit("03-lambert");
    let (passed, log) = fake.progress();
    assert!(passed);
    assert_eq!(starts(&log), ["03", "04", "05", "06", "07", "08"]);
    assert!(
        log[0] == "start ch03-lambert" && before(&log, "03", "04"),
        "{log:?}"
    );
    assert!(!before(&log, "04", "05"), "chapter 5 starts early: {log:?}");
}

#[test]
fn a_failing_chapter_stops_those_after_it() {
    let fake = Fake::new();
    fake.progress();
    // The edited chapter fails: it alone is tested.
    fake.fail("ch04-shadows");
    fake.edit("04-shadows");
    let (passed, log) = fake.progress();
    assert!(!passed);
    assert_eq!(starts(&log), ["04"]);
    // Again, nothing changed: its failure is shown, nothing tested.
    let (passed, log) = fake.progress();
    assert!(!passed && log.is_empty(), "{log:?}");

    // An edit in chapter 1 with chapter 4 still failing: chapter 4 may
    // start beside chapter 3 (which passed last time), chapter 5 not
    // beside chapter 4 (which failed), and after chapter 4 fails again
    // the chapters after it are not run.
    fake.edit("01-rays");
    let (passed, log) = fake.progress();
    assert!(!passed);
    assert_eq!(starts(&log), ["01", "02", "03", "04"], "{log:?}");
}
