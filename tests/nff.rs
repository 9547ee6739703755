//! NFF import: the SPD scenes load, entities map onto raybook's scene, bad
//! files are refused with the line, and the BVH sees what brute force sees.

use raybook::nff;
use raybook::toolkit::scene::{Light, Shape};
use raybook::toolkit::snapshot::workspace_root;
use raybook::toolkit::{Color, Scene, SceneError, Vec3};
use raybook::tracer::{Termination, World, render_complete};

/// A small scene using every entity raybook reads.
const GOOD: &str = "# a comment
b 0.1 0.2 0.3
v
from 0 -5 1
at 0 0 0
up 0 0 1
angle 45
hither 0.01
resolution 64 48
l 4 3 2
l 1 -4 4 0.5 0.5 0.5
f 1 0.5 0.25 0.8 0.4 30 0.5 1.5
s 0 0 0 1   # a sphere
p 4
-2 -2 -1
2 -2 -1
2 2 -1
-2 2 -1
pp 3
0 0 2 0 0 1
1 0 2 0 0 1
0 1 2 0 0.6 0.8
";

fn spd(name: &str) -> std::path::PathBuf {
    workspace_root().join("scenes/spd").join(name)
}

#[test]
fn every_entity_maps_onto_the_scene() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    assert_eq!(scene.image.background, Vec3::new(0.1, 0.2, 0.3));
    assert_eq!((scene.image.width, scene.image.height), (64, 48));
    assert_eq!(scene.camera.eye, Vec3::new(0.0, -5.0, 1.0));
    // 45° between the centres of the first and last rows of 48: a little
    // more between the edges.
    let half = (22.5f32.to_radians().tan() / (1.0 - 1.0 / 48.0))
        .atan()
        .to_degrees();
    assert!((scene.camera.vfov_degrees - 2.0 * half).abs() < 1e-4);
    let m = &scene.materials[0];
    assert_eq!(m.color, 0.8 * Color::new(1.0, 0.5, 0.25));
    assert_eq!(m.reflectance, Color::splat(0.4));
    assert_eq!((m.specular, m.shininess), (0.4, 30.0));
    assert_eq!((m.transparency, m.ior), (0.5, 1.5));
    // One sphere, the square as two triangles, the patch as one smooth one.
    assert_eq!(scene.objects.len(), 4);
    assert!(matches!(
        scene.objects[0].shape,
        Shape::Sphere { radius: 1.0, .. }
    ));
    assert!(matches!(scene.objects[1].shape, Shape::Triangle { .. }));
    let Shape::SmoothTriangle { normals, .. } = scene.objects[3].shape else {
        panic!("pp makes smooth triangles: {:?}", scene.objects[3]);
    };
    assert_eq!(normals[2], Vec3::new(0.0, 0.6, 0.8));
}

#[test]
fn a_light_without_colour_gets_an_equal_share_at_the_at_point() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    let Light::Point {
        position,
        color,
        intensity,
        ..
    } = scene.lights[0]
    else {
        panic!("NFF lights are point lights");
    };
    // Two lights: half of white each, as bright at `at` as NFF's unattenuated light.
    assert_eq!(color, Color::splat(0.5));
    let at_the_at_point = intensity / position.distance_squared(scene.camera.look_at);
    assert!((at_the_at_point - 1.0).abs() < 1e-6);
    let Light::Point { color, .. } = scene.lights[1] else {
        panic!()
    };
    assert_eq!(color, Color::splat(0.5), "its own colour");
}

#[test]
fn the_spd_scenes_load_with_their_primitives() {
    let count = |name| nff::load(spd(name)).unwrap().objects.len();
    assert_eq!(count("balls-1.nff"), 10 + 2);
    assert_eq!(count("balls-4.nff"), 7381 + 2);
    assert_eq!(count("tetra-3.nff"), 64);
    assert_eq!(count("tetra-6.nff"), 4096);
    assert_eq!(count("mount-3.nff"), 128 + 4);
    assert!(count("teapot-2.nff") > 240);
}

fn broken(text: &str) -> SceneError {
    let error = nff::parse(text, "bad.nff").expect_err("must be refused");
    println!("{error}\n");
    assert_eq!(error.file, "bad.nff");
    assert!(error.to_string().starts_with("bad.nff:"), "{error}");
    error
}

/// The good scene with line `line` (1-based) replaced.
fn with_line(line: usize, text: &str) -> String {
    let mut lines: Vec<&str> = GOOD.lines().collect();
    lines[line - 1] = text;
    lines.join("\n")
}

#[test]
fn bad_files_are_refused_with_the_line() {
    let cases = [
        (13, "s 0 0 0 -1", 13, "radius"),
        (13, "s 0 0 zero 1", 13, "`zero`"),
        (13, "s 0 0 0", 13, "found 3 numbers"),
        (13, "c", 13, "cones and cylinders"),
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
        (5, "at 0 -5 1", 3, "view direction"),
        (6, "angle 180", 3, "angle"),
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

/// Renders with the complete tracer against `world`.
fn render(scene: &Scene, world: &(impl World + ?Sized)) -> raybook::toolkit::Image {
    render_complete(scene, world, Termination::of(scene), || {}).0
}

#[test]
fn bvh_and_brute_force_give_the_same_picture_on_the_spd_scenes() {
    let dir = workspace_root().join("scenes/spd");
    let mut names: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "nff"))
        .collect();
    names.sort();
    assert!(names.len() >= 7, "{names:?}");
    for path in names {
        let scene = nff::load(&path).unwrap();
        // Brute force is slow on thousands of primitives: a small picture.
        let side = if scene.objects.len() > 1000 { 24 } else { 64 };
        let scene = scene.with_size(side, side);
        let bvh = ch08_bvh::Bvh::build(&scene.objects);
        let same = render(&scene, &scene.objects[..]) == render(&scene, &bvh);
        assert!(same, "{} differs", path.display());
    }
}
