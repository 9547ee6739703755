//! Chapter 7: each criterion ends the paths it should, and the statistics
//! count them.

use ch07_termination::toolkit::snapshot::assert_image;
use ch07_termination::toolkit::{Scene, Vec3};
use ch07_termination::{CHAPTER, Glass, Mirrors, Termination, render_terminated, render_whitted};

fn mirrors(reflectance: f32) -> Scene {
    let mut scene = Scene::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mirrors.toml"))
        .unwrap()
        .with_size(40, 30);
    scene.materials[0].reflectance = Vec3::splat(reflectance);
    scene
}

#[test]
fn in_two_perfect_mirrors_only_depth_ends_paths() {
    for max_depth in [0, 1, 5, 12] {
        let termination = Termination {
            max_depth,
            min_weight: 0.001,
        };
        let (image, stats) = render_terminated(&mirrors(1.0), termination, || {});
        let primary = stats.primary;
        assert_eq!(stats.ended_no_hit, 0, "every ray hits a mirror");
        assert_eq!(stats.ended_threshold, 0, "weight stays 1");
        assert_eq!(stats.ended_max_depth, primary, "one end per path");
        assert_eq!(stats.reflection, primary * max_depth as u64);
        assert!(image.pixels.iter().all(|c| c.is_finite()));
    }
}

#[test]
fn half_mirrors_and_threshold_one_tenth_trace_three_reflections() {
    // Weights along a path: 0.5, 0.25, 0.125 are traced; 0.0625 < 0.1 ends it.
    for max_depth in [3, 4, 5, 10, 64] {
        let termination = Termination {
            max_depth,
            min_weight: 0.1,
        };
        let (_, stats) = render_terminated(&mirrors(0.5), termination, || {});
        assert_eq!(stats.reflection, 3 * stats.primary, "max_depth {max_depth}");
        if max_depth == 3 {
            assert_eq!(
                stats.ended_max_depth, stats.primary,
                "at 3 the depth ends it first"
            );
        } else {
            assert_eq!(
                stats.ended_threshold, stats.primary,
                "max_depth {max_depth}"
            );
            assert_eq!(stats.ended_max_depth, 0);
        }
    }
}

#[test]
fn rays_into_nothing_end_by_no_hit() {
    let mut scene = mirrors(1.0);
    scene.objects.clear();
    let (image, stats) = render_terminated(&scene, Termination::of(&scene), || {});
    assert_eq!(stats.ended_no_hit, stats.primary);
    assert!(image.pixels.iter().all(|&c| c == scene.image.background));
}

#[test]
fn a_threshold_of_zero_changes_nothing_a_high_one_cuts_reflections() {
    let scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    let deep = Termination {
        max_depth: 6,
        min_weight: 0.0,
    };
    let (all_image, all) = render_terminated(&scene, deep, || {});
    // Chapter 6's tracer has only the depth criterion: with a threshold of
    // zero, chapter 7 must make its picture, ray for ray.
    let glass = Glass {
        mirrors: Mirrors { max_depth: 6 },
    };
    let (depth_only_image, depth_only) = render_whitted(&glass, &scene, &scene.objects[..], || {});
    assert_eq!(all_image.pixels, depth_only_image.pixels);
    assert_eq!(
        (all.reflection, all.refraction, all.shadow),
        (
            depth_only.reflection,
            depth_only.refraction,
            depth_only.shadow
        )
    );

    let (_, cut) = render_terminated(
        &scene,
        Termination {
            min_weight: 0.5,
            ..deep
        },
        || {},
    );
    assert!(cut.ended_threshold > 0);
    assert!(cut.reflection < all.reflection);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    let (image, _) = render_terminated(&scene, Termination::of(&scene), || {});
    assert_image("07-termination", "default", &image);
}
