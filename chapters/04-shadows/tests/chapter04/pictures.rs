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
