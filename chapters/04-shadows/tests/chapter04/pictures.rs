//! The chapter's pictures, against their reference snapshots.

use ch04_shadows::workbench::snapshot::assert_image;
use ch04_shadows::{CHAPTER, ShadowStart};

use super::{earlier, render, scene_file};

#[test]
fn snapshot_default() {
    earlier::all_but_light_is_free();
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image(
        "04-shadows",
        "default",
        &render(&scene, ShadowStart::Offset),
    );
}

#[test]
fn snapshot_box() {
    earlier::all_but_light_is_free();
    let scene = scene_file("box.toml").with_size(160, 120);
    assert_image("04-shadows", "box", &render(&scene, ShadowStart::Offset));
}

/// A floor of two triangles with corners 10⁶ away, a light 0.03 above it:
/// the bright spot is smooth, as a plane's is (README, *A floor as large as
/// the world*).
#[test]
fn snapshot_huge_floor() {
    let scene = scene_file("huge-floor.toml");
    assert_image(
        "04-shadows",
        "huge-floor",
        &render(&scene, ShadowStart::Offset),
    );
}
