//! Chapter 8: the BVH gives the same pictures as brute force, faster.

use ch08_bvh::scene_files;
use std::path::PathBuf;

use ch08_bvh::toolkit::scene::{Object, Shape};
use ch08_bvh::toolkit::{Image, Scene, Stats, Vec3};
use ch08_bvh::workbench::cli::with_threads;
use ch08_bvh::workbench::snapshot::{assert_image, workspace_root};
use ch08_bvh::{Bvh, CHAPTER, Ray, Termination, Tracer, World, render_bvh, render_whitted};
use proptest::prelude::*;
use test_support::strategies::{cone, point};

/// Every chapter's scene files, the first chapter first.
fn chapter_scenes() -> Vec<PathBuf> {
    ch08_bvh::workbench::chapters::scene_files(&workspace_root())
}

/// Chapter 7's tracer against `world`.
fn render_against(scene: &Scene, world: &(impl World + ?Sized)) -> (Image, Stats) {
    let termination = Termination::of(scene);
    render_whitted(&Tracer { termination }, scene, world, || {})
}

#[test]
fn bvh_and_brute_force_give_the_same_picture_on_every_chapter_scene() {
    let scenes = chapter_scenes();
    assert!(scenes.len() >= 12, "found {scenes:?}");
    for path in scenes {
        let scene = scene_files::load(&path).unwrap().with_size(80, 60);
        let bvh = Bvh::build(&scene.objects);
        let brute = render_against(&scene, &scene.objects[..]);
        let fast = render_against(&scene, &bvh);
        // Equal f32 pixels (so equal bytes) and equal ray counts.
        assert!(brute == fast, "{} differs", path.display());
    }
}

#[test]
fn one_thread_and_four_give_the_same_bytes() {
    let scene = CHAPTER.default_scene().unwrap().with_size(96, 64);
    let termination = Termination::of(&scene);
    let render =
        |threads| with_threads(Some(threads), || render_bvh(&scene, termination, || {})).unwrap();
    let (one, one_stats) = render(1);
    let (four, four_stats) = render(4);
    assert_eq!(one.to_png(), four.to_png());
    assert_eq!(one_stats, four_stats);
}

#[test]
fn the_tree_holds_every_bounded_object_once() {
    let scene = CHAPTER.default_scene().unwrap();
    let summary = Bvh::build(&scene.objects).summary();
    println!("{summary}");
    assert_eq!(summary.primitives, 820);
    assert_eq!(summary.unbounded, 1);
    assert_eq!(summary.nodes, 2 * summary.leaves - 1, "a binary tree");
    // 820 spheres in leaves of at most 4: at least 205 leaves, depth ≥ 9.
    assert!(summary.leaves >= 205 && summary.depth >= 9);
    assert!(summary.depth <= 30, "{summary}");
}

#[test]
fn an_empty_scene_has_an_empty_tree() {
    let bvh = Bvh::build(&[]);
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    assert_eq!(bvh.closest_hit(&ray, 0.0, f32::INFINITY), None);
    assert!(!bvh.any_hit(&ray, 0.0, f32::INFINITY));
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    let image = render_bvh(&scene, Termination::of(&scene), || {}).0;
    assert_image("08-bvh", "default", &image);
}

fn object() -> impl Strategy<Value = Object> {
    let shape = prop_oneof![
        4 => (point(), 0.05f32..1.5).prop_map(|(center, radius)| Shape::Sphere { center, radius }),
        4 => (point(), point(), point()).prop_filter_map("no area", |(a, b, c)| {
            let area = (b - a).cross(c - a).length();
            (area > 1e-3).then_some(Shape::Triangle { vertices: [a, b, c] })
        }),
        3 => cone(),
        1 => (point(), -3.0f32..3.0).prop_filter_map("no normal", |(n, offset)| {
            (n.length() > 0.1).then(|| Shape::Plane { normal: n.normalize(), offset })
        }),
    ];
    (shape, any::<bool>()).prop_map(|(shape, shadows)| Object {
        shape,
        material: 0,
        shadows,
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Random objects, random rays: the BVH answers both questions exactly
    /// as chapter 2's and chapter 4's loops do.
    /// A cone's box holds every point of its side, and it is tight: each
    /// face is touched by a point of an end circle (up to the few
    /// millionths of `padded` and the gaps between the sampled angles).
    #[test]
    fn a_cones_box_holds_its_side_and_touches_it(cone in cone()) {
        let Shape::Cone { base, base_radius, apex, apex_radius, .. } = cone else {
            unreachable!()
        };
        let b = ch08_bvh::bounds(&cone).unwrap();
        let w = (apex - base).normalize();
        let (u, v) = w.any_orthonormal_pair();
        let (mut low, mut high) = (Vec3::INFINITY, Vec3::NEG_INFINITY);
        for i in 0..256 {
            let angle = i as f32 * std::f32::consts::TAU / 256.0;
            let across = u * angle.cos() + v * angle.sin();
            for s in [0.0, 0.3, 1.0] {
                let p = base.lerp(apex, s) + (base_radius + s * (apex_radius - base_radius)) * across;
                prop_assert!(p.cmpge(b.min).all() && p.cmple(b.max).all(), "{p} outside {b:?}");
                (low, high) = (low.min(p), high.max(p));
            }
        }
        let slack = 1e-3 * base_radius.max(apex_radius) + 1e-4;
        prop_assert!((b.min - low).abs().max_element() < slack, "{b:?} vs {low}");
        prop_assert!((b.max - high).abs().max_element() < slack, "{b:?} vs {high}");
    }

    #[test]
    fn bvh_agrees_with_brute_force_on_random_rays(
        objects in prop::collection::vec(object(), 1..60),
        rays in prop::collection::vec((point(), point(), 0.1f32..20.0), 20),
    ) {
        let bvh = Bvh::build(&objects);
        for (origin, direction, t_max) in rays {
            prop_assume!(direction.length() > 1e-3);
            let ray = Ray::new(origin * 2.0, direction);
            prop_assert_eq!(
                bvh.any_hit(&ray, 0.0, t_max),
                objects[..].any_hit(&ray, 0.0, t_max)
            );
            prop_assert_eq!(
                bvh.closest_hit(&ray, 0.0, t_max),
                objects[..].closest_hit(&ray, 0.0, t_max)
            );
        }
    }
}

#[test]
fn an_obj_mesh_becomes_smooth_triangles() {
    let scene =
        scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mesh.toml")).unwrap();
    let smooth = scene
        .objects
        .iter()
        .filter(|o| matches!(o.shape, Shape::SmoothTriangle { .. }))
        .count();
    assert_eq!(smooth, 64 * 32 * 2, "the torus's quads, two triangles each");
    assert_eq!(
        scene.objects.len(),
        smooth + 2,
        "and the floor and the sphere"
    );
}

#[test]
fn snapshot_mesh() {
    let scene = scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mesh.toml"))
        .unwrap()
        .with_size(160, 120);
    let image = render_bvh(&scene, Termination::of(&scene), || {}).0;
    assert_image("08-bvh", "mesh", &image);
}

// Last: `workbook progress` ranks failures in this file's order, theirs after these.
/// Through the BVH, a pixel's ray tree is the same as chapter 7's.
mod ray_tree;

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
