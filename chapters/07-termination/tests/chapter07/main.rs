//! Chapter 7: each criterion ends the paths it should, and the statistics
//! count them.

use ch07_termination::scene_files;
use ch07_termination::toolkit::{Color, Scene, Vec3};
use ch07_termination::workbench::exercise::builds_on;
use ch07_termination::workbench::snapshot::{Precise, assert_image_beside};
use ch07_termination::{
    CHAPTER, Glass, Mirrors, Termination, below_threshold, render_terminated, render_whitted,
};
use test_support::pictures::assert_same_pixels;

fn mirrors(reflectance: f32) -> Scene {
    mirrors_of(Vec3::splat(reflectance))
}

/// Two facing mirrors of `reflectance` (per channel): every ray hits one.
/// The tests that render them judge `may_trace`, so they check
/// `below_threshold` first.
fn mirrors_of(reflectance: Color) -> Scene {
    below_threshold_first();
    let mut scene = scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mirrors.toml"))
        .unwrap()
        .with_size(40, 30);
    scene.materials[0].reflectance = reflectance;
    scene
}

/// `ch07-below-threshold`, which `may_trace` builds on: below 0.1 only when
/// every channel is, and a channel equal to 0.1 is not below it.
fn below_threshold_first() {
    for (weight, below) in [
        (Color::splat(0.05), true),
        (Color::new(0.2, 0.0, 0.0), false),
        (Color::new(0.0, 0.0, 0.3), false),
        (Color::new(0.1, 0.0, 0.0), false),
    ] {
        let got = below_threshold(weight, 0.1);
        builds_on(
            "ch07-below-threshold",
            got == below,
            format_args!(
                "below_threshold({weight}, 0.1) gave {got}, want {below} (the test \
                 below_threshold_decides_five_weights says more)"
            ),
        );
    }
}

/// "1 bounce", "2 bounces": `n` of `thing`, in words that read.
fn count(n: u32, thing: &str) -> String {
    if n == 1 {
        format!("1 {thing}")
    } else {
        format!("{n} {thing}s")
    }
}

#[test]
fn below_threshold_decides_five_weights() {
    for (weight, below, why) in [
        (Color::splat(0.05), true, "every channel is below 0.1"),
        (Color::splat(0.09), true, "every channel is below 0.1"),
        (
            Color::new(0.2, 0.0, 0.0),
            false,
            "red still carries 0.2: a path ends only when every channel is below min_weight",
        ),
        (
            Color::new(0.0, 0.0, 0.3),
            false,
            "blue still carries 0.3: a path ends only when every channel is below min_weight \
             (not the mean, not the brightness)",
        ),
        (
            Color::new(0.1, 0.0, 0.0),
            false,
            "red is 0.1, equal to min_weight, not below it",
        ),
    ] {
        assert_eq!(
            below_threshold(weight, 0.1),
            below,
            "weight {weight}, min_weight 0.1: {why}"
        );
    }
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
        assert_eq!(
            stats.reflection,
            primary * max_depth as u64,
            "max_depth = {max_depth} follows exactly {}: {} per pixel (the first bounce is \
             depth 1; a ray beyond max_depth is not traced)",
            count(max_depth, "bounce"),
            count(max_depth, "mirror ray")
        );
        assert_eq!(
            stats.ended_max_depth, primary,
            "each path ends once, by depth: count it in stats.ended_max_depth"
        );
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
        assert_eq!(
            stats.reflection,
            3 * stats.primary,
            "max_depth {max_depth}, weights 0.5, 0.25, 0.125, 0.0625: three mirror rays per pixel"
        );
        if max_depth == 3 {
            assert_eq!(
                stats.ended_max_depth, stats.primary,
                "at max_depth 3 the fourth ray is both too deep and too weak: the depth is \
                 checked first and ends it"
            );
        } else {
            assert_eq!(
                stats.ended_threshold, stats.primary,
                "max_depth {max_depth}: each path ends once, by the threshold: count it in \
                 stats.ended_threshold"
            );
            assert_eq!(stats.ended_max_depth, 0);
        }
    }
}

#[test]
fn a_weight_equal_to_the_threshold_is_traced() {
    // Weights 0.5, 0.25, 0.125 (exactly min_weight: not below it), 0.0625.
    let termination = Termination {
        max_depth: 10,
        min_weight: 0.125,
    };
    let (_, stats) = render_terminated(&mirrors(0.5), termination, || {});
    assert_eq!(
        stats.reflection,
        3 * stats.primary,
        "min_weight 0.125: the third mirror ray has weight 0.125, not below the threshold, and is \
         traced"
    );
}

#[test]
fn two_facing_tinted_mirrors_end_by_weight() {
    // Red weights 0.5, 0.25, 0.125, 0.0625; green and blue 0.05 from the
    // first bounce on. Threshold 0.1: red keeps three rays going.
    let termination = Termination {
        max_depth: 10,
        min_weight: 0.1,
    };
    let scene = mirrors_of(Color::new(0.5, 0.05, 0.05));
    let (_, stats) = render_terminated(&scene, termination, || {});
    assert_eq!(
        stats.reflection,
        3 * stats.primary,
        "mirrors of reflectance (0.5, 0.05, 0.05), min_weight 0.1: red carries 0.5, 0.25, 0.125 \
         over three bounces, so each pixel traces three mirror rays; a path ends only when every \
         channel of its weight is below min_weight (found {} per pixel)",
        stats.reflection as f64 / stats.primary as f64
    );
}

/// The weight bounds a path's share relative to the colour it brings back,
/// which can be far above 1: here a cut path of weight 0.0008 < 0.001 would
/// have brought back a floodlit wall of colour up to 400.
#[test]
fn a_path_below_the_threshold_can_change_a_pixel_by_more_than_the_threshold() {
    let scene = scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/floodlit.toml"))
        .unwrap()
        .with_size(40, 30);
    let criteria = Termination::of(&scene);
    assert_eq!(criteria.min_weight, 0.001);
    let (cut, cut_stats) = render_terminated(&scene, criteria, || {});
    let all = Termination {
        min_weight: 0.0,
        ..criteria
    };
    let (full, _) = render_terminated(&scene, all, || {});
    assert_eq!(
        cut_stats.ended_threshold, cut_stats.primary,
        "the pane's weight 0.0008 is below min_weight 0.001: every mirror ray is cut"
    );
    let (cut8, full8) = (cut.to_rgb8(), full.to_rgb8());
    let (index, levels) = (cut8.as_raw().iter())
        .zip(full8.as_raw())
        .map(|(&a, &b)| a.abs_diff(b))
        .enumerate()
        .max_by_key(|&(_, d)| d)
        .unwrap();
    let pixel = (index / 3) as u32;
    let (x, y) = (pixel % cut.width, pixel / cut.width);
    let (a, b) = (cut.get(x, y), full.get(x, y));
    println!("pixel ({x}, {y}): {a} with min_weight 0.001, {b} with 0; {levels} levels apart");
    assert!(
        levels > 1 && (b - a).max_element() > 1.0 / 255.0,
        "a path of weight below 0.001 brings back up to 0.0008 × 400: pixel ({x}, {y}) should \
         differ by far more than 1/255 between min_weight 0.001 and 0; found {a} and {b}"
    );
    assert!(
        (b - a).max_element() > 50.0 * 0.001,
        "the change, {}, is far more than min_weight",
        (b - a).max_element()
    );
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
    assert_same_pixels(
        &all_image,
        &depth_only_image,
        "max_depth 6 and min_weight 0 against chapter 6's tracer with max_depth 6",
        "Few pixels off by little, where mirrors or glass are seen, is the share of the \
         deepest bounce: the depth limit ends paths one bounce early or late (max_depth 6 \
         traces bounces 1 to 6: a ray at depth 6 goes on, one at depth 7 ends; depth > \
         max_depth, not >=). Many pixels off by much is the threshold: no weight is below 0",
    );
    assert_eq!(
        (all.reflection, all.refraction, all.shadow),
        (
            depth_only.reflection,
            depth_only.refraction,
            depth_only.shadow
        ),
        "(reflection, refraction, shadow) rays with min_weight 0 against chapter 6's tracer: \
         with a threshold of zero only the depth ends a path, at the same bounce as chapter 6"
    );

    let (_, cut) = render_terminated(
        &scene,
        Termination {
            min_weight: 0.5,
            ..deep
        },
        || {},
    );
    assert!(
        cut.ended_threshold > 0,
        "min_weight 0.5 ends the paths whose weight falls below 0.5 (a mirror of reflectance \
         below 0.5 does it at the first bounce): count each in stats.ended_threshold; found 0"
    );
    assert!(
        cut.reflection < all.reflection,
        "min_weight 0.5 cuts paths, so fewer mirror rays are traced than with min_weight 0: \
         found {} with 0.5 and {} with 0",
        cut.reflection,
        all.reflection
    );
}

#[test]
fn snapshot_default() {
    below_threshold_first();
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    let (image, _) = render_terminated(&scene, Termination::of(&scene), || {});
    assert_image_beside("07-termination", "default", &image, PRECISE);
}

/// The tests whose messages say more than the picture's count of pixels:
/// the snapshot, when it differs, names those of them that fail beside it.
const PRECISE: &[Precise] = &[
    (
        "below_threshold_decides_five_weights",
        below_threshold_decides_five_weights,
    ),
    (
        "a_weight_equal_to_the_threshold_is_traced",
        a_weight_equal_to_the_threshold_is_traced,
    ),
    (
        "two_facing_tinted_mirrors_end_by_weight",
        two_facing_tinted_mirrors_end_by_weight,
    ),
    (
        "in_two_perfect_mirrors_only_depth_ends_paths",
        in_two_perfect_mirrors_only_depth_ends_paths,
    ),
    (
        "half_mirrors_and_threshold_one_tenth_trace_three_reflections",
        half_mirrors_and_threshold_one_tenth_trace_three_reflections,
    ),
];

// Last: `workbook progress` ranks failures in this file's order, theirs after these.
/// `--pixel X,Y --json`: which criterion ended each path.
mod ray_tree;

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
