//! NFF import: the SPD scenes load, entities map onto raybook's scene, bad
//! files are refused with the line, and the BVH sees what brute force sees.

use ch03_lambert::{Arrival, arrival};
use raybook::nff;
use raybook::scene_files::{self, SceneError};
use raybook::toolkit::scene::{Falloff, Light, Shape, TraceSpec};
use raybook::toolkit::{Color, Scene, Vec3};
use raybook::tracer::{Termination, World, render_complete};
use raybook::workbench::snapshot::workspace_root;

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
fn a_light_without_colour_gets_the_spd_generators_grey_and_no_falloff() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    let Light::Point {
        color,
        intensity,
        falloff,
        ..
    } = scene.lights[0]
    else {
        panic!("NFF lights are point lights");
    };
    // Two lights: 1/√2 each, as the SPD generators write them for POV-Ray.
    assert_eq!(color, Color::splat(0.5f32.sqrt()));
    assert_eq!((intensity, falloff), (1.0, Falloff::None));
    let Light::Point { color, .. } = scene.lights[1] else {
        panic!()
    };
    assert_eq!(color, Color::splat(0.5), "its own colour");
}

#[test]
fn an_nff_light_is_as_bright_near_as_far() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    let light = &scene.lights[0];
    let irradiance = |point: Vec3| match arrival(light, point) {
        Arrival::Incoming(incoming) => incoming.irradiance,
        other => panic!("{other:?}"),
    };
    let (near, far) = (irradiance(Vec3::new(4.0, 3.0, 1.0)), irradiance(Vec3::ZERO));
    assert_eq!(near, far, "1 and 5.4 away");
    assert_eq!(near, Color::splat(0.5f32.sqrt()));
    // The same light with the 1/r² of a TOML scene's point light.
    let mut physical = light.clone();
    if let Light::Point { falloff, .. } = &mut physical {
        *falloff = Falloff::InverseSquare;
    }
    let Arrival::Incoming(far) = arrival(&physical, Vec3::new(4.0, 3.0, -2.0)) else {
        panic!()
    };
    assert!(
        (far.irradiance - near / 16.0).length() < 1e-6,
        "4 away: 1/16"
    );
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
    // The seven generators at their default sizes. gears: 9217 quads of
    // two triangles and 128 tooth outlines of 144 corners, 142 triangles each.
    assert_eq!(count("gears-4.nff"), 9217 * 2 + 128 * 142);
    assert_eq!(count("mount-6.nff"), 8192 + 4);
    // rings and tree: as many cones as spheres, and a floor of two triangles.
    assert_eq!(count("rings-7.nff"), 4200 * 2 + 2);
    assert_eq!(count("tree-11.nff"), 4095 * 2 + 2);
    assert_eq!(count("teapot-6.nff"), 36 * 2 + 2256);
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
fn an_nff_scene_gets_the_defaults_of_a_toml_scene() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    assert_eq!(scene.trace, TraceSpec::default());
    assert_eq!(scene.image.samples, 1);
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

/// The objects of GOOD's material and viewpoint followed by `objects`.
fn shapes_of(objects: &str) -> Vec<Shape> {
    let text = format!("{}{objects}", &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]);
    let scene = nff::parse(&text, "shapes.nff").unwrap_or_else(|e| panic!("{e}"));
    scene.objects.iter().map(|o| o.shape).collect()
}

/// The one cone of a `c` entity: its base, base radius, apex, apex radius
/// and whether it is inside out.
fn the_cone(objects: &str) -> (Vec3, f32, Vec3, f32, bool) {
    match shapes_of(objects)[..] {
        [
            Shape::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
                inside_out,
            },
        ] => (base, base_radius, apex, apex_radius, inside_out),
        ref other => panic!("a `c` entity is one cone, found {other:?}"),
    }
}

#[test]
fn a_cylinder_on_three_lines_is_one_cone_shape() {
    // NFF's form: `c`, then the base and the apex on lines of their own.
    let cone = the_cone("c\n1 2 0 0.5\n1 2 3 0.5\n");
    let (base, apex) = (Vec3::new(1.0, 2.0, 0.0), Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(cone, (base, 0.5, apex, 0.5, false));
}

#[test]
fn a_pointed_cone_may_stand_on_one_line() {
    // The SPD generators' form: all eight numbers on the `c` line.
    let cone = the_cone("c 0 0 0 1 0 0 1 0\n");
    assert_eq!(cone, (Vec3::ZERO, 1.0, Vec3::Z, 0.0, false));
}

#[test]
fn negative_radii_turn_a_cone_inside_out() {
    let cone = the_cone("c 0 0 0 -1 0 0 2 -0.5\n");
    assert_eq!(cone, (Vec3::ZERO, 1.0, 2.0 * Vec3::Z, 0.5, true));
    // Its normals point towards the axis: a ray from the axis meets a wall
    // whose normal faces back towards it.
    let scene = nff::parse(
        &format!(
            "{}c 0 0 0 -1 0 0 2 -0.5\n",
            &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]
        ),
        "inside.nff",
    )
    .unwrap();
    let ray = raybook::tracer::Ray::new(Vec3::new(0.0, 0.0, 1.0), Vec3::X);
    let hit = raybook::tracer::closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    // Outward it would be d̂ + (r_b − r_a)/h·w = (1, 0, 0.25), normalised.
    let inward = -Vec3::new(1.0, 0.0, 0.25).normalize();
    assert!((hit.normal - inward).length() < 1e-6, "{}", hit.normal);
}

#[test]
fn a_cone_that_ends_early_names_its_line() {
    let e = broken(&format!(
        "{}c\n0 0 0 1\n",
        &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]
    ));
    assert!(e.message.contains("the apex of the cone"), "{e}");
    assert_eq!(e.line, Some(13));
    let e = broken(&with_line(13, "c\n0 0 0 1\n0 0 1 -1"));
    assert_eq!(e.line, Some(15), "the apex's line");
    assert_eq!(e.column, Some(7), "at the radius");
}

/// (b − a) × (c − a): the normal of a triangle's winding, twice its area long.
fn area_vector([a, b, c]: [Vec3; 3]) -> Vec3 {
    (b - a).cross(c - a)
}

/// Checks that the triangles of a polygon cover it exactly: as many as a
/// triangulation has (n − 2), each wound as the polygon is (so none is
/// flipped, as a fan's are outside a concave corner), and together as large
/// as the polygon (so none overlaps another or pokes out).
fn covers_exactly(corners: &[[f32; 2]]) -> Vec<[Vec3; 3]> {
    let lines: Vec<String> = corners.iter().map(|[x, y]| format!("{x} {y} 0")).collect();
    let shapes = shapes_of(&format!("p {}\n{}\n", corners.len(), lines.join("\n")));
    let triangles: Vec<[Vec3; 3]> = (shapes.iter())
        .map(|s| match *s {
            Shape::Triangle { vertices } => vertices,
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(triangles.len(), corners.len() - 2);
    // The shoelace formula: the polygon's area, positive if counter-clockwise.
    let n = corners.len();
    let area: f32 = (0..n)
        .map(|i| {
            let ([x0, y0], [x1, y1]) = (corners[i], corners[(i + 1) % n]);
            (x0 * y1 - x1 * y0) / 2.0
        })
        .sum();
    assert!(area > 0.0, "the test's polygons are counter-clockwise");
    let mut covered = 0.0;
    for t in &triangles {
        let z = area_vector(*t).z / 2.0;
        assert!(z > 0.0, "{t:?} is wound against the polygon");
        covered += z;
    }
    assert!((covered - area).abs() < 1e-4 * area, "{covered} ≠ {area}");
    triangles
}

#[test]
fn concave_polygons_are_cut_into_triangles_inside_them() {
    // An L, starting at a corner from which a fan would leave the L.
    covers_exactly(&[
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
        [0.0, 0.0],
    ]);
    // A five-pointed star, starting at a tip.
    let star: Vec<[f32; 2]> = (0..10)
        .map(|i| {
            let angle = std::f32::consts::TAU * i as f32 / 10.0;
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            [r * angle.cos(), r * angle.sin()]
        })
        .collect();
    covers_exactly(&star);
}

#[test]
fn polygons_are_cut_into_compact_triangles() {
    // A long thin rhombus: the fan from the first corner cuts it along its
    // long diagonal into two slivers; the short diagonal is the better cut.
    let triangles = covers_exactly(&[[0.0, 0.0], [10.0, -1.0], [20.0, 0.0], [10.0, 1.0]]);
    for t in triangles {
        assert!(t.contains(&Vec3::new(10.0, -1.0, 0.0)) && t.contains(&Vec3::new(10.0, 1.0, 0.0)));
    }
}

/// Renders with the complete tracer against `world`.
fn render(scene: &Scene, world: &(impl World + ?Sized)) -> raybook::toolkit::Image {
    render_complete(scene, world, Termination::of(scene), || {}).0
}

/// The NFF scenes of scenes/spd, sorted.
fn spd_scenes() -> Vec<std::path::PathBuf> {
    let dir = workspace_root().join("scenes/spd");
    let mut names: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "nff"))
        .collect();
    names.sort();
    names
}

#[test]
fn every_spd_generator_is_there_at_its_default_size_and_renders() {
    let names = spd_scenes();
    let defaults = [
        "balls-4", "gears-4", "mount-6", "rings-7", "teapot-6", "tetra-6", "tree-11",
    ];
    for name in defaults {
        assert!(
            names.iter().any(|p| p.ends_with(format!("{name}.nff"))),
            "{name}"
        );
        let pov = workspace_root().join(format!("scenes/spd/{name}.pov"));
        assert!(pov.is_file(), "{} for POV-Ray", pov.display());
    }
    for path in names {
        let scene = nff::load(&path).unwrap().with_size(32, 32);
        let bvh = ch08_bvh::Bvh::build(&scene.objects);
        let image = render(&scene, &bvh);
        assert!(
            image.pixels.iter().all(|c| c.is_finite()),
            "{}",
            path.display()
        );
        let lit = image
            .pixels
            .iter()
            .filter(|&&c| c != scene.image.background);
        assert!(
            lit.count() > 32 * 32 / 10,
            "{} shows its objects",
            path.display()
        );
    }
}

#[test]
fn bvh_and_brute_force_give_the_same_picture_on_the_spd_scenes() {
    let names = spd_scenes();
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

#[test]
fn the_render_arguments_read_nff_with_every_override() {
    let args = raybook::workbench::cli::RenderArgs {
        scene: Some(spd("balls-1.nff")),
        width: Some(8),
        height: Some(6),
        samples: Some(4),
        ..Default::default()
    };
    let (scene, name) = args.load_scene(&raybook::CHAPTER).unwrap();
    let image = scene.image;
    assert_eq!((image.width, image.height, image.samples), (8, 6, 4));
    assert!(name.ends_with("balls-1.nff"), "{name}");
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
