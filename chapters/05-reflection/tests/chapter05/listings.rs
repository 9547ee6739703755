//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch05_reflection::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn a_ray_down_at_45_degrees_leaves_up_at_45_degrees() {
    // ANCHOR: reflect
    use ch05_reflection::{reflect, toolkit::Vec3};

    let s = 0.5f32.sqrt();
    let d = Vec3::new(s, -s, 0.0);                   // 45° down onto the floor
    let out = reflect(d, Vec3::Y);
    assert!((out - Vec3::new(s, s, 0.0)).length() < 1e-7); // 45° up again
    // ANCHOR_END: reflect
}
