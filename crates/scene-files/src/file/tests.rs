//! The file parsed in parts (head, then batches of objects) gives the same
//! scene, and the same errors, as the file parsed whole.

use super::parts::parse_in_parts;
use super::*;

const CAMERA: &str = r#"[camera]
eye = [0.0, 1.0, 6.0]
look_at = [0.0, 0.5, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 64
height = 48
"#;

/// After object `BATCH + 100`: a light between two runs of objects.
const LIGHTS: &str = r#"
[[lights]]
type = "point"
position = [2.0, 4.0, 3.0]
intensity = 40.0
"#;

/// At the end, after every object.
const MATERIALS: &str = r#"
[materials.red]
color = [0.8, 0.1, 0.1]

[materials.blue]
color = [0.1, 0.1, 0.8]
reflectance = [0.5, 0.5, 0.5]
"#;

const SPHERE: &str = "[[objects]]\ntype = \"sphere\"\ncenter = [0.0, 1.0, 0.0]\n\
                      radius = 1.0\nmaterial = \"red\"\n";
const PLANE: &str = "[[objects]]\ntype = \"plane\"\nnormal = [0.0, 1.0, 0.0]\n\
                     offset = 0.0\nmaterial = \"blue\"\nshadows = false\n";
const TRIANGLE: &str = "[[objects]]   # a comment\ntype = \"triangle\"\n\
                        vertices = [\n  [-1.0, 0.0, 0.0],\n  [1.0, 0.0, 0.0],\n  [0.0, 1.0, 0.0],\n]\n\
                        material = \"red\"\n";

/// Objects in the scene: more than two batches.
const OBJECTS: usize = 2 * outline::BATCH + 500;

/// The `i`th object's table: a sphere, a plane or a triangle, each
/// somewhere else.
fn object(i: usize) -> String {
    match i % 3 {
        0 => SPHERE.replace("center = [0.0", &format!("center = [{i}.0")),
        1 => PLANE.replace("offset = 0.0", &format!("offset = {i}.0")),
        _ => TRIANGLE.replace("[-1.0, 0.0, 0.0]", &format!("[-1.0, 0.0, {i}.0]")),
    }
}

/// The first object of the third batch that is a sphere (0), a plane (1)
/// or a triangle (2).
fn in_third_batch(kind: usize) -> usize {
    (2 * outline::BATCH + 5..).find(|i| i % 3 == kind).unwrap()
}

/// The mixed scene, with `from` replaced by `to` in the table of object
/// `broken` (`None`: in the head).
fn scene(broken: Option<usize>, from: &str, to: &str) -> String {
    let mut text = CAMERA.to_owned();
    for i in 0..OBJECTS {
        let table = match broken {
            Some(b) if b == i => broken_table(&object(i), from, to),
            _ => object(i),
        };
        text += &table;
        if i == outline::BATCH + 100 {
            text += LIGHTS;
        }
    }
    text += MATERIALS;
    match broken {
        None => broken_table(&text, from, to),
        Some(_) => text,
    }
}

/// `text` with the first `from` replaced by `to`.
fn broken_table(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "test setup: {from:?} not in {text}");
    text.replacen(from, to, 1)
}

/// Parses `text` both ways; they must agree.
fn both_ways(text: &str) -> Result<Scene, SceneError> {
    let outline = Outline::of(text);
    assert!(!outline.unusual);
    // Full batches, one cut short by the light: 0.., BATCH.., BATCH + 101.., ...
    assert_eq!(outline.batches[2].first, outline::BATCH + 101);
    let whole = parse_whole(text, "big.toml", None);
    let in_parts = parse_in_parts(text, "big.toml", &outline, None);
    assert_eq!(in_parts, whole);
    in_parts
}

#[test]
fn the_mixed_scene_is_the_same_scene_both_ways() {
    let scene = both_ways(&scene(None, "", "")).unwrap();
    assert_eq!(scene.objects.len(), OBJECTS);
    assert_eq!(scene.lights.len(), 1);
    assert_eq!(scene.materials.len(), 2);
}

/// An error in object `index` (of the third batch unless said), the same
/// both ways; returns it.
fn broken_object(index: usize, from: &str, to: &str) -> SceneError {
    let text = scene(Some(index), from, to);
    let error = both_ways(&text).expect_err("the broken scene must be refused");
    let prefix = format!("objects[{index}]");
    assert!(
        error.path.starts_with(&prefix) || error.path.is_empty(),
        "{error}"
    );
    error
}

/// The 1-based line of the first `needle` after the table of object `index` starts.
fn line_in_object(text: &str, index: usize, needle: &str) -> u32 {
    let tables: Vec<_> = text.match_indices("[[objects]]").collect();
    let start = tables[index].0;
    let offset = start + text[start..].find(needle).unwrap();
    text[..offset].matches('\n').count() as u32 + 1
}

#[test]
fn errors_in_the_third_batch_name_the_file_s_line_and_object() {
    let index = in_third_batch(2);
    let to = "[0.0, 1.0, 0.0],\n  [0.0, 1.0, 0.0],";
    let e = broken_object(index, "[0.0, 1.0, 0.0],", to);
    let text = scene(Some(index), "[0.0, 1.0, 0.0],", to);
    assert_eq!(e.path, format!("objects[{index}].vertices"));
    assert_eq!(e.line, Some(line_in_object(&text, index, "vertices")));
    assert!(e.message.contains("three vertices"), "{e}");
}

#[test]
fn errors_in_objects_are_the_same_both_ways() {
    let (sphere, plane) = (in_third_batch(0), in_third_batch(1));
    let cases = [
        (sphere, "radius = 1.0", "radius = 1.0\nradus = 2.0"),
        (sphere, "radius = 1.0", "radius = \"big\""),
        (sphere, "radius = 1.0", "radius = -1.0"),
        (sphere, "radius = 1.0", "radius = nan"),
        (sphere, "radius = 1.0", "radius = = 1"),
        (sphere, "radius = 1.0", "radius = 1.0\nradius = 2.0"),
        (sphere, "radius = 1.0\n", ""),
        (sphere, ", 1.0, ", ", true, "),
        (sphere, "center = [", "center = [7.0, "),
        (sphere, "material = \"red\"", "material = \"rde\""),
        (sphere, "type = \"sphere\"", "type = \"cube\""),
        (sphere, "type = \"sphere\"\n", ""),
        (plane, "offset = ", "radius = 2.0\noffset = "),
        (plane, "normal = [0.0, 1.0, 0.0]", "normal = [0, 0, 0]"),
        (plane, "shadows = false", "shadows = \"no\""),
        (3, "radius = 1.0", "radius = 0"),
        (OBJECTS - 1, "radius = 1.0", "radius = [1.0"),
    ];
    for (index, from, to) in cases {
        let e = broken_object(index, from, to);
        println!("{e}\n");
        assert!(e.line.is_some(), "{e}");
    }
}

#[test]
fn errors_in_the_head_are_the_same_both_ways() {
    let cases = [
        ("vfov = 40.0", "vfov = 40.0\nfov = 3"),
        ("eye = [0.0, 1.0, 6.0]", "eye = [0.0, 1.0]"),
        ("up = [0.0, 1.0, 0.0]", "up = [0.0, -0.5, -6.0]"),
        ("width = 64", "width = 0"),
        ("position = [2.0, 4.0, 3.0]", "position = [2.0, inf, 3.0]"),
        ("intensity = 40.0", "intensity = 40.0\nradius = 1"),
        ("color = [0.1, 0.1, 0.8]", "color = [0.1, 0.1, 1.8]"),
        (
            "reflectance = [0.5, 0.5, 0.5]",
            "reflectance = [0.5, 0.5, 0.5",
        ),
        ("[materials.blue]", "[materials.red]"),
    ];
    for (from, to) in cases {
        let text = scene(None, from, to);
        let e = both_ways(&text).expect_err("the broken scene must be refused");
        println!("{e}\n");
        let needle_line = text[..text.find(to).unwrap()].matches('\n').count() as u32 + 1;
        assert!(e.line >= Some(needle_line), "{needle_line}: {e}");
    }
}

#[test]
fn renumbering_moves_only_the_object_index() {
    assert_eq!(renumber("objects[3].radius", 1024), "objects[1027].radius");
    assert_eq!(renumber("objects[0]", 5), "objects[5]");
    assert_eq!(renumber("objects", 5), "objects");
    assert_eq!(renumber("lights[2].color", 5), "lights[2].color");
    assert_eq!(renumber("", 5), "");
}

#[test]
fn unusual_files_are_parsed_whole() {
    for text in [
        format!("objects = []\n{CAMERA}{SPHERE}{MATERIALS}"),
        format!("{CAMERA}{SPHERE}[objects.extra]\n{MATERIALS}"),
    ] {
        assert!(Outline::of(&text).unusual);
        let e = parse(&text, "odd.toml", None).expect_err("objects twice");
        assert_eq!(e, parse_whole(&text, "odd.toml", None).unwrap_err());
    }
}

#[test]
fn a_scene_larger_than_the_limit_is_refused_before_parsing() {
    // Not TOML after the headers: a parse would fail, so the refusal came first.
    let text = format!("{CAMERA}{}", "[[objects]]\nradius = = =\n".repeat(1000));
    let limit = MemoryLimit {
        bytes: 100_000,
        source: "a test's limit".into(),
    };
    let e = parse(&text, "big.toml", Some(&limit)).unwrap_err();
    assert_eq!(e.file, "big.toml");
    assert_eq!(e.line, None);
    for words in ["1000 objects", "a test's limit", "97.7 KiB is available"] {
        assert!(e.message.contains(words), "{words:?} not in {e}");
    }
    let need = memory::size(text.len() as u64 + 1000 * BYTES_PER_OBJECT);
    assert!(
        e.message.contains(&format!("about {need} of memory")),
        "{e}"
    );
}

#[test]
fn a_file_of_nothing_but_objects_is_refused_for_its_missing_head() {
    // Its head (everything but the [[objects]] tables) is empty: the error
    // is placed in the file, not lost, and nothing panics.
    let text =
        "[[objects]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"red\"\n";
    let error = crate::parse(text, "objects.toml").unwrap_err();
    assert_eq!(error.file, "objects.toml");
    assert!(error.message.contains("camera"), "{error}");
}
