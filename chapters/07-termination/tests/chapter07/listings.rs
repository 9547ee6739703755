//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch07_termination::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn two_facing_mirrors_end_their_paths_at_the_threshold() {
    // ANCHOR: mirrors
    use ch07_termination::{Termination, render_terminated, scene_files, toolkit::Vec3};

    // Two facing mirrors of reflectance 0.5, threshold 0.1: weights 0.5, 0.25
    // and 0.125 are traced; 0.0625 < 0.1 ends the path.
    let mut scene = scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/mirrors.toml"))
        .unwrap()
        .with_size(8, 6);
    scene.materials[0].reflectance = Vec3::splat(0.5);
    let (_, stats) = render_terminated(&scene, Termination { max_depth: 10, min_weight: 0.1 }, || {});
    assert_eq!(stats.reflection, 3 * stats.primary);
    assert_eq!(stats.ended_threshold, stats.primary);
    // ANCHOR_END: mirrors
}
