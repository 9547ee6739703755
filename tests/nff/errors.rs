//! Bad files are refused with the line, by the rules of TOML scenes, and a
//! scene too large for the memory before it is converted.

use raybook::nff;
use raybook::scene_files;

use super::{GOOD, broken, with_line};

#[test]
fn bad_files_are_refused_with_the_line() {
    let cases = [
        (13, "s 0 0 0 -1", 13, "radius"),
        (13, "s 0 0 zero 1", 13, "`zero`"),
        (13, "s 0 0 0", 13, "found 3 numbers"),
        (13, "c 0 0 0 1 0 0 1", 13, "found 7 numbers"),
        (13, "c 0 0 0 1 0 0 0 1", 13, "coincide"),
        (13, "c 0 0 0 -1 0 0 1 1", 13, "negative only if both are"),
        (13, "c 0 0 0 1 0 0 1 -1", 13, "negative only if both are"),
        (13, "c 0 0 0 0 0 0 1 0", 13, "radius > 0"),
        (13, "c 0 0 0 nan 0 0 1 1", 13, "`nan`"),
        (13, "cube 1", 13, "unknown entity `cube`"),
        (12, "f 1 0.5 0.25 1.8 0.4 30 0.5 1.5", 12, "Kd"),
        (
            12,
            "f 1 0.5 0.25 0.8 0.4 30 0.5 0",
            12,
            "index of refraction",
        ),
        (12, "f 2 0.5 0.25 0.8 0.4 30 0.5 1.5", 12, "colour"),
        (10, "l 4 3", 10, "l x y z"),
        (14, "p 2", 14, "3 or more"),
        (5, "at 0 -5 1", 5, "looks nowhere"),
        (6, "up 0 5 -1", 6, "parallel to the view direction"),
        (6, "up 0 0 0", 6, "non-zero length"),
        (6, "angle 45", 7, "`angle` twice"),
        (7, "angle 180", 7, "field of view"),
        (7, "angle 0", 7, "strictly between 0 and 180"),
        (9, "resolution 0 48", 9, "from 1 to 16384"),
        (9, "resolution 64 16385", 9, "found 16385"),
        (9, "resolution 64 47.5", 9, "whole number"),
        (4, "form 0 -5 1", 4, "expected a viewpoint line"),
        (21, "0 1 2 0 0 0", 21, "normal must not be zero"),
    ];
    for (line, text, error_line, words) in cases {
        let e = broken(&with_line(line, text));
        assert_eq!(e.line, Some(error_line), "{text}: {e}");
        assert!(e.message.contains(words), "{text}: {e}");
    }
}

#[test]
fn the_viewpoint_is_checked_by_the_rules_of_toml_scenes() {
    // The same words as a TOML scene's, with NFF's names and the line's field.
    let e = broken(&with_line(5, "at 0 -5 1"));
    assert_eq!(e.path, "v.at");
    assert!(e.message.contains("`at` equals `from`"), "{e}");
    let e = broken(&with_line(9, "resolution 64 0"));
    assert_eq!((e.path.as_str(), e.column), ("v.resolution", Some(15)));
    let toml = "[camera]\neye = [0, -5, 1]\nlook_at = [0, 0, 0]\nup = [0, 0, 1]\nvfov = 45\n\
                [image]\nwidth = 64\nheight = 0\n";
    let same = scene_files::parse(toml, "bad.toml").unwrap_err();
    assert_eq!(e.message, same.message);
    let e = broken(&with_line(7, "angle 200"));
    assert_eq!(e.path, "v.angle");
    let toml = toml.replace("vfov = 45", "vfov = 200");
    assert_eq!(
        e.message,
        scene_files::parse(&toml, "bad.toml").unwrap_err().message
    );
}

#[test]
fn structural_mistakes_are_refused_too() {
    let e = broken(&GOOD.replace("f 1 0.5 0.25 0.8 0.4 30 0.5 1.5\n", ""));
    assert!(e.message.contains("needs a material"), "{e}");
    let e = broken(&GOOD[..GOOD.find("2 2 -1").unwrap()]);
    assert!(e.message.contains("corner 3 of 4"), "{e}");
    let e = broken("f 1 1 1 1 0 1 0 1\ns 0 0 0 1\n");
    assert!(e.message.contains("no viewpoint"), "{e}");
    let e = broken("p 3\n0 0 0\n1 1 1\n2 2 2\n");
    assert!(e.message.contains("zero area"), "{e}");
}

#[test]
fn a_cone_beyond_f32_is_refused_not_drawn_with_nan() {
    // The axis is shorter than f32 can divide by: the tilt overflows.
    let e = broken(&with_line(13, "c 0 0 0 1 0 0 1e-44 2"));
    assert!(e.message.contains("too short for its radii"), "{e}");
}

/// An NFF scene that would need more memory than the machine has is
/// refused with a clear message before it is converted, as a TOML scene
/// is; the same scene within a sufficient limit loads.
#[test]
fn an_nff_scene_too_large_for_the_memory_is_refused_before_it_is_converted() {
    // Broken after GOOD (a sphere of three numbers): converting it would
    // fail on the next line, so a refusal without a line came first.
    let text = format!("{GOOD}{}", "s 1 2 3\n".repeat(1000));
    let lines = text.lines().count();
    let limit = raybook::scene_files::MemoryLimit {
        bytes: 200_000,
        source: "a test's limit".into(),
    };
    let e = nff::parse_within(&text, "big.nff", Some(&limit)).unwrap_err();
    assert_eq!((e.file.as_str(), e.line), ("big.nff", None), "{e}");
    for words in [
        &format!("up to {lines} objects (one a line)"),
        "a test's limit",
        "195.3 KiB is available",
        "render a smaller scene",
    ] {
        assert!(e.message.contains(words), "{words:?} not in {e}");
    }
    let within = raybook::scene_files::MemoryLimit {
        bytes: 10_000_000,
        source: "a test's limit".into(),
    };
    let e = nff::parse_within(&text, "big.nff", Some(&within)).unwrap_err();
    let first_broken = GOOD.lines().count() as u32 + 1;
    assert_eq!(
        e.line,
        Some(first_broken),
        "converted: the broken sphere is found: {e}"
    );
    assert!(nff::parse_within(GOOD, "good.nff", Some(&limit)).is_ok());
}
