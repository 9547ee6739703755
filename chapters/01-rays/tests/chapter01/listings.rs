//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch01_rays::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 2);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn a_ray_is_normalised_and_walks_along_its_direction() {
    // ANCHOR: ray
    use ch01_rays::{Ray, toolkit::Vec3};

    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -5.0, 0.0));
    assert_eq!(ray.direction, Vec3::new(0.0, -1.0, 0.0)); // normalised
    assert_eq!(ray.at(1.5), Vec3::new(0.0, 0.5, 0.0));     // r0 + t·rd
    // ANCHOR_END: ray
}

#[test]
#[rustfmt::skip] // as the text shows it
fn four_samples_fall_one_in_each_quarter_of_the_pixel() {
    // ANCHOR: samples
    use ch01_rays::sample_positions;

    // Four rays through pixel (10, 20): one in each quarter of the pixel.
    let rays: Vec<(f32, f32)> = sample_positions(10, 20, 4, 12345).collect();
    assert_eq!(rays.len(), 4);
    assert!(rays.iter().all(|&(x, y)| (10.0..11.0).contains(&x) && (20.0..21.0).contains(&y)));
    assert_eq!(sample_positions(10, 20, 1, 0).next(), Some((10.5, 20.5)));
    // ANCHOR_END: samples
}
