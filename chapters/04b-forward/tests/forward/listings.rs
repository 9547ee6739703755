//! The Rust listings of the chapter's text (its README.md), each a test.
//! The text shows the lines between a test's `// ANCHOR` markers, and
//! `the_text_shows_these_listings` fails when the two differ (see
//! `workbench::listings`).

#[test]
fn the_text_shows_these_listings() {
    ch04_shadows::workbench::listings::assert_checked(env!("CARGO_MANIFEST_DIR"), 1);
}

#[test]
#[rustfmt::skip] // as the text shows it
fn only_an_aperture_lets_photons_reach_the_image() {
    // ANCHOR: forward
    use ch04b_forward::{Settings, check_scene, trace_forward};
    use ch04_shadows::scene_files;

    let scene = scene_files::parse(r#"
        [camera]
        eye = [0, 1, 2]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 60
        [image]
        width = 4
        height = 3
        background = [0, 0, 0]
        [materials.grey]
        [[lights]]
        type = "point"
        position = [0, 2, 0]
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = 0
        material = "grey"
    "#, "floor.toml").unwrap();
    check_scene(&scene).unwrap();
    let through = |aperture| {
        let settings = Settings { rays: 100_000, aperture, seed: 1 };
        trace_forward(&scene, &settings, |_| {}).counts.on_image
    };
    assert!(through(0.2) > 0);
    assert_eq!(through(0.0), 0); // a true pinhole lets no photon through
    // ANCHOR_END: forward
}
