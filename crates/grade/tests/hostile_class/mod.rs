//! The hostile class's students (see the table in `hostile.rs`): handouts
//! made from the reference, each with the attack it tries written in.

use std::path::Path;

use crate::grade_support::handout;

/// The attacker's code (`at` calls it once per process).
const RUNTIME: &str = include_str!("../hostile_corpus/runtime.rs");

/// The student folders.
pub fn make_class(reference: &Path, class: &Path, places: &[(&str, String)]) {
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
    attacker(&student("q-pictures", 1), "pictures", true);
    attacker(&student("s-flood", 1), "flood", true);

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

    let padded = student("n-padded", 1);
    pad(&padded.join("chapters/01-rays/src"));
    rewrite(&padded, |id| {
        (id == "ch01-at").then(|| PADDED_AT.to_owned())
    });
    let beyond = student("o-beyond", 1);
    append(&beyond.join("chapters/01-rays/src/lib.rs"), BEYOND);
    rewrite(&beyond, |id| {
        (id == "ch01-at").then(|| BEYOND_AT.to_owned())
    });
    let verbose = student("p-verbose", 1);
    let notes = verbose.join("chapters/01-rays/notes");
    std::fs::create_dir_all(&notes).unwrap();
    for i in 0..2000 {
        std::fs::write(notes.join(format!("{i}.md")), "").unwrap();
    }
    rewrite(&verbose, |id| {
        (id == "ch01-at").then(|| "        panic!(\"{}\", \"x\".repeat(1 << 20))".to_owned())
    });
    let slow = student("r-slow-scan", 1);
    for (i, unit) in ["#[", "include!(r#\"", "include!(x)\n"].iter().enumerate() {
        let text = unit.repeat((8 << 20) / unit.len());
        std::fs::write(slow.join(format!("chapters/01-rays/src/slow{i}.rs")), text).unwrap();
    }

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
        include_str!("../../../../chapters/01-rays/scenes/default.toml"),
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
pub const NEWLINE: &str = "i-new\nzz-fake,3,3";

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

/// 75 MiB of padding in `src` (a probe of about 90 MiB, past the 64 MiB
/// grading keeps; an honest one is about 15 MiB): five files of 15 MiB of
/// noise (alike, the linker would keep one), each taken in by
/// `include_bytes!` into `PAD`. (A `static` array as large makes rustc
/// run out of its address space.)
fn pad(src: &Path) {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut names = Vec::new();
    for i in 0..5 {
        let noise: Vec<u8> = (0..(15 << 20) / 8)
            .flat_map(|_| {
                // xorshift64: noise that no compressor or linker merges.
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state.to_le_bytes()
            })
            .collect();
        std::fs::write(src.join(format!("pad{i}.bin")), noise).unwrap();
        names.push(format!("include_bytes!(\"pad{i}.bin\")"));
    }
    let code = format!("\npub static PAD: [&[u8]; 5] = [{}];\n", names.join(", "));
    append(&src.join("lib.rs"), &code);
}

/// Ray::at, right, reading the padding so that the linker keeps it.
const PADDED_AT: &str = "        let _ = std::hint::black_box(&crate::PAD).len();\n        \
                         self.origin + t * self.direction";

/// Writes where a sandbox may have no bound: a file in `/dev` (bubblewrap's
/// own tmpfs, half the machine's memory) and 65 MiB in `/dev/shm`; panics
/// if either was written whole.
const BEYOND: &str = r#"
fn write_beyond() {
    use std::io::Write;
    let chunk = vec![7u8; 1 << 20];
    let shm = std::fs::File::create("/dev/shm/hog")
        .is_ok_and(|mut f| (0..65).all(|_| f.write_all(&chunk).is_ok()));
    let _ = std::fs::remove_file("/dev/shm/hog");
    let dev = std::fs::write("/dev/hog", b"x").is_ok();
    assert!(!shm && !dev, "written beyond the bounds: /dev/shm {shm}, /dev {dev}");
}
"#;

/// Ray::at, right, after one try (a process) at writing beyond the bounds.
const BEYOND_AT: &str = "        static ONCE: std::sync::Once = std::sync::Once::new();\n        \
                         ONCE.call_once(crate::write_beyond);\n        \
                         self.origin + t * self.direction";

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
