//! The OBJ reader: what it reads, what it refuses and where.

use super::*;
use crate::Vec3;

/// The mesh of OBJ `text`, without a memory limit.
fn mesh(text: &str) -> Result<Mesh, SceneError> {
    read(text.as_bytes(), "m.obj", None)
}

/// The error for OBJ `text`, which must be refused at `line` (and `column`).
fn refused(text: &str, line: u32, column: u32, words: &[&str]) -> SceneError {
    let e = mesh(text).expect_err("must be refused");
    assert_eq!((e.line, e.column), (Some(line), Some(column)), "{e}");
    assert!(
        e.headline()
            .starts_with(&format!("m.obj:{line}:{column}: ")),
        "{e}"
    );
    for word in words {
        assert!(e.message.contains(word), "{word:?} missing from: {e}");
    }
    e
}

const SQUARE: &str = "# a unit square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
                      vn 0 0 1\nvt 0 0\nf 1 2 3 4\nf 1//1 2//1 3//1\n";

#[test]
fn a_quad_is_cut_into_a_fan_and_normals_make_it_smooth() {
    let shapes = mesh(SQUARE).unwrap().shapes;
    let [x, y, o] = [Vec3::X, Vec3::Y, Vec3::ZERO];
    assert_eq!(
        shapes,
        [
            Shape::Triangle {
                vertices: [o, x, x + y]
            },
            Shape::Triangle {
                vertices: [o, x + y, y]
            },
            Shape::SmoothTriangle {
                vertices: [o, x, x + y],
                normals: [Vec3::Z; 3],
            },
        ]
    );
}

#[test]
fn crlf_line_ends_and_a_byte_order_mark_read_as_plain_lines() {
    let crlf = format!("\u{FEFF}{}", SQUARE.replace('\n', "\r\n"));
    assert_eq!(mesh(&crlf), mesh(SQUARE));
    let e = mesh(&format!(
        "\u{FEFF}{}f 1 2 9\r\n",
        SQUARE.replace('\n', "\r\n")
    ))
    .unwrap_err();
    assert_eq!(e.line, Some(10), "{e}");
    assert_eq!(e.source_line.as_deref(), Some("f 1 2 9"));
}

#[test]
fn every_corner_form_and_relative_indices_give_the_same_triangle() {
    let head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n";
    let forms = ["f 1 2 3", "f 1/1 2/2 3/3", "f -3 -2 -1", "f -3/-3 2/-2 3/3"];
    let triangle = mesh(&format!("{head}{}\n", forms[0])).unwrap();
    for face in &forms[1..] {
        assert_eq!(
            mesh(&format!("{head}{face}\n")).unwrap(),
            triangle,
            "{face}"
        );
    }
    let smooth = mesh(&format!("{head}f 1/1/1 2/2/1 3//-1\n")).unwrap();
    assert!(matches!(smooth.shapes[0], Shape::SmoothTriangle { .. }));
}

#[test]
fn faces_without_area_are_left_out_and_points_and_lines_skipped() {
    let text = "o thing\ng part\ns 1\nusemtl copper\nv 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n\
                f 1 2 3\nf 1 1 4\nl 1 2\np 1\nf 1 2 4\n";
    let shapes = mesh(text).unwrap().shapes;
    assert_eq!(shapes.len(), 1);
}

#[test]
fn a_file_with_nothing_to_draw_is_refused_and_says_why() {
    let cases = [
        ("", "is empty"),
        ("# nothing\n\nv 0 0 0\n", "no faces"),
        (
            "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 1\n",
            "each of its 2 faces",
        ),
    ];
    for (text, words) in cases {
        let e = mesh(text).unwrap_err();
        assert_eq!(e.line, None, "{e}");
        assert!(e.message.contains(words), "{words:?} missing from: {e}");
        assert!(e.to_string().starts_with("m.obj: "), "{e}");
    }
}

#[test]
fn faces_that_name_missing_vertices_are_refused_where_they_are() {
    let square = SQUARE.lines().count() as u32;
    refused(
        &format!("{SQUARE}f 1 2 5\n"),
        square + 1,
        7,
        &["vertex 5", "4 v lines"],
    );
    refused(
        &format!("{SQUARE}f 1 -5 2\n"),
        square + 1,
        5,
        &["vertex -5", "5 back"],
    );
    refused(&format!("{SQUARE}f 0 1 2\n"), square + 1, 3, &["from 1"]);
    refused(
        &format!("{SQUARE}f 1//2 2 3\n"),
        square + 1,
        3,
        &["normal 2", "1 vn lines"],
    );
    refused(
        &format!("{SQUARE}f 1/5 2 3\n"),
        square + 1,
        3,
        &["texture coordinate 5"],
    );
    refused(
        &format!("{SQUARE}f 1 2\n"),
        square + 1,
        3,
        &["3 corners or more, found 2"],
    );
    refused("f 1 2 3\nv 0 0 0\n", 1, 3, &["vertex 1", "0 v lines above"]);
}

#[test]
fn coordinates_that_are_not_finite_f32_are_refused() {
    refused("v 0 nan 0\n", 1, 5, &["finite", "nan"]);
    refused("v 0 0 0\nvn inf 0 0\n", 2, 4, &["finite", "inf"]);
    refused("v 1e39 0 0\n", 1, 3, &["too large", "f32"]);
    refused("v 0 0 zero\n", 1, 7, &["expected a number", "zero"]);
    refused("v 0 0\n", 1, 3, &["`v x y z`", "found 2"]);
    refused("v 0 0 0 1 NaN 0\n", 1, 11, &["finite"]);
}

#[test]
fn what_obj_does_not_have_is_refused() {
    refused(
        "v 0 0 0\nvertex 1 2 3\n",
        2,
        1,
        &["unknown statement `vertex`"],
    );
    let e = refused("\u{7f}ELF\u{2}\u{1}", 1, 1, &["0x7F", "binary"]);
    assert!(e.to_string().contains("m.obj:1:1"), "{e}");
    refused(
        "v 0 0 0\nv 1 0 0\nv 1\u{0} 0 0",
        3,
        4,
        &["0x00 is not text"],
    );
}

#[test]
fn a_binary_file_is_refused_on_its_first_line() {
    let bytes: Vec<u8> = (0..=255u8).cycle().take(4096).collect();
    let e = read(&bytes[..], "b.obj", None).unwrap_err();
    assert_eq!(e.line, Some(1), "{e}");
    assert!(e.message.contains("binary"), "{e}");
}

#[test]
fn a_mesh_too_large_for_the_limit_is_refused_at_the_line_where_it_becomes_so() {
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    text += &"f 1 2 3\n".repeat(10_000);
    let limit = MemoryLimit {
        bytes: 2 << 20,
        source: "a test".into(),
    };
    let e = read(text.as_bytes(), "big.obj", Some(&limit)).unwrap_err();
    // Taken from the budget a MiB at a time, the triangles pass the limit
    // within a MiB's triangles after it.
    let triangles = e.line.unwrap() as u64 - 3;
    let (at_limit, a_mib) = (limit.bytes / BYTES_PER_OBJECT, (1 << 20) / BYTES_PER_OBJECT);
    assert!(
        (at_limit..=at_limit + a_mib + 1).contains(&triangles),
        "{e}"
    );
    for words in [
        &format!("{triangles} triangles"),
        "2.0 MiB is available (a test)",
    ] {
        assert!(e.message.contains(words), "{words:?} missing from: {e}");
    }
    assert!(read(text.as_bytes(), "big.obj", None).is_ok());
}

#[test]
fn a_missing_material_library_is_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.obj");
    std::fs::write(&path, format!("mtllib here.mtl gone.mtl\n{SQUARE}")).unwrap();
    std::fs::write(dir.path().join("here.mtl"), "newmtl x\n").unwrap();
    let mesh = load(&path, None).unwrap();
    assert_eq!(mesh.shapes.len(), 3);
    assert_eq!(mesh.warnings.len(), 1, "{:?}", mesh.warnings);
    let warning = &mesh.warnings[0];
    assert!(warning.ends_with("m.obj:1: the material library `gone.mtl` is missing; the scene's material colours the mesh, so nothing is lost"), "{warning}");
}
