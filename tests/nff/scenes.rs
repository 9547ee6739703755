//! The SPD scenes: they load with their primitives, every generator renders,
//! the BVH sees what brute force sees, and `raybook render` reads them.

use raybook::nff;
use raybook::toolkit::Scene;
use raybook::tracer::{Termination, World, render_complete};
use raybook::workbench::snapshot::workspace_root;

use super::spd;

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
