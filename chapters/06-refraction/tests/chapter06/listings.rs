//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch06_refraction::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn snell_at_30_degrees_and_no_refracted_ray_beyond_the_critical_angle() {
    // ANCHOR: refract
    use ch06_refraction::{refract, toolkit::Vec3};

    // 30° into glass: sin θ₂ = sin 30° / 1.5 = 1/3, so θ₂ = 19.47°.
    let d = Vec3::new(0.5, -(0.75f32).sqrt(), 0.0);
    let out = refract(d, Vec3::Y, 1.0 / 1.5).unwrap();
    assert!((out.angle_between(Vec3::NEG_Y).to_degrees() - 19.47).abs() < 0.01);

    // From inside glass at 42°, beyond the critical angle of 41.81°: no refracted ray.
    let steep = Vec3::new(42f32.to_radians().sin(), -42f32.to_radians().cos(), 0.0);
    assert_eq!(refract(steep, Vec3::Y, 1.5), None);
    // ANCHOR_END: refract
}
