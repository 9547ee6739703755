//! Hostile submissions against the judging (issue 35, items 1 and 9): the
//! kinds of cheating that points read from the student's own process let
//! through, and those that a design judging values invites. Chapter 1
//! only, to keep CI's time.
//!
//! | folder    | what it does                                                   | expected            |
//! |-----------|----------------------------------------------------------------|---------------------|
//! | `honest`  | chapter 1 written                                              | 3/3, no flag        |
//! | `printer` | an empty handout whose exercises print `test NAME ... ok` for  | 0/3 (its tests      |
//! |           | every test of the chapter, then exit 0                         | "pass")             |
//! | `forger`  | ch01-ray-through written; ch01-at a lookup table of the tests' | 1/3, flagged where  |
//! |           | expected values; ch01-frame the reference's frame for the      | it overwrote the    |
//! |           | handout's scene, stored beside the embedded reference picture, | picture             |
//! |           | and it overwrites the reference picture in its copy            |                     |
//!
//! Nothing outside the students' copies may change: the class and the
//! reference are checksummed before and after.
//!
//! It runs only when asked, with `RAYBOOK_GRADE_HOSTILE=1` (a plain `cargo
//! test` says it was not asked and does nothing); asked, it fails, never
//! skips, when the students' runs cannot be confined:
//!
//! ```text
//! RAYBOOK_GRADE_HOSTILE=1 cargo test -p grade --test hostile_judging -- --nocapture
//! ```

mod grade_support;

use std::path::{Path, PathBuf};
use std::time::Instant;

use grade_support::{class_fingerprint, grade_chapters, handout, read_csv, snapshot_reference};

const CH01: [&str; 3] = ["ch01-at", "ch01-frame", "ch01-ray-through"];

#[test]
fn hostile_submissions_get_only_their_honest_points_and_are_flagged() {
    if std::env::var_os("RAYBOOK_GRADE_HOSTILE").is_none() {
        eprintln!("hostile_judging: set RAYBOOK_GRADE_HOSTILE=1 to grade the hostile corpus");
        return;
    }
    let start = Instant::now();
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("grade-hostile");
    let _ = std::fs::remove_dir_all(&base);
    let reference = snapshot_reference(&base.join("reference"));
    let class = base.join("class");
    make_class(&reference, &class);
    let before = (class_fingerprint(&class), class_fingerprint(&reference));
    let out = base.join("out");
    let printed = grade_chapters(&reference, &out, &[class.as_os_str()], "1");
    eprintln!("graded in {:.0?}\n{printed}", start.elapsed());
    assert!(
        !printed.contains("note: "),
        "the students' runs could not be confined here: {printed}"
    );
    let after = (class_fingerprint(&class), class_fingerprint(&reference));
    assert_eq!(after.0, before.0, "a student folder changed");
    assert_eq!(after.1, before.1, "the reference changed");

    let rows = read_csv(&out.join("grades.csv"));
    let points =
        |name: &str| -> Vec<&str> { CH01.iter().map(|id| rows[name][*id].as_str()).collect() };
    assert_eq!(points("honest"), ["1", "1", "1"], "{:?}", rows["honest"]);
    assert_eq!(rows["honest"]["flags"], "");

    // Its tests "passed" (the old grader gave it every point); its probes
    // wrote no values.
    let printer = &rows["printer"];
    assert_eq!(points("printer"), ["0", "0", "0"], "{printer:?}");
    assert_ne!(printer["01-rays passed"], "0", "{printer:?}");
    assert!(
        printer["why"].contains("ch01-frame: no values"),
        "{printer:?}"
    );

    let forger = &rows["forger"];
    assert_eq!(points("forger"), ["0", "0", "1"], "{forger:?}");
    assert!(
        forger["why"].contains("ch01-at: disagrees on drawn input"),
        "{forger:?}"
    );
    // Where the sandbox let it overwrite the picture, that is flagged.
    let json = std::fs::read_to_string(out.join("gradescope/forger.json")).unwrap();
    let overwrote = !json.contains("wrote=false");
    assert!(
        !overwrote
            || forger["flags"]
                .contains("changed during the run: snapshots/01-rays/default.snap.png"),
        "{forger:?}"
    );
    eprintln!("whole test: {:.0?}", start.elapsed());
}

/// The class: `honest`, `printer`, `forger` (see the module's table).
fn make_class(reference: &Path, class: &Path) {
    std::fs::create_dir_all(class).unwrap();
    handout(reference, &class.join("honest"), 1);

    let printer = class.join("printer");
    handout(reference, &printer, 0);
    rewrite(&printer, |id| {
        (id == "ch01-frame").then(|| PRINTER.to_owned())
    });

    let forger = class.join("forger");
    handout(reference, &forger, 1);
    let frame = forged_frame();
    rewrite(&forger, |id| match id {
        "ch01-at" => Some(LOOKUP.to_owned()),
        "ch01-frame" => Some(frame.clone()),
        _ => None,
    });
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
