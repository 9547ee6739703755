//! Large scenes load object by object: a generated scene of 20,000 spheres
//! (many of the loader's batches) loads completely and in order, an
//! error deep inside it names its own line and object, and a scene larger
//! than the memory there is is refused before it is parsed; a mesh whose
//! triangles need more than there is, as its OBJ file is read.
//!
//! Time and memory are measured by hand (see "Large scenes" in book/appendix/performance.md),
//! not here: these tests check what can fail on any machine.

use scene_files::SceneError;
use scene_files::{BYTES_PER_OBJECT, MemoryLimit, Shape, write_sphere_cloud};

const SPHERES: usize = 20_000;

/// The generated scene's text.
fn cloud() -> String {
    let mut text = Vec::new();
    write_sphere_cloud(&mut text, SPHERES).unwrap();
    String::from_utf8(text).unwrap()
}

/// The centres as the text writes them, in order.
fn centres_in(text: &str) -> Vec<[f32; 3]> {
    let lines = text.lines().filter_map(|l| l.strip_prefix("center = ["));
    let parse = |l: &str| -> [f32; 3] {
        let numbers: Vec<f32> = (l.trim_end_matches(']').split(", "))
            .map(|x| x.parse().unwrap())
            .collect();
        numbers.try_into().unwrap()
    };
    lines.map(parse).collect()
}

fn no_limit() -> Option<&'static MemoryLimit> {
    None
}

#[test]
fn every_sphere_loads_in_file_order() {
    let text = cloud();
    let scene = scene_files::parse_within(&text, "cloud.toml", no_limit()).unwrap();
    assert_eq!(scene.objects.len(), SPHERES);
    assert_eq!(scene.lights.len(), 2);
    assert_eq!(scene.materials.len(), 1);
    let centres = centres_in(&text);
    assert_eq!(centres.len(), SPHERES);
    for (object, centre) in scene.objects.iter().zip(centres) {
        assert_eq!(
            object.shape,
            Shape::Sphere {
                center: centre.into(),
                radius: 0.01,
            }
        );
    }
}

/// The cloud with the `n`th `radius = ...` line replaced by `to`: the error,
/// which must be on that line.
fn with_radius(n: usize, to: &str) -> SceneError {
    let text = cloud();
    let mut lines: Vec<&str> = text.lines().collect();
    let radius = (lines.iter().enumerate())
        .filter(|(_, l)| l.starts_with("radius = "))
        .nth(n)
        .unwrap()
        .0;
    lines[radius] = to;
    let text = lines.join("\n");
    let error = scene_files::parse_within(&text, "cloud.toml", no_limit()).unwrap_err();
    assert_eq!(error.line, Some(radius as u32 + 1), "{error}");
    error
}

#[test]
fn an_error_deep_in_the_file_names_its_line_and_object() {
    let n = 2_500 + 17; // past several of the loader's batches
    let e = with_radius(n, "radius = -0.5");
    assert_eq!(e.file, "cloud.toml");
    assert_eq!(e.path, format!("objects[{n}].radius"));
    assert!(e.message.contains("greater than 0"), "{e}");
    assert_eq!(e.source_line.as_deref(), Some("radius = -0.5"));
}

#[test]
fn a_syntax_error_deep_in_the_file_names_its_line() {
    let e = with_radius(SPHERES - 1, "radius = = 0.5");
    assert_eq!(e.path, "");
    assert!(e.to_string().starts_with("cloud.toml:"), "{e}");
}

#[test]
fn a_scene_larger_than_the_memory_there_is_is_refused() {
    let text = cloud();
    let need = text.len() as u64 + SPHERES as u64 * BYTES_PER_OBJECT;
    let limit = MemoryLimit {
        bytes: need - 1,
        source: "the test's limit".into(),
    };
    let e = scene_files::parse_within(&text, "cloud.toml", Some(&limit)).unwrap_err();
    println!("{e}");
    assert_eq!(e.file, "cloud.toml");
    for words in ["20000 objects", "the test's limit", "would need about"] {
        assert!(e.message.contains(words), "{words:?} not in {e}");
    }
    let enough = MemoryLimit {
        bytes: need,
        ..limit
    };
    assert!(scene_files::parse_within(&text, "cloud.toml", Some(&enough)).is_ok());
}

#[test]
fn this_machine_s_memory_is_known_or_not_checked() {
    // Where /proc/meminfo can be read, the limit is positive; elsewhere there
    // is none, and nothing is refused.
    if let Some(limit) = MemoryLimit::of_machine() {
        assert!(limit.bytes > 0, "{limit:?}");
        assert!(!limit.source.is_empty());
    }
    assert!(scene_files::parse(&cloud(), "cloud.toml").is_ok());
}

#[test]
fn a_file_larger_than_the_memory_there_is_is_not_even_read() {
    let text = cloud();
    let file = tempfile::NamedTempFile::new().unwrap();
    std::fs::write(file.path(), &text).unwrap();
    let limit = |bytes| MemoryLimit {
        bytes,
        source: "the test's limit".into(),
    };
    let file_size = text.len() as u64;
    let e = scene_files::load_within(file.path(), Some(&limit(file_size - 1))).unwrap_err();
    assert!(e.message.contains("the file is 2.0 MiB"), "{e}");
    assert!(e.message.contains("cannot be loaded"), "{e}");
    // Room for the text, not for the objects: refused after counting them.
    let e = scene_files::load_within(file.path(), Some(&limit(file_size + 1))).unwrap_err();
    assert!(e.message.contains("20000 objects"), "{e}");
    assert!(scene_files::load_within(file.path(), None).is_ok());
}

/// Two meshes of 20,000 triangles each, named by one scene in `dir` (so
/// they take from one budget): the scene's path.
fn two_meshes(dir: &std::path::Path) -> std::path::PathBuf {
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj += &"f 1 2 3\n".repeat(20_000);
    std::fs::write(dir.join("mesh.obj"), obj).unwrap();
    let mesh = "[[objects]]\ntype = \"mesh\"\npath = \"mesh.obj\"\nmaterial = \"grey\"\n";
    let mut text = Vec::new();
    write_sphere_cloud(&mut text, 0).unwrap();
    let text = format!("{}{mesh}{mesh}", String::from_utf8(text).unwrap());
    std::fs::write(dir.join("meshes.toml"), text).unwrap();
    dir.join("meshes.toml")
}

#[test]
fn meshes_whose_triangles_need_more_than_the_memory_there_is_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let scene = two_meshes(dir.path());
    let triangles = 2 * 20_000 * BYTES_PER_OBJECT;
    let limit = |bytes| MemoryLimit {
        bytes,
        source: "the test's limit".into(),
    };
    // Room for one mesh's triangles, not for both.
    let e = scene_files::load_within(&scene, Some(&limit(triangles * 3 / 4))).unwrap_err();
    println!("{e}");
    assert!(e.path.ends_with("].path"), "{e}");
    let mesh = dir.path().join("mesh.obj").display().to_string();
    assert!(e.message.starts_with(&format!("{mesh}:")), "{e}");
    for words in [
        "the mesh is too large for the memory",
        "of the 156.3 KiB file",
        "triangles with area",
        "448 bytes a triangle",
        "is available (the test's limit)",
    ] {
        assert!(e.message.contains(words), "{words:?} not in {e}");
    }
    assert!(scene_files::load_within(&scene, Some(&limit(2 * triangles))).is_ok());
}
