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
pub(crate) fn a_shadow_ray_is_blocked_only_before_the_light() {
    // ANCHOR: any_hit
    use ch04_shadows::{Ray, any_hit, scene_files, toolkit::Vec3};

    let scene = scene_files::parse(r#"
        [camera]
        eye = [0, 0, 5]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 40
        [image]
        width = 8
        height = 8
        [materials.grey]
        [[objects]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "grey"
    "#, "example.toml").unwrap();
    let ray = Ray::new(Vec3::new(0.0, 0.0, 3.0), Vec3::new(0.0, 0.0, -1.0));
    assert!(any_hit(&scene.objects, &ray, 0.0, 10.0));  // a light at distance 10 is blocked
    assert!(!any_hit(&scene.objects, &ray, 0.0, 1.5)); // a light at distance 1.5 is not
    // ANCHOR_END: any_hit
}
