//! Which pictures pass (the reference, one step of noise) and which fail.

use ch03_lambert::{Surface, direct_light, lambert};
use workbook::toolkit::Image;
use workbook::verify::reference;

use super::{diagnosis, named, passes, reference_image};

#[test]
fn chapters_are_found_by_number_folder_or_package() {
    for name in ["3", "03", "03-lambert", "ch03-lambert"] {
        assert_eq!(reference(name).unwrap().chapter.folder, "03-lambert");
    }
    assert!(reference("9").is_none());
}

#[test]
fn the_reference_itself_passes() {
    let chapters: Vec<String> = workbook::verify::references()
        .iter()
        .map(|r| r.chapter.number().to_string())
        .collect();
    assert_eq!(chapters, ["1", "2", "3", "4", "5", "6", "7"]);
    for chapter in &chapters {
        assert!(passes(
            chapter,
            &reference_image(chapter),
            &format!("same-{chapter}.png")
        ));
    }
}

#[test]
fn one_step_of_noise_passes() {
    let mut noisy = reference_image("5");
    for (i, p) in noisy.pixels_mut().enumerate() {
        for (c, v) in p.0.iter_mut().enumerate() {
            *v = if (i + c) % 2 == 0 {
                v.saturating_add(1)
            } else {
                v.saturating_sub(1)
            };
        }
    }
    assert!(passes("5", &noisy, "noisy.png"));
}

#[test]
fn a_picture_one_pixel_off_fails() {
    let original = reference_image("3");
    let shifted = image::RgbImage::from_fn(original.width(), original.height(), |x, y| {
        *original.get_pixel(x.saturating_sub(1), y)
    });
    assert!(!passes("3", &shifted, "shifted.png"));
}

#[test]
fn flipped_normals_fail() {
    // A student's Lambert shading with the normal pointing the wrong way.
    let scene = ch03_lambert::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(160, 120);
    let (flipped, _) = ch03_lambert::render(
        &scene,
        |ray, _| match ch03_lambert::closest_hit(&scene.objects, ray, 0.0, f32::INFINITY) {
            None => scene.image.background,
            Some(hit) => {
                let mut surface = Surface::new(&scene, hit, ray);
                surface.normal = -surface.normal;
                direct_light(
                    &scene,
                    &surface,
                    |_, _| true,
                    |incoming| lambert(&surface, incoming),
                )
            }
        },
        || {},
    );
    let flipped: Image = flipped;
    assert!(!passes("3", &flipped.to_rgb8(), "flipped.png"));
    let diagnosis = diagnosis("3", &flipped.to_rgb8(), "flipped-normals.png");
    assert_eq!(named(&diagnosis), None, "{diagnosis}");
}
