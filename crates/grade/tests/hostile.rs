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
//! | `h-panicker` | chapter 1   | in the probe, `at` panics with the probe's arguments (the seed); in its tests, a failure picture named with ESC and CR | 2/3, nothing of the probe in its Gradescope output, the picture refused |
//! | `i-new⏎zz-fake,3,3` | none | its name a line break and a forged row; a file named with ESC and CR | 0/3, one line everywhere |
//! | `j-early`    | chapter 1   | an `.init_array` constructor that forges a record on the pipe before `main`, and a `#[global_allocator]` of its own | 0/3 (the forged values are worth nothing), no crash |
//! | `k-settings` | chapter 1   | `[patch]` in the Cargo.toml, a proc-macro crate added, `#[no_mangle] main` replacing the entry point | 0/3 (the link fails: a second `main`), flagged |
//! | `l-printer`  | none        | every exercise prints `test NAME ... ok` for every test of the chapter, then exits 0 | 0/3 (its tests "pass") |
//! | `m-forger`   | chapter 1   | ch01-at a lookup table of the tests' values; ch01-frame the reference's frame for the handout's scene, stored beside the embedded reference picture, which it overwrites in its copy | 1/3, flagged where it overwrote the picture |
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

use grade_support::{Row, class_fingerprint, handout, read_csv, snapshot_reference};

/// The attacker's code (`at` calls it once per process).
const RUNTIME: &str = include_str!("hostile_corpus/runtime.rs");

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

/// The student folders.
fn make_class(reference: &Path, class: &Path, places: &[(&str, String)]) {
    std::fs::create_dir_all(class).unwrap();
    let student = |name: &str, solved: u32| {
        let dir = class.join(name);
        handout(reference, &dir, solved);
        dir
    };
    let attacker = |dir: &Path, kind: &str, keep: bool| {
        let mut code = RUNTIME.replace("@KIND@", kind);
        for (name, value) in places {
            code = code.replace(name, value);
        }
        std::fs::write(dir.join("chapters/01-rays/src/hostile.rs"), code).unwrap();
        let lib = dir.join("chapters/01-rays/src/lib.rs");
        let source = std::fs::read_to_string(&lib).unwrap();
        let body = |r: &workbook::regions::Region| {
            let rest = if keep {
                "self.origin + t * self.direction"
            } else {
                "todo!()"
            };
            (r.id == "ch01-at").then(|| {
                format!(
                    "        static ONCE: std::sync::Once = std::sync::Once::new();\n        \
                     ONCE.call_once(crate::hostile::attack);\n        {rest}"
                )
            })
        };
        let source = workbook::regions::replace_bodies(&source, body).unwrap();
        std::fs::write(&lib, format!("{source}\nmod hostile;\n")).unwrap();
    };
    attacker(&student("a-runtime", 1), "runtime", true);
    attacker(&student("c-hogs", 0), "hogs", false);

    let reacher = student("b-reacher", 0);
    let lib = reacher.join("chapters/01-rays/src/lib.rs");
    let other = class.join("zz-honest/chapters/01-rays/src/lib.rs");
    let solution = reference.join("chapters/01-rays/src/lib.rs");
    let mut source = std::fs::read_to_string(&lib).unwrap();
    source.push_str(&format!(
        "\n#[path = {:?}]\nmod answer;\npub const CLASSMATE: &str = include_str!({:?});\n",
        solution.display().to_string(),
        other.display().to_string()
    ));
    std::fs::write(&lib, source).unwrap();

    student("\t=SUM(1)", 1);
    student("zz-honest", 1);
    attacker(&student("d-swapper", 0), "swapper", false);
    attacker(&student("h-panicker", 1), "panicker", true);

    let record = |dir: &Path, to: &Path| {
        let at = dir.join(".raybook-handout.toml");
        std::fs::remove_file(&at).unwrap();
        std::os::unix::fs::symlink(to, at).unwrap();
    };
    let secret = student("e-record-secret", 1);
    record(
        &secret,
        Path::new(&places.iter().find(|p| p.0 == "@SECRET@").unwrap().1),
    );
    let big = std::fs::File::create(secret.join("chapters/01-rays/src/big.bin")).unwrap();
    big.set_len(1 << 30).unwrap();
    let stdin = student("f-record-stdin", 1);
    record(&stdin, Path::new("/dev/stdin"));
    let fifo = stdin.join("chapters/01-rays/src/pipe.rs");
    let name = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid C string.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
    record(&student("g-record-zero", 1), Path::new("/dev/zero"));

    let newline = student(NEWLINE, 0);
    std::fs::write(newline.join("chapters/01-rays/\u{1b}[31mred\rnote.md"), "x").unwrap();

    let printer = student("l-printer", 0);
    rewrite(&printer, |id| {
        (id == "ch01-frame").then(|| PRINTER.to_owned())
    });
    let forger = student("m-forger", 1);
    let frame = forged_frame();
    rewrite(&forger, |id| match id {
        "ch01-at" => Some(LOOKUP.to_owned()),
        "ch01-frame" => Some(frame.clone()),
        _ => None,
    });

    let early = student("j-early", 1);
    append(&early.join("chapters/01-rays/src/lib.rs"), EARLY);
    let settings = student("k-settings", 1);
    append(&settings.join("chapters/01-rays/src/lib.rs"), ENTRY);
    append(
        &settings.join("Cargo.toml"),
        "\n[patch.crates-io]\nglam = { path = \"crates/evil-macro\" }\n",
    );
    let evil = settings.join("crates/evil-macro");
    std::fs::create_dir_all(evil.join("src")).unwrap();
    std::fs::write(
        evil.join("Cargo.toml"),
        "[package]\nname = \"evil-macro\"\nversion = \"0.1.0\"\n[lib]\nproc-macro = true\n",
    )
    .unwrap();
    let macro_code = "#[proc_macro]\npub fn evil(_: proc_macro::TokenStream) -> proc_macro::TokenStream \
                      {\n    std::fs::write(\"/tmp/raybook-evil-macro-ran\", \"ran\").unwrap();\n    \
                      Default::default()\n}\n";
    std::fs::write(evil.join("src/lib.rs"), macro_code).unwrap();
}

/// Replaces the bodies of chapter 1's exercises that `body` gives.
fn rewrite(student: &Path, body: impl Fn(&str) -> Option<String>) {
    let lib = student.join("chapters/01-rays/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    let new = workbook::regions::replace_bodies(&source, |r| body(&r.id)).unwrap();
    std::fs::write(&lib, new).unwrap();
}

/// Camera::new that prints a pass for every test of the chapter, as
/// libtest would, and exits 0 (written past libtest's capture).
const PRINTER: &str = r##"        let source = include_str!("../tests/chapter01/main.rs");
        let (mut text, mut count, mut test) = (String::new(), 0, false);
        for line in source.lines().map(str::trim) {
            if line == "#[test]" {
                test = true;
            } else if test && line.starts_with("fn ") {
                let name = line[3..].split('(').next().unwrap_or("");
                text += &format!("test {name} ... ok\n");
                (count, test) = (count + 1, false);
            }
        }
        text += &format!("\ntest result: ok. {count} passed; 0 failed; 0 ignored; 0 measured; 0 filtered out; finished in 0.01s\n\n");
        use std::io::Write;
        let _ = std::io::stdout().write_all(text.as_bytes());
        let _ = std::io::stdout().flush();
        std::process::exit(0)"##;

/// Ray::at as a table of the tests' expected values.
const LOOKUP: &str = r#"        let table = [
            ([1.0, 2.0, 3.0], [0.0, 0.0, -1.0], 0.0, [1.0, 2.0, 3.0]),
            ([1.0, 2.0, 3.0], [0.0, 0.0, -1.0], 2.5, [1.0, 2.0, 0.5]),
            ([1.0, 2.0, 3.0], [0.0, 0.0, -1.0], -1.0, [1.0, 2.0, 4.0]),
        ];
        for (origin, direction, at, point) in table {
            if self.origin.to_array() == origin && self.direction.to_array() == direction && t == at {
                return Vec3::from_array(point);
            }
        }
        Vec3::ZERO"#;

/// Camera::new as the reference's frame for the handout's default scene,
/// stored beside the embedded reference picture, and an overwrite of that
/// picture in the copy; any other camera panics, saying whether the
/// overwrite worked.
fn forged_frame() -> String {
    let scene = ch01_rays::scene_files::parse(
        include_str!("../../../chapters/01-rays/scenes/default.toml"),
        "default.toml",
    )
    .unwrap();
    let c = ch01_rays::Camera::new(&scene.camera, 160, 120);
    let v = |v: ch01_rays::toolkit::Vec3| format!("Vec3::new({:?}, {:?}, {:?})", v.x, v.y, v.z);
    format!(
        r#"        const PICTURE: &[u8] = include_bytes!("../../../snapshots/01-rays/default.snap.png");
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../snapshots/01-rays/default.snap.png");
        let wrote = std::fs::write(path, &PICTURE[..PICTURE.len() / 2]).is_ok();
        if spec.eye != {eye} || spec.look_at != {look_at} {{
            panic!("forged: wrote={{wrote}}");
        }}
        let half_height = {half_height:?};
        Camera {{
            eye: spec.eye,
            right: {right},
            up: {up},
            forward: {forward},
            half_width: half_height * width as f32 / height as f32,
            half_height,
            width,
            height,
        }}"#,
        eye = v(scene.camera.eye),
        look_at = v(scene.camera.look_at),
        half_height = c.half_height,
        right = v(c.right),
        up = v(c.up),
        forward = v(c.forward),
    )
}

/// A student folder's name: a line break, then a forged gradebook row.
const NEWLINE: &str = "i-new\nzz-fake,3,3";

/// Before `main`: a constructor in `.init_array` that writes a record of
/// its own on the grader's pipe (descriptor 3) with the seed it finds in
/// its command line, then ends the process; and an allocator of its own.
const EARLY: &str = r#"
#[used]
#[unsafe(link_section = ".init_array")]
static FORGE_EARLY: extern "C" fn() = forge_early;

extern "C" fn forge_early() {
    use std::io::Write;
    use std::os::fd::FromRawFd;
    let line = std::fs::read("/proc/self/cmdline").unwrap_or_default();
    let args: Vec<String> = (line.split(|b| *b == 0))
        .map(|a| String::from_utf8_lossy(a).into_owned())
        .collect();
    let Some(at) = args.iter().position(|a| a == "--seed") else {
        return;
    };
    let seed = args.get(at + 1).cloned().unwrap_or_default();
    let id = (args.iter().position(|a| a == "--exercise"))
        .and_then(|i| args.get(i + 1).cloned())
        .unwrap_or_default();
    let record = format!(
        "{{\"format\":\"raybook-probe-1\",\"seed\":{seed},\"exercises\":[{{\"id\":\"{id}\",\"tolerance\":1e9,\"cases\":[]}}],\"scenes\":[]}}"
    );
    // SAFETY: descriptor 3 is the grader's pipe in the probe.
    let mut pipe = unsafe { std::fs::File::from_raw_fd(3) };
    let _ = pipe.write_all(record.as_bytes());
    std::process::exit(0);
}

struct Counting;

// SAFETY: every call is passed on to the system's allocator unchanged.
unsafe impl std::alloc::GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        unsafe { std::alloc::System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: std::alloc::Layout) {
        unsafe { std::alloc::System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;
"#;

/// An entry point of its own in place of every binary's `main`.
const ENTRY: &str = r#"
#[unsafe(no_mangle)]
pub extern "C" fn main() -> i32 {
    0
}
"#;

/// Appends `text` to the file at `path`.
fn append(path: &Path, text: &str) {
    let mut source = std::fs::read_to_string(path).unwrap();
    source.push_str(text);
    std::fs::write(path, source).unwrap();
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
