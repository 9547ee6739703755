//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch03_lambert::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn a_point_light_ten_units_up_brings_a_hundredth_of_its_intensity() {
    // ANCHOR: arrival
    use ch03_lambert::{Arrival, arrival, toolkit::{scene::{Falloff, Light}, Vec3}};

    // A white point light of intensity 50, 10 units above a point.
    let light = Light::Point {
        position: Vec3::new(0.0, 10.0, 0.0),
        color: Vec3::ONE,
        intensity: 50.0,
        shadows: true,
        falloff: Falloff::InverseSquare, // the physical 1/r² (NFF's lights have `None`)
    };
    let Arrival::Incoming(incoming) = arrival(&light, Vec3::ZERO) else { panic!() };
    assert_eq!(incoming.direction, Vec3::Y);          // l points to the light
    assert_eq!(incoming.irradiance, Vec3::splat(0.5));  // the irradiance I_L = 50 / 10²
    // ANCHOR_END: arrival
}
