//! The chapter's pictures, against their reference snapshots.

use ch04_shadows::workbench::snapshot::{Precise, assert_image_beside};
use ch04_shadows::{CHAPTER, ShadowStart};

use super::{earlier, render, scene_file};

/// The tests whose messages say more than the pictures' counts of pixels:
/// a picture that differs names those of them that fail beside it.
const PRECISE: &[Precise] = &[
    (
        "the_shadow_ray_goes_from_the_surface_to_the_light",
        super::the_shadow_ray_goes_from_the_surface_to_the_light,
    ),
    (
        "the_shadow_ray_starts_at_the_offset_origin",
        super::the_shadow_ray_starts_at_the_offset_origin,
    ),
    (
        "a_blocker_beyond_the_light_casts_no_shadow",
        super::a_blocker_beyond_the_light_casts_no_shadow,
    ),
    (
        "a_blocker_just_before_the_light_casts_a_shadow",
        super::a_blocker_just_before_the_light_casts_a_shadow,
    ),
    (
        "a_shadow_ray_is_blocked_only_before_the_light",
        super::listings::a_shadow_ray_is_blocked_only_before_the_light,
    ),
    (
        "objects_that_opt_out_cast_no_shadow",
        super::objects_that_opt_out_cast_no_shadow,
    ),
    (
        "lights_that_opt_out_trace_no_shadow_ray",
        super::lights_that_opt_out_trace_no_shadow_ray,
    ),
    (
        "a_blocker_between_point_and_light_blocks_it_one_behind_does_not",
        super::a_blocker_between_point_and_light_blocks_it_one_behind_does_not,
    ),
    (
        "the_offset_moves_to_the_lights_side_and_scales_with_magnitude",
        super::the_offset_moves_to_the_lights_side_and_scales_with_magnitude,
    ),
];

#[test]
fn snapshot_default() {
    earlier::all_but_light_is_free();
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image_beside(
        "04-shadows",
        "default",
        &render(&scene, ShadowStart::Offset),
        PRECISE,
    );
}

#[test]
fn snapshot_box() {
    earlier::all_but_light_is_free();
    let scene = scene_file("box.toml").with_size(160, 120);
    assert_image_beside(
        "04-shadows",
        "box",
        &render(&scene, ShadowStart::Offset),
        PRECISE,
    );
}

/// A floor of two triangles with corners 10⁶ away, a light 0.03 above it:
/// the bright spot is smooth, as a plane's is (README, *A floor as large as
/// the world*).
#[test]
fn snapshot_huge_floor() {
    let scene = scene_file("huge-floor.toml");
    assert_image_beside(
        "04-shadows",
        "huge-floor",
        &render(&scene, ShadowStart::Offset),
        PRECISE,
    );
}
