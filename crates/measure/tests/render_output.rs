//! `raybook render -o NAME` writes the format that NAME's extension says,
//! refuses an extension it cannot write before rendering anything, and
//! writes only into a regular file: never into a directory, a named pipe
//! or a device.

mod common;

use std::path::Path;

use common::{names_in, raybook};
use raybook::workbench::snapshot::workspace_root;

/// `raybook render` of chapter 3's default scene, 8×6 pixels, into `out`.
fn render_into(dir: &Path, out: &str) -> common::Run {
    let scene = workspace_root().join("chapters/03-lambert/scenes/default.toml");
    let scene = scene.to_str().unwrap();
    let args = [
        "render", scene, "--width", "8", "--height", "6", "-q", "-o", out,
    ];
    raybook(dir, &args)
}

#[test]
fn the_extension_names_the_format() {
    let dir = tempfile::tempdir().unwrap();
    let starts: [(&str, &[u8]); 5] = [
        ("out.png", b"\x89PNG"),
        ("out.ppm", b"P6\n8 6 255\n"),
        ("OUT.PNM", b"P6\n8 6 255\n"),
        ("out.bmp", b"BM"),
        ("out.tga", b"\0\0\x0a"),
    ];
    for (name, start) in starts {
        let run = render_into(dir.path(), name);
        assert!(run.success, "{name}: {}", run.stderr);
        assert!(
            run.stdout.contains(&format!("wrote {name} (8×6 pixels)")),
            "{}",
            run.stdout
        );
        let bytes = std::fs::read(dir.path().join(name)).unwrap();
        assert!(bytes.starts_with(start), "{name} starts {:?}", &bytes[..12]);
    }
    let ppm = std::fs::read(dir.path().join("out.ppm")).unwrap();
    assert_eq!(ppm.len(), "P6\n8 6 255\n".len() + 8 * 6 * 3);
}

#[test]
fn an_extension_it_cannot_write_is_refused_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    for (name, words) in [
        (
            "out.jpg",
            "out.jpg: raybook cannot write .jpg pictures; end it in .png, .ppm",
        ),
        (
            "out",
            "out: the name has no extension to say the picture's format; end it in .png, .ppm",
        ),
    ] {
        let run = render_into(dir.path(), name);
        assert!(!run.success);
        assert_eq!(
            run.stderr,
            format!("error: -o {words} (or .pnm), .bmp or .tga\n")
        );
        assert_eq!(run.stdout, "", "nothing rendered");
    }
    assert!(names_in(dir.path()).is_empty());
}

#[test]
fn a_picture_replaces_a_regular_file_whole() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("old.png");
    std::fs::write(&out, "an older picture").unwrap();
    assert!(render_into(dir.path(), "old.png").success);
    assert!(std::fs::read(&out).unwrap().starts_with(b"\x89PNG"));
    assert_eq!(
        names_in(dir.path()),
        ["old.png"],
        "no temporary file is left"
    );
}

#[test]
fn a_directory_is_not_written_into() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("folder.png")).unwrap();
    let run = render_into(dir.path(), "folder.png");
    assert!(!run.success);
    let refusal = "error: -o folder.png: it is a directory (name a file in it, such as \
                   DIR/render.png), not a regular file";
    assert!(run.stderr.starts_with(refusal), "{}", run.stderr);
    assert!(names_in(&dir.path().join("folder.png")).is_empty());
}

#[cfg(unix)]
#[test]
fn a_pipe_or_a_device_is_not_written_into_nor_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let pipe = dir.path().join("pipe.png");
    common::fifo(&pipe);
    let run = render_into(dir.path(), "pipe.png");
    assert!(!run.success);
    assert!(
        run.stderr
            .contains("it is a named pipe (FIFO), not a regular file"),
        "{}",
        run.stderr
    );
    assert!(
        std::fs::symlink_metadata(&pipe)
            .unwrap()
            .file_type()
            .is_fifo(),
        "still a pipe"
    );
    for device in ["/dev/null", "/dev/zero"] {
        let run = render_into(dir.path(), device);
        let refusal = format!("error: -o {device}: it is a device, not a regular file");
        assert!(run.stderr.starts_with(&refusal), "{}", run.stderr);
    }
    assert!(
        std::fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device()
    );
}

#[cfg(unix)]
#[test]
fn a_link_to_a_picture_stays_a_link_to_the_new_picture() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("picture.png"), "an older picture").unwrap();
    std::os::unix::fs::symlink("picture.png", dir.path().join("latest.png")).unwrap();
    let run = render_into(dir.path(), "latest.png");
    assert!(run.success, "{}", run.stderr);
    let link = std::fs::read_link(dir.path().join("latest.png")).unwrap();
    assert_eq!(link, Path::new("picture.png"));
    let picture = std::fs::read(dir.path().join("picture.png")).unwrap();
    assert!(picture.starts_with(b"\x89PNG"));
}

#[test]
fn the_help_says_which_formats_and_files_it_writes() {
    let run = raybook(Path::new("."), &["render", "--help"]);
    for words in [
        ".png, .ppm (or .pnm), .bmp or .tga",
        "(even /dev/null) is refused",
    ] {
        assert!(
            run.stdout.contains(words),
            "{words:?} missing from {}",
            run.stdout
        );
    }
}

#[test]
fn linear_writes_the_values_the_png_rounds() {
    let dir = tempfile::tempdir().unwrap();
    let scene = workspace_root().join("chapters/03-lambert/scenes/default.toml");
    let args = [
        "render",
        scene.to_str().unwrap(),
        "--width",
        "8",
        "--height",
        "6",
        "-q",
        "-o",
        "out.png",
        "--linear",
        "out.pfm",
    ];
    let run = raybook(dir.path(), &args);
    assert!(run.success, "{}", run.stderr);
    let pfm = std::fs::read(dir.path().join("out.pfm")).unwrap();
    let linear = raybook::workbench::pfm::decode(&pfm).unwrap();
    assert_eq!((linear.width, linear.height), (8, 6));
    let png = image::open(dir.path().join("out.png")).unwrap().to_rgb8();
    assert_eq!(
        linear.to_rgb8(),
        png,
        "the PNG is the linear values, rounded"
    );
    assert!(
        linear
            .pixels
            .iter()
            .any(|c| c.x != (c.x * 255.0).round() / 255.0),
        "values between the 8-bit steps: not read back from the PNG"
    );
}
