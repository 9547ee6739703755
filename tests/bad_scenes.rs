//! Every kind of bad scene file gets an error naming the file, the line, the
//! field path and what would be valid, before anything is rendered.

use raybook::scene_files::{self, SceneError};

/// A small valid scene; each test breaks one thing in it.
const GOOD: &str = r#"
[camera]
eye = [0.0, 1.0, 6.0]
look_at = [0.0, 0.5, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 64
height = 48

[materials.red]
color = [0.8, 0.1, 0.1]

[[lights]]
type = "point"
position = [2.0, 4.0, 3.0]
intensity = 40.0

[[objects]]
type = "sphere"
center = [0.0, 1.0, 0.0]
radius = 1.0
material = "red"

[[objects]]
type = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0
material = "red"

[[objects]]
type = "triangle"
vertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
material = "red"
"#;

/// Replaces the first `from` in the good scene by `to` and parses the result,
/// which must fail.
fn broken(from: &str, to: &str) -> SceneError {
    assert!(
        GOOD.contains(from),
        "test setup: {from:?} is not in the scene"
    );
    let text = GOOD.replacen(from, to, 1);
    let error =
        scene_files::parse(&text, "bad.toml").expect_err("the broken scene must be refused");
    println!("{error}\n");
    error
}

/// The line (1-based) of the first occurrence of `needle` after `from` is replaced.
fn line_of(needle: &str, from: &str, to: &str) -> u32 {
    let text = GOOD.replacen(from, to, 1);
    let offset = text.find(needle).expect("needle in scene");
    text[..offset].matches('\n').count() as u32 + 1
}

fn assert_error(e: &SceneError, line: u32, path: &str, words: &[&str]) {
    assert_eq!(e.file, "bad.toml");
    assert_eq!(e.line, Some(line), "line of: {e}");
    assert_eq!(e.path, path, "path of: {e}");
    for word in words {
        assert!(e.message.contains(word), "{word:?} missing from: {e}");
    }
    let shown = e.to_string();
    assert!(shown.starts_with(&format!("bad.toml:{line}:")), "{shown}");
    assert!(shown.contains(path), "{shown}");
}

#[test]
fn the_good_scene_parses() {
    let scene = scene_files::parse(GOOD, "good.toml").unwrap();
    assert_eq!(scene.objects.len(), 3);
    assert_eq!(scene.lights.len(), 1);
    assert_eq!(scene.materials[0].name, "red");
}

#[test]
fn unknown_key() {
    let e = broken("radius = 1.0", "radius = 1.0\nradus = 2.0");
    assert_error(
        &e,
        line_of("radus", "radius = 1.0", "radius = 1.0\nradus = 2.0"),
        "objects[0].radus",
        &["unknown field `radus`", "radius"],
    );
}

#[test]
fn unknown_key_in_a_table() {
    let e = broken("vfov = 40.0", "vfov = 40.0\nfov = 3");
    assert_error(&e, 7, "camera.fov", &["unknown field `fov`", "vfov"]);
}

#[test]
fn wrong_type() {
    let e = broken("radius = 1.0", "radius = \"big\"");
    assert_error(
        &e,
        line_of("radius", "", ""),
        "objects[0].radius",
        &["string", "f64"],
    );
}

#[test]
fn wrong_type_in_a_vector() {
    let e = broken("center = [0.0, 1.0, 0.0]", "center = [0.0, true, 0.0]");
    assert_error(
        &e,
        line_of("center", "", ""),
        "objects[0].center[1]",
        &["boolean"],
    );
}

#[test]
fn four_numbers_where_three_belong() {
    let e = broken("center = [0.0, 1.0, 0.0]", "center = [0.0, 1.0, 0.0, 7.0]");
    assert_error(
        &e,
        line_of("center", "", ""),
        "objects[0].center",
        &["three numbers", "found 4"],
    );
}

#[test]
fn two_numbers_where_three_belong() {
    let e = broken("eye = [0.0, 1.0, 6.0]", "eye = [0.0, 1.0]");
    assert_error(&e, 3, "camera.eye", &["three numbers", "found 2"]);
}

#[test]
fn nan() {
    let e = broken("radius = 1.0", "radius = nan");
    assert_error(
        &e,
        line_of("radius", "", ""),
        "objects[0].radius",
        &["finite", "NaN"],
    );
}

#[test]
fn infinity() {
    let e = broken("position = [2.0, 4.0, 3.0]", "position = [2.0, inf, 3.0]");
    assert_error(
        &e,
        line_of("position", "", ""),
        "lights[0].position[1]",
        &["finite", "inf"],
    );
}

#[test]
fn too_large_for_f32() {
    let e = broken("offset = 0.0", "offset = 1e300");
    assert_error(
        &e,
        line_of("offset", "", ""),
        "objects[1].offset",
        &["too large"],
    );
}

#[test]
fn negative_radius() {
    let e = broken("radius = 1.0", "radius = -1.0");
    assert_error(
        &e,
        line_of("radius", "", ""),
        "objects[0].radius",
        &["greater than 0", "-1"],
    );
}

#[test]
fn zero_radius() {
    let e = broken("radius = 1.0", "radius = 0");
    assert_error(
        &e,
        line_of("radius", "", ""),
        "objects[0].radius",
        &["greater than 0"],
    );
}

#[test]
fn zero_length_normal() {
    let e = broken("normal = [0.0, 1.0, 0.0]", "normal = [0.0, 0.0, 0.0]");
    assert_error(
        &e,
        line_of("normal", "", ""),
        "objects[1].normal",
        &["non-zero length"],
    );
}

#[test]
fn zero_length_up() {
    let e = broken("up = [0.0, 1.0, 0.0]", "up = [0, 0, 0]");
    assert_error(&e, 5, "camera.up", &["non-zero length"]);
}

#[test]
fn up_parallel_to_the_view_direction() {
    let e = broken("up = [0.0, 1.0, 0.0]", "up = [0.0, -0.5, -6.0]");
    assert_error(
        &e,
        5,
        "camera.up",
        &["parallel to the view direction", "[0, 1, 0]"],
    );
}

#[test]
fn eye_equals_look_at() {
    let e = broken("look_at = [0.0, 0.5, 0.0]", "look_at = [0.0, 1.0, 6.0]");
    assert_error(&e, 4, "camera.look_at", &["equals eye"]);
}

#[test]
fn zero_area_triangle() {
    let from = "vertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]";
    let e = broken(
        from,
        "vertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]",
    );
    assert_error(
        &e,
        line_of("vertices", "", ""),
        "objects[2].vertices",
        &["zero area"],
    );
}

#[test]
fn collinear_triangle() {
    let from = "vertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]";
    let e = broken(from, "vertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]");
    assert_error(
        &e,
        line_of("vertices", "", ""),
        "objects[2].vertices",
        &["on a line"],
    );
}

#[test]
fn triangle_with_two_vertices() {
    let from = "vertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]";
    let e = broken(from, "vertices = [[0, 0, 0], [1, 1, 1]]");
    assert_error(
        &e,
        line_of("vertices", "", ""),
        "objects[2].vertices",
        &["three vertices", "found 2"],
    );
}

#[test]
fn unknown_material() {
    let e = broken("material = \"red\"", "material = \"rde\"");
    assert_error(
        &e,
        line_of("material = \"red\"", "", ""),
        "objects[0].material",
        &["unknown material `rde`", "known materials: red"],
    );
}

#[test]
fn image_side_zero() {
    let e = broken("width = 64", "width = 0");
    assert_error(&e, 9, "image.width", &["from 1 to 16384", "found 0"]);
}

#[test]
fn image_side_too_large() {
    let e = broken("height = 48", "height = 16385");
    assert_error(&e, 10, "image.height", &["from 1 to 16384", "found 16385"]);
}

#[test]
fn unknown_object_type() {
    let e = broken("type = \"sphere\"", "type = \"cube\"");
    assert_error(
        &e,
        line_of("cube", "type = \"sphere\"", "type = \"cube\""),
        "objects[0].type",
        &["unknown variant `cube`", "sphere", "plane", "triangle"],
    );
}

#[test]
fn field_of_another_kind() {
    let e = broken("offset = 0.0", "offset = 0.0\nradius = 2.0");
    assert_eq!(e.path, "objects[1].radius");
    assert!(e.message.contains("a plane has no `radius`"), "{e}");
    assert!(e.message.contains("normal, offset"), "{e}");
    assert!(e.line.is_some());
}

#[test]
fn missing_field_of_a_kind() {
    let e = broken("radius = 1.0\n", "");
    assert_eq!(e.path, "objects[0]");
    assert!(e.message.contains("missing field `radius`"), "{e}");
    assert!(e.line.is_some());
}

#[test]
fn missing_table() {
    let e = broken("[image]\nwidth = 64\nheight = 48\n", "");
    assert!(e.message.contains("missing field `image`"), "{e}");
}

#[test]
fn not_toml_at_all() {
    let e = broken("vfov = 40.0", "vfov = = 40");
    assert_eq!(e.line, Some(6), "{e}");
}

#[test]
fn unreadable_file() {
    let e = scene_files::load("no/such/scene.toml").unwrap_err();
    assert_eq!(e.file, "no/such/scene.toml");
    assert!(e.message.contains("cannot read"), "{e}");
}

#[test]
fn mesh_whose_obj_file_is_missing() {
    let mesh = "type = \"mesh\"\npath = \"no/such/mesh.obj\"\nmaterial = \"red\"\n";
    let e = broken(
        "type = \"triangle\"\nvertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]\nmaterial = \"red\"\n",
        mesh,
    );
    let line = line_of(
        "path =",
        "type = \"triangle\"\nvertices = [[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]\nmaterial = \"red\"\n",
        mesh,
    );
    assert_error(
        &e,
        line,
        "objects[2].path",
        &["cannot read the OBJ file", "mesh.obj"],
    );
}

#[test]
fn mesh_without_a_path() {
    let e = broken(
        "type = \"sphere\"\ncenter = [0.0, 1.0, 0.0]\nradius = 1.0\n",
        "type = \"mesh\"\n",
    );
    assert_eq!(e.path, "objects[0]");
    assert!(
        e.message.contains("missing field `path`: a mesh needs it"),
        "{e}"
    );
}

#[test]
fn samples_that_are_not_a_square_number() {
    let e = broken("height = 48", "height = 48\nsamples = 5");
    assert_error(&e, 11, "image.samples", &["square number", "found 5"]);
}

#[test]
fn a_point_light_says_its_falloff_in_words() {
    let from = "intensity = 40.0";
    let e = broken(from, "intensity = 40.0\nfalloff = \"linear\"");
    assert_error(
        &e,
        line_of("falloff", from, "intensity = 40.0\nfalloff = \"linear\""),
        "lights[0].falloff",
        &["linear", "inverse_square", "none"],
    );
    let good = GOOD.replacen(from, "intensity = 40.0\nfalloff = \"none\"", 1);
    let scene = scene_files::parse(&good, "good.toml").unwrap();
    let raybook::toolkit::scene::Light::Point { falloff, .. } = scene.lights[0] else {
        panic!("a point light");
    };
    assert_eq!(falloff, raybook::toolkit::scene::Falloff::None);
}

/// The good scene's sphere replaced by a cone with `fields`.
fn cone(fields: &str) -> String {
    let sphere = "type = \"sphere\"\ncenter = [0.0, 1.0, 0.0]\nradius = 1.0";
    GOOD.replacen(sphere, &format!("type = \"cone\"\n{fields}"), 1)
}

const CONE: &str =
    "base = [0.0, 0.0, 0.0]\nbase_radius = 1.0\napex = [0.0, 2.0, 0.0]\napex_radius = 0.5";

#[test]
fn a_cone_is_read_and_its_ends_are_checked() {
    let scene = scene_files::parse(&cone(CONE), "good.toml").unwrap();
    let raybook::toolkit::scene::Shape::Cone {
        apex, apex_radius, ..
    } = scene.objects[0].shape
    else {
        panic!("a cone: {:?}", scene.objects[0]);
    };
    assert_eq!((apex.y, apex_radius), (2.0, 0.5));
    let refused = |fields: &str| {
        let e = scene_files::parse(&cone(fields), "bad.toml").expect_err("must be refused");
        println!("{e}\n");
        e
    };
    let e = refused(&CONE.replace("[0.0, 2.0, 0.0]", "[0.0, 0.0, 0.0]"));
    assert_error(&e, 20, "objects[0]", &["coincide"]);
    let e = refused(&CONE.replace("apex_radius = 0.5", "apex_radius = -0.5"));
    assert_error(&e, 25, "objects[0].apex_radius", &["-0.5"]);
    let e = refused(&CONE.replace("1.0\n", "0.0\n").replace("0.5", "0.0"));
    assert_error(&e, 20, "objects[0]", &["radius > 0"]);
    let e = refused(&CONE.replace("apex_radius = 0.5", ""));
    assert_error(&e, 20, "objects[0]", &["missing field `apex_radius`"]);
    let e = refused(&format!("{CONE}\nradius = 1.0"));
    assert_error(&e, 20, "objects[0].radius", &["a cone has no `radius`"]);
}
