//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch08_bvh::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn a_ray_enters_the_unit_box_at_one_or_misses_it() {
    // ANCHOR: entry
    use ch08_bvh::{Aabb, toolkit::Vec3};

    let unit = Aabb { min: Vec3::ZERO, max: Vec3::ONE };
    // From (−1, 0.5, 0.5) along +x: enters the box at t = 1, leaves at t = 2.
    let inverse = Vec3::X.recip(); // (1, ∞, ∞)
    let origin = Vec3::new(-1.0, 0.5, 0.5);
    assert_eq!(unit.entry(origin, inverse, 0.0, f32::INFINITY), Some(1.0));
    // The same ray stopped at t = 0.5, before the box: a miss.
    assert_eq!(unit.entry(origin, inverse, 0.0, 0.5), None);
    // ANCHOR_END: entry
}
