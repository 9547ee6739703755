//! Wrong pictures that name no usual mistake: verify says where they differ
//! and which objects that region shows.

use workbook::toolkit::Color;
use workbook::verify::Diagnosis;

use super::{chapter3_scene, diagnosis, named, reference_image};

#[test]
fn a_wrong_colour_names_no_mistake_but_the_object() {
    // The red sphere (object 1 of the scene) painted green.
    let mut scene = chapter3_scene();
    let red = scene.objects[1].material;
    assert_eq!(scene.materials[red].name, "red");
    scene.materials[red].color = Color::new(0.2, 0.8, 0.2);
    let (green, _) = ch03_lambert::render_lambert(&scene, || {});
    let diagnosis = diagnosis("3", &green.to_rgb8(), "green.png");
    let Diagnosis::Differs(region) = &diagnosis else {
        panic!("names a mistake: {diagnosis}");
    };
    assert_eq!(region.spread, None, "{diagnosis}");
    let shown = region.shown.as_ref().expect("chapter 3 has an object map");
    assert_eq!(
        shown[0].object.as_ref().map(|o| o.0),
        Some(1),
        "{diagnosis}"
    );
    assert!(shown[0].share > 0.95, "{diagnosis}");
    let text = diagnosis.to_string();
    assert!(text.contains("object 1 (sphere, material red)"), "{text}");
    // The sphere spans about x 24..71, y 30..76 of the reference.
    assert!(region.area.x.0 > 15 && region.area.x.1 < 80, "{text}");
    assert!(region.area.y.0 > 20 && region.area.y.1 < 85, "{text}");
}

#[test]
fn another_chapters_picture_names_no_mistake() {
    for (chapter, other) in [("3", "4"), ("5", "6"), ("6", "7"), ("2", "3")] {
        let name = format!("{other}-as-{chapter}.png");
        let diagnosis = diagnosis(chapter, &reference_image(other), &name);
        assert_eq!(named(&diagnosis), None, "{diagnosis}");
    }
}

#[test]
fn a_picture_one_pixel_off_names_no_mistake() {
    let original = reference_image("3");
    let shifted =
        image::RgbImage::from_fn(160, 120, |x, y| *original.get_pixel(x.saturating_sub(1), y));
    let diagnosis = diagnosis("3", &shifted, "one-pixel-off.png");
    assert_eq!(named(&diagnosis), None, "{diagnosis}");
}
