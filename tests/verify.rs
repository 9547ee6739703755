//! `raybook verify` accepts a correct picture and names what is wrong with
//! a mistaken one.

use std::path::PathBuf;
use std::process::Command;

use ch03_lambert::{Surface, direct_light, lambert};
use raybook::toolkit::Image;
use raybook::verify::{reference, verify};

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raybook-verify-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn reference_image(chapter: &str) -> image::RgbImage {
    image::load_from_memory(reference(chapter).unwrap().png)
        .unwrap()
        .to_rgb8()
}

fn save(name: &str, picture: &image::RgbImage) -> PathBuf {
    let path = temp(name);
    picture.save(&path).unwrap();
    path
}

fn passes(chapter: &str, picture: &image::RgbImage, name: &str) -> bool {
    let path = save(name, picture);
    let outcome = verify(
        &reference(chapter).unwrap(),
        &path,
        &temp(&format!("{name}.diff.png")),
    )
    .unwrap();
    println!("{name}: {}", outcome.verdict);
    outcome.verdict.passed()
}

#[test]
fn chapters_are_found_by_number_folder_or_package() {
    for name in ["3", "03", "03-lambert", "ch03-lambert"] {
        assert_eq!(reference(name).unwrap().chapter.folder, "03-lambert");
    }
    assert!(reference("9").is_none());
}

#[test]
fn the_reference_itself_passes() {
    let chapters: Vec<String> = raybook::verify::references()
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
}

#[test]
fn a_wrong_size_fails_with_a_clear_message() {
    let small = image::RgbImage::new(320, 240);
    let path = save("big.png", &small);
    let output = Command::new(env!("CARGO_BIN_EXE_raybook"))
        .args(["verify", "3"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!output.status.success());
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("FAIL"), "{stdout}");
    assert!(
        stdout.contains("the image is 320×240 but the reference is 160×120"),
        "{stdout}"
    );
    assert!(stdout.contains("--width 160 --height 120"), "{stdout}");
}

#[test]
fn the_command_passes_the_reference_and_writes_a_diff() {
    let path = save("mine.png", &reference_image("7"));
    let output = Command::new(env!("CARGO_BIN_EXE_raybook"))
        .args(["verify", "07-termination"])
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    assert!(stdout.starts_with("PASS"), "{stdout}");
    assert!(path.with_extension("diff.png").exists());
}
