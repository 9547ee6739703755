//! `grade` against a class of hostile submissions (issue 35): one test per
//! attack kind that the sandbox, the copies and the checks stop, on one
//! graded class (chapter 1 only, to keep CI's time):
//!
//! | folder       | honest work | what it tries                                          | expected row             |
//! |--------------|-------------|--------------------------------------------------------|--------------------------|
//! | `a-runtime`  | chapter 1   | a `setsid` child; Unix sockets outside; overwriting the shared artefacts in place (its own, the base build's, the teacher's); a symlink and a FIFO as failure pictures | 3/3, the pictures refused and flagged |
//! | `b-reacher`  | none        | `#[path = "/…"]` to the reference's solution, `include_str!` of another student's file | 0/3 (does not compile), flagged |
//! | `c-hogs`     | none        | files together over its disk; six children together over its memory | 0/3, both limits noted |
//! | `\t=SUM(1)`  | chapter 1   | its name: a CSV cell that begins with a tab              | 3/3, the cell neutralised |
//! | `d-swapper`  | none        | in the probe: `target/probe` swapped for a link to the base copy's outputs, `snapshot-failures/01-rays` for a link to a teacher's folder, a picture named with escapes; a forged record on the pipe, then exit 0 | 0/3, the links flagged, nothing read through them |
//! | `e-record-secret` | chapter 1 | `.raybook-handout.toml` a link to a teacher's secret; a 1 GiB sparse file in `src/` | 3/3, both flagged, the secret never quoted |
//! | `f-record-stdin` | chapter 1 | the record a link to `/dev/stdin`; a FIFO in `src/` | 3/3, flagged, the class never waits |
//! | `g-record-zero` | chapter 1 | the record a link to `/dev/zero` | 3/3, flagged, nothing read |
//! | `h-panicker` | chapter 1   | in the probe, `at` leaves a symlink named with the seed in its build folder, then panics with the probe's arguments; in its tests, a failure picture named with ESC and CR | 2/3, nothing of the probe in its Gradescope output, the picture refused |
//! | `i-new⏎zz-fake,3,3` | none | its name a line break and a forged row; a file named with ESC and CR | 0/3, one line everywhere |
//! | `j-early`    | chapter 1   | an `.init_array` constructor that forges a record on the pipe before `main`, and a `#[global_allocator]` of its own | 0/3 (the forged values are worth nothing), no crash |
//! | `k-settings` | chapter 1   | `[patch]` in the Cargo.toml, a proc-macro crate added, `#[no_mangle] main` replacing the entry point | 0/3 (the link fails: a second `main`), flagged |
//! | `l-printer`  | none        | every exercise prints `test NAME ... ok` for every test of the chapter, then exits 0 | 0/3 (its tests "pass") |
//! | `m-forger`   | chapter 1   | ch01-at a lookup table of the tests' values; ch01-frame the reference's frame for the handout's scene, stored beside the embedded reference picture, which it overwrites in its copy | 1/3, flagged where it overwrote the picture |
//! | `n-padded`   | chapter 1   | 75 MiB of noise `include_bytes!`'d into a `static` its `Ray::at` reads: a probe of 90 MiB, copied to the teacher's disk per chapter | 0/3, the probe refused, never kept |
//! | `o-beyond`   | chapter 1   | once a process, a file in `/dev` (bubblewrap's tmpfs: half the memory) and 65 MiB in `/dev/shm`; panics if either went through | 3/3: neither does |
//! | `p-verbose`  | chapter 1   | 2000 files added (a flag each); `Ray::at` panics with a 1 MiB line | 2/3, at most 101 flags, every text cut: the report stays small |
//! | `q-pictures` | chapter 1   | forty 4 MiB failure pictures, kept on the teacher's disk twice | 3/3, 8 MiB of them kept, flagged |
//! | `r-slow-scan` | chapter 1  | three 8 MiB sources of `#[`, `include!(r#"` and `include!(x)` lines, each read again from every one (days) | 3/3, read in one pass, 100 flags a file |
//! | `s-flood`    | chapter 1   | its tests print 12 MiB of made-up failures and panics (a quarter of a million names) | 3/3, read in one pass |
//! | `zz-honest`  | chapter 1   | nothing, graded after the others                       | 3/3, no flag             |
//!
//! Nothing outside the students' copies may change: the reference, the
//! class's folders, the base build and the grading cache, the teacher's own
//! `target/` (a canary in it), checked before and after. No process of a
//! student outlives the run, and the sockets outside hear nothing.
//!
//! It needs the sandbox (bubblewrap, user namespaces): where it cannot
//! start, grading refuses and these tests fail. It takes minutes, so it
//! runs only when asked, as CI does:
//!
//! ```text
//! RAYBOOK_GRADE_HOSTILE=1 cargo test -p grade --test hostile -- --nocapture
//! ```

mod grade_support;

use std::collections::BTreeMap;
use std::os::unix::fs::MetadataExt;
use std::os::unix::net::UnixListener;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Instant;

use grade_support::{Row, class_fingerprint, read_csv, snapshot_reference};

/// The class: each student's folder made, with the attack it tries.
mod hostile_class;

use hostile_class::{NEWLINE, make_class};

/// What the graded class left: its rows, what grading printed, and the
/// checks made around it.
struct Graded {
    rows: BTreeMap<String, Row>,
    csv: String,
    printed: String,
    /// Fingerprints that must not change: (what, before, after).
    unchanged: Vec<(&'static str, Vec<String>, Vec<String>)>,
    /// What the sockets outside heard.
    heard: Vec<String>,
    /// Processes still running with the survivor's mark.
    survivors: Vec<String>,
    /// The secret the symlinked picture led to, and the report folder.
    secret: String,
    report: PathBuf,
}

/// The class, graded once for all the tests (None: not asked for).
fn graded() -> Option<&'static Graded> {
    static GRADED: OnceLock<Graded> = OnceLock::new();
    if std::env::var_os("RAYBOOK_GRADE_HOSTILE").is_none() {
        eprintln!("hostile: set RAYBOOK_GRADE_HOSTILE=1 to grade the hostile class (minutes)");
        return None;
    }
    Some(GRADED.get_or_init(grade_the_class))
}

/// `grade CLASS --chapters 1` with this test's reference and output.
fn grade(reference: &Path, out: &Path, class: &Path) -> String {
    let limits = ["--memory", "3072", "--disk", "1024", "--timeout", "180"];
    let mut args = vec![class.as_os_str()];
    args.extend(limits.iter().map(std::ffi::OsStr::new));
    grade_support::grade_chapters(reference, out, &args, "1")
}

fn grade_the_class() -> Graded {
    let start = Instant::now();
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("grade-hostile");
    // Everything of a last run goes but the reference's base build (kept
    // for the same reference: a rerun on a maintainer's machine skips it).
    let (class, out) = (base.join("class"), base.join("out"));
    let kept = base.with_file_name("grade-hostile-kept");
    let _ = std::fs::rename(out.join(".cache"), &kept);
    let _ = std::fs::remove_dir_all(&base);
    let reference = snapshot_reference(&base.join("reference"));
    if kept.exists() {
        std::fs::create_dir_all(&out).unwrap();
        let _ = std::fs::remove_dir_all(kept.join("students"));
        let _ = std::fs::remove_dir_all(kept.join("work"));
        std::fs::rename(&kept, out.join(".cache")).unwrap();
    }
    // The base build first (an empty class), so that what it made can be
    // checked before and after the students.
    std::fs::create_dir_all(base.join("nobody")).unwrap();
    grade(&reference, &out, &base.join("nobody"));
    eprintln!("reference prepared: {:.0?}", start.elapsed());

    let teacher_deps = Path::new(env!("CARGO_BIN_EXE_grade"))
        .parent()
        .unwrap()
        .join("deps");
    std::fs::write(teacher_deps.join("raybook-hostile-canary"), "the teacher's").unwrap();
    let secret = format!("a secret of the teacher's, {}", std::process::id());
    std::fs::write(base.join("secret.txt"), &secret).unwrap();
    let teacher_pictures = base.join("teacher-pictures");
    std::fs::create_dir_all(&teacher_pictures).unwrap();
    std::fs::write(teacher_pictures.join("default.diff.png"), &secret).unwrap();
    let (heard, socket, abstract_name) = listen(&base);
    let places = [
        ("@SOCKET@", socket.display().to_string()),
        ("@ABSTRACT@", abstract_name),
        (
            "@BASE_DEPS@",
            out.join(".cache/base/target/debug/deps")
                .display()
                .to_string(),
        ),
        ("@TEACHER_DEPS@", teacher_deps.display().to_string()),
        ("@SECRET@", base.join("secret.txt").display().to_string()),
        (
            "@BASE_PROBE@",
            out.join(".cache/base/target/probe").display().to_string(),
        ),
        ("@TEACHER_PICTURES@", teacher_pictures.display().to_string()),
    ];
    make_class(&reference, &class, &places);

    let watched: Vec<(&'static str, PathBuf)> = vec![
        ("the reference", reference.clone()),
        ("the class", class.clone()),
        ("the base build", out.join(".cache/base/target/debug/deps")),
        ("the base copy's sources", out.join(".cache/base/chapters")),
        ("the teacher's pictures", teacher_pictures.clone()),
    ];
    let before: Vec<Vec<String>> = watched.iter().map(|(_, p)| class_fingerprint(p)).collect();
    let teacher_before = shallow_fingerprint(&teacher_deps);
    let start = Instant::now();
    let printed = grade(&reference, &out, &class);
    eprintln!(
        "the hostile class graded: {:.0?}\n{printed}",
        start.elapsed()
    );
    let mut unchanged: Vec<_> = watched
        .iter()
        .zip(before)
        .map(|((what, path), before)| (*what, before, class_fingerprint(path)))
        .collect();
    unchanged.push((
        "the teacher's target/debug/deps",
        teacher_before,
        shallow_fingerprint(&teacher_deps),
    ));
    let csv = std::fs::read_to_string(out.join("grades.csv")).unwrap();
    eprintln!("grades.csv:\n{csv}");
    Graded {
        rows: read_csv(&out.join("grades.csv")),
        csv,
        printed,
        unchanged,
        heard: heard.lock().unwrap().clone(),
        survivors: survivors(),
        secret,
        report: out.join("report"),
    }
}

/// Listens on a Unix socket at a path outside the class and on an abstract
/// name: what they hear, the path and the name.
fn listen(base: &Path) -> (Arc<Mutex<Vec<String>>>, PathBuf, String) {
    use std::io::Read;
    use std::os::linux::net::SocketAddrExt;
    let heard = Arc::new(Mutex::new(Vec::new()));
    let path = base.join("outside.sock");
    let name = format!("raybook-hostile-{}", std::process::id());
    let address = std::os::unix::net::SocketAddr::from_abstract_name(name.as_bytes()).unwrap();
    for listener in [
        UnixListener::bind(&path).unwrap(),
        UnixListener::bind_addr(&address).unwrap(),
    ] {
        let heard = Arc::clone(&heard);
        std::thread::spawn(move || {
            for stream in listener.incoming().flatten() {
                let mut text = String::new();
                let _ = (&stream).read_to_string(&mut text);
                heard.lock().unwrap().push(text);
            }
        });
    }
    (heard, path, name)
}

/// Every file of a folder (not its subfolders): name, size, time, inode;
/// but the grade crate's own, which a build of these tests beside them
/// may rewrite.
fn shallow_fingerprint(dir: &Path) -> Vec<String> {
    let mut found: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter_map(|e| {
            let meta = e.metadata().ok()?;
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with("grade-") || name.starts_with("libgrade-") {
                return None;
            }
            Some(format!(
                "{name} {} {} {} {}",
                meta.len(),
                meta.mtime(),
                meta.mtime_nsec(),
                meta.ino()
            ))
        })
        .collect();
    found.sort();
    found
}

/// The processes whose command line holds the survivor's mark.
fn survivors() -> Vec<String> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir("/proc").unwrap().flatten() {
        let cmdline = std::fs::read(entry.path().join("cmdline")).unwrap_or_default();
        let cmdline = String::from_utf8_lossy(&cmdline).replace('\0', " ");
        if cmdline.contains("987654") {
            found.push(cmdline);
        }
    }
    found
}

/// The row of a student.
fn row(name: &str) -> Option<&'static Row> {
    Some(&graded()?.rows[name])
}

/// The row's flags, less the one every handout has today: a handout's
/// Cargo.lock still names the grade crate, which the reference's base copy
/// (without it) has dropped from its own.
fn flags(row: &Row) -> Vec<&str> {
    row["flags"]
        .split("; ")
        .filter(|f| !f.is_empty() && *f != "edited Cargo.lock")
        .collect()
}

fn score(row: &Row) -> (&str, &str) {
    (row["score"].as_str(), row["max_score"].as_str())
}

#[test]
fn nothing_outside_the_students_copies_changes() {
    let Some(graded) = graded() else { return };
    for (what, before, after) in &graded.unchanged {
        assert!(!before.is_empty(), "{what}: nothing to compare");
        let changed: Vec<_> = after.iter().filter(|a| !before.contains(a)).collect();
        assert_eq!(before, after, "{what} changed: {changed:?}");
    }
}

#[test]
fn honest_students_get_exactly_their_points_and_no_flag() {
    let Some(honest) = row("zz-honest") else {
        return;
    };
    assert_eq!(score(honest), ("3", "3"), "{honest:?}");
    assert!(flags(honest).is_empty(), "{honest:?}");
    assert_eq!(honest["troubles"], "", "{honest:?}");
}

#[test]
fn a_setsid_child_dies_with_the_run() {
    let Some(graded) = graded() else { return };
    assert!(graded.survivors.is_empty(), "{:?}", graded.survivors);
    assert_eq!(score(&graded.rows["a-runtime"]), ("3", "3"));
}

#[test]
fn a_unix_socket_reaches_no_process_outside() {
    let Some(graded) = graded() else { return };
    assert!(graded.heard.is_empty(), "heard {:?}", graded.heard);
}

#[test]
fn overwriting_shared_artefacts_in_place_harms_no_one_else() {
    let Some(graded) = graded() else { return };
    // The base build and the teacher's target: `nothing_outside…`. Here:
    // the classmate graded after builds and scores as if nothing happened.
    let honest = &graded.rows["zz-honest"];
    assert_eq!(
        (score(honest), honest["compiled"].as_str()),
        (("3", "3"), "yes")
    );
    let canary = Path::new(env!("CARGO_BIN_EXE_grade"))
        .parent()
        .unwrap()
        .join("deps/raybook-hostile-canary");
    assert_eq!(std::fs::read_to_string(canary).unwrap(), "the teacher's");
}

#[test]
fn a_symlink_or_a_fifo_as_a_failure_picture_is_refused_and_noted() {
    let Some(graded) = graded() else { return };
    let attacker = &graded.rows["a-runtime"];
    let flags = flags(attacker);
    let leak = flags.iter().find(|f| f.contains("leak.diff.png"));
    assert!(leak.is_some_and(|f| f.contains("a symlink")), "{flags:?}");
    let block = flags.iter().find(|f| f.contains("block.diff.png"));
    assert!(block.is_some_and(|f| f.contains("a FIFO")), "{flags:?}");
    // Nothing of the secret reached the report.
    for entry in test_support::files_under(&graded.report) {
        let bytes = std::fs::read(&entry).unwrap_or_default();
        let text = String::from_utf8_lossy(&bytes);
        assert!(
            !text.contains(&graded.secret),
            "{} leaks it",
            entry.display()
        );
    }
}

#[test]
fn paths_and_includes_outside_the_folder_read_nothing_and_are_flagged() {
    let Some(reacher) = row("b-reacher") else {
        return;
    };
    assert_eq!(score(reacher), ("0", "3"), "{reacher:?}");
    assert_eq!(
        reacher["compiled"], "no",
        "the files are not in its sandbox"
    );
    let flags = flags(reacher);
    assert!(
        flags
            .iter()
            .any(|f| f.contains("#[path] reaches outside") && f.contains("an absolute path")),
        "{flags:?}"
    );
    assert!(
        flags
            .iter()
            .any(|f| f.contains("include_str! reaches outside")),
        "{flags:?}"
    );
}

#[test]
fn children_together_over_the_memory_and_files_over_the_disk_are_held() {
    let Some(graded) = graded() else { return };
    let hogs = &graded.rows["c-hogs"];
    assert_eq!(score(hogs), ("0", "3"), "{hogs:?}");
    let report = std::fs::read_to_string(graded.report.join("index.html")).unwrap();
    assert!(
        report.contains("runs filled their build folder (1024 MiB)"),
        "the disk limit is noted"
    );
    // A control group per student where the system allows one (as root on
    // cgroup v1, or delegated): then the memory limit held them together.
    if !graded.printed.contains("no control group per student") {
        assert!(
            report.contains("the kernel ended"),
            "the memory limit is noted"
        );
    }
}

#[test]
fn a_csv_cell_that_begins_with_a_tab_is_neutralised() {
    let Some(graded) = graded() else { return };
    assert!(graded.csv.contains("'\t=SUM(1)"), "{}", graded.csv);
    let cells = graded.csv.split([',', '\n']);
    assert!(cells.clone().all(|c| !c.starts_with('\t')));
    assert_eq!(score(&graded.rows["'\t=SUM(1)"]), ("3", "3"));
}

/// The Gradescope output of the student whose slug is `slug`.
fn gradescope(slug: &str) -> Option<String> {
    let graded = graded()?;
    let out = graded.report.parent().unwrap();
    Some(std::fs::read_to_string(out.join("gradescope").join(format!("{slug}.json"))).unwrap())
}

/// The attacks on what leaves the sandbox and on what grading reads
/// (issue 43), and on the judging.
mod hostile_reads;

/// The bounds on what a student's runs write: `/dev` in the sandbox, the
/// probes kept outside it.
mod hostile_bounds;
