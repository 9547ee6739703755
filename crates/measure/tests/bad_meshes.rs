//! A corpus of malformed OBJ meshes, each named by a scene and rendered with
//! `raybook render`: each is refused with the scene's file:line:column and
//! the mesh's own place (its file:line:column, or its file for what is wrong
//! with all of it), never with a panic or a hang, and no picture is left
//! behind. Files that are not regular files (a device, a named pipe, a
//! folder, a loop of links) are refused at once, as meshes and as scenes;
//! so is an NFF polygon that says it has a billion corners. What OBJ
//! allows (CRLF line ends, a byte order mark, a missing material library)
//! is read.

mod common;

use std::path::Path;

use common::{PATH_COLUMN, PATH_LINE, names_in, raybook, scene_with_mesh};

const TRIANGLE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

/// A malformed mesh: its name, its bytes, where the mesh's error is
/// (`Some((line, column))`, or `None` for the whole file) and words that
/// its message must have.
type Case = (
    &'static str,
    Vec<u8>,
    Option<(u32, u32)>,
    &'static [&'static str],
);

fn corpus() -> Vec<Case> {
    let text = |s: &str| s.as_bytes().to_vec();
    let face = |f: &str| text(&format!("{TRIANGLE}{f}\n"));
    let mut binary: Vec<u8> = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR".to_vec();
    binary.extend((0..=255u8).cycle().take(1000));
    vec![
        (
            "missing vertex",
            face("f 1 2 4"),
            Some((4, 7)),
            &["vertex 4", "3 v lines above"],
        ),
        (
            "far back",
            face("f -1 -2 -4"),
            Some((4, 9)),
            &["vertex -4", "4 back"],
        ),
        (
            "vertex zero",
            face("f 0 1 2"),
            Some((4, 3)),
            &["vertex 0 names none"],
        ),
        (
            "missing normal",
            face("f 1//1 2//1 3//1"),
            Some((4, 3)),
            &["normal 1", "0 vn"],
        ),
        (
            "later vertex",
            text("f 1 2 3\nv 0 0 0\n"),
            Some((1, 3)),
            &["0 v lines above"],
        ),
        ("NaN", text("v 0 NaN 0\n"), Some((1, 5)), &["finite", "NaN"]),
        (
            "inf",
            text("v 0 0 0\nv -inf 0 0\n"),
            Some((2, 3)),
            &["finite", "-inf"],
        ),
        (
            "beyond f32",
            text("v 1e39 0 0\n"),
            Some((1, 3)),
            &["too large", "f32"],
        ),
        (
            "NaN normal",
            face("vn 0 nan 1"),
            Some((4, 6)),
            &["finite", "nan"],
        ),
        (
            "two corners",
            face("f 1 2"),
            Some((4, 3)),
            &["3 corners or more, found 2"],
        ),
        (
            "odd corner",
            face("f 1/1/1/1 2 3"),
            Some((4, 3)),
            &["v/vt/vn", "1/1/1/1"],
        ),
        (
            "word",
            text("v 0 0 zero\n"),
            Some((1, 7)),
            &["expected a number", "zero"],
        ),
        (
            "unknown",
            text("vertex 0 0 0\n"),
            Some((1, 1)),
            &["unknown statement `vertex`"],
        ),
        ("empty", vec![], None, &["the OBJ file is empty"]),
        ("comments", text("# nothing\n\n"), None, &["no faces"]),
        (
            "no area",
            face("f 1 1 2\nf 1 2 2"),
            None,
            &["no triangles with area"],
        ),
        (
            "binary",
            binary,
            Some((2, 1)),
            &["0x1A is not text", "binary"],
        ),
        (
            "no line end",
            vec![0xFF; 3 << 20],
            Some((1, 1)),
            &["longer than 1 MiB"],
        ),
    ]
}

/// What a refusal of the mesh `mesh.obj` must say: where in the scene, and
/// where in the mesh.
fn assert_refused_at(dir: &Path, place: Option<(u32, u32)>, words: &[&str]) {
    let before = names_in(dir);
    let run = raybook(dir, &["render", "scene.toml", "-q", "-o", "out.png"]);
    let e = &run.stderr;
    println!("{:?}: {}", run.took, e.lines().next().unwrap_or(""));
    assert!(!run.success, "{e}");
    assert!(!e.contains("panicked"), "{e}");
    let scene = format!("error: scene.toml:{PATH_LINE}:{PATH_COLUMN}: objects[1].path: ");
    let mesh = match place {
        Some((line, column)) => format!("mesh.obj:{line}:{column}: "),
        None => "mesh.obj: ".into(),
    };
    assert!(e.starts_with(&format!("{scene}{mesh}")), "{e}");
    for word in words {
        assert!(e.contains(word), "{word:?} missing from: {e}");
    }
    assert_eq!(
        names_in(dir),
        before,
        "a refused render leaves nothing behind"
    );
}

#[test]
fn every_malformed_mesh_is_refused_where_it_is_wrong() {
    for (name, bytes, place, words) in corpus() {
        println!("{name}");
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("scene.toml"), scene_with_mesh("mesh.obj")).unwrap();
        std::fs::write(dir.path().join("mesh.obj"), bytes).unwrap();
        assert_refused_at(dir.path(), place, words);
    }
}

/// A scene in a new folder whose mesh `mesh.obj` is made by `make`.
fn with_mesh(make: impl FnOnce(&Path)) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene_with_mesh("mesh.obj")).unwrap();
    make(&dir.path().join("mesh.obj"));
    dir
}

#[test]
fn a_mesh_that_is_missing_or_a_folder_is_refused() {
    let dir = with_mesh(|_| {});
    assert_refused_at(
        dir.path(),
        None,
        &["cannot read the OBJ file", "No such file"],
    );
    let dir = with_mesh(|path| std::fs::create_dir(path).unwrap());
    assert_refused_at(dir.path(), None, &["it is a directory, not a file"]);
}

#[cfg(unix)]
#[test]
fn a_mesh_that_loops_through_links_is_refused() {
    let dir = with_mesh(|path| {
        let other = path.with_file_name("other.obj");
        std::os::unix::fs::symlink(&other, path).unwrap();
        std::os::unix::fs::symlink(path, other).unwrap();
    });
    assert_refused_at(dir.path(), None, &["loops through symbolic links"]);
}

#[cfg(unix)]
#[test]
fn a_device_or_a_pipe_is_refused_at_once_as_a_mesh() {
    let dir = with_mesh(common::fifo);
    assert_refused_at(dir.path(), None, &["named pipe (FIFO), not a regular file"]);
    let dir = with_mesh(|path| std::os::unix::fs::symlink("/dev/zero", path).unwrap());
    assert_refused_at(dir.path(), None, &["a device (such as /dev/zero"]);
    // Named directly, the device is the mesh's name in the message.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene_with_mesh("/dev/zero")).unwrap();
    let run = raybook(dir.path(), &["render", "scene.toml", "-q", "-o", "out.png"]);
    println!("/dev/zero as a mesh: refused in {:?}", run.took);
    let at = format!("scene.toml:{PATH_LINE}:{PATH_COLUMN}: objects[1].path: /dev/zero: ");
    assert!(run.stderr.contains(&at), "{}", run.stderr);
    assert_eq!(names_in(dir.path()), ["scene.toml"]);
}

#[cfg(unix)]
#[test]
fn a_device_a_pipe_or_a_folder_is_refused_at_once_as_a_scene() {
    let dir = tempfile::tempdir().unwrap();
    common::fifo(&dir.path().join("pipe.toml"));
    common::fifo(&dir.path().join("pipe.nff"));
    std::fs::create_dir(dir.path().join("folder.toml")).unwrap();
    for (scene, words) in [
        ("/dev/zero", "it is a device (such as /dev/zero"),
        ("pipe.toml", "it is a named pipe (FIFO)"),
        ("pipe.nff", "it is a named pipe (FIFO)"),
        ("folder.toml", "it is a directory"),
    ] {
        let run = raybook(dir.path(), &["render", scene, "-q", "-o", "out.png"]);
        println!("{scene} as a scene: refused in {:?}", run.took);
        let expected = format!("error: {scene}: cannot read the scene file: {words}");
        assert!(run.stderr.starts_with(&expected), "{}", run.stderr);
    }
    assert_eq!(
        names_in(dir.path()),
        ["folder.toml", "pipe.nff", "pipe.toml"]
    );
}

#[test]
fn an_nff_polygon_of_a_billion_corners_says_what_is_wrong() {
    let dir = tempfile::tempdir().unwrap();
    let nff = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\n\
               f 1 1 1 1 0 1 0 1\np 1000000000\n0 0 0\n1 0 0\n0 1 0\n";
    std::fs::write(dir.path().join("scene.nff"), nff).unwrap();
    let run = raybook(dir.path(), &["render", "scene.nff", "-q", "-o", "out.png"]);
    println!("p 1000000000: refused in {:?}", run.took);
    let e = &run.stderr;
    assert!(
        e.starts_with("error: scene.nff:9:3: a polygon has at most 4096 corners"),
        "{e}"
    );
    assert!(
        e.contains("says it has 1000000000, and only 3 lines follow it"),
        "{e}"
    );
    assert_eq!(names_in(dir.path()), ["scene.nff"]);
}

/// The picture of `scene.toml` in `dir`, rendered into `name`.
fn picture(dir: &Path, name: &str) -> (Vec<u8>, String) {
    let run = raybook(dir, &["render", "scene.toml", "-q", "-o", name]);
    assert!(run.success, "{}", run.stderr);
    (std::fs::read(dir.join(name)).unwrap(), run.stderr)
}

#[test]
fn crlf_line_ends_and_a_byte_order_mark_give_the_same_picture() {
    let obj = format!("# a square\n{TRIANGLE}v 1 1 0\nvn 0 0 1\nf 1//1 2//1 4//1 3//1\n");
    let dir = with_mesh(|path| std::fs::write(path, &obj).unwrap());
    let (plain, _) = picture(dir.path(), "plain.png");
    let windows = format!("\u{FEFF}{}", obj.replace('\n', "\r\n"));
    std::fs::write(dir.path().join("mesh.obj"), windows).unwrap();
    let (read, _) = picture(dir.path(), "windows.png");
    assert_eq!(plain, read);
}

#[test]
fn a_missing_material_library_is_a_warning_that_names_both_files() {
    let obj = format!("mtllib gone.mtl\n{TRIANGLE}f 1 2 3\n");
    let dir = with_mesh(|path| std::fs::write(path, &obj).unwrap());
    let (_, stderr) = picture(dir.path(), "out.png");
    let warning = format!(
        "warning: scene.toml:{PATH_LINE}:{PATH_COLUMN}: objects[1].path: mesh.obj:1: \
         the material library `gone.mtl` is missing"
    );
    assert!(stderr.starts_with(&warning), "{stderr}");
}
