//! `workbook verify` accepts a correct picture and names what is wrong with
//! a mistaken one.

use ch03_lambert::scene_files;
use std::path::PathBuf;
use std::process::Command;

use ch03_lambert::{Camera, Surface, direct_light, lambert};
use workbook::toolkit::{Color, Image, Scene};
use workbook::verify::{
    Diagnosis, Mistake, ObjectMap, ObjectName, Reference, Swap, reference, references, shape_name,
    verify,
};
use workbook::workbench::compare::{Tolerance, compare};
use workbook::workbench::snapshot::workspace_root;

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

/// Verifies a picture that must fail and returns what verify says about it
/// (printed, with the picture's path, to look at with `--nocapture`).
fn diagnosis(chapter: &str, picture: &image::RgbImage, name: &str) -> Diagnosis {
    let path = save(name, picture);
    let diff = temp(&format!("{name}.diff.png"));
    let outcome = verify(&reference(chapter).unwrap(), &path, &diff).unwrap();
    assert!(!outcome.verdict.passed(), "{name} passes");
    let diagnosis = outcome.diagnosis.expect("a failing picture is diagnosed");
    println!("{}: {}\n{diagnosis}", path.display(), outcome.verdict);
    diagnosis
}

/// The usual mistake a diagnosis names, if any.
fn named(diagnosis: &Diagnosis) -> Option<Mistake> {
    match diagnosis {
        Diagnosis::Mistake { mistake, .. } => Some(*mistake),
        Diagnosis::Differs(_) => None,
    }
}

/// Asserts that verify names `mistake` for `picture`, in words that contain `words`.
fn assert_named(
    chapter: &str,
    picture: &image::RgbImage,
    name: &str,
    mistake: Mistake,
    words: &str,
) {
    let diagnosis = diagnosis(chapter, picture, name);
    assert_eq!(named(&diagnosis), Some(mistake), "{diagnosis}");
    assert!(diagnosis.to_string().contains(words), "{diagnosis}");
}

/// Chapter 3's default scene at the reference size.
fn chapter3_scene() -> Scene {
    ch03_lambert::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(160, 120)
}

/// Chapter 3's picture rendered with one ray per pixel, through image
/// position `aim(x, y)` of `camera`, unclamped.
fn render_chapter3(
    scene: &Scene,
    camera: &Camera,
    aim: impl Fn(u32, u32) -> (f32, f32) + Sync,
) -> Image {
    let (image, _) = Image::render(
        160,
        120,
        |x, y, _| {
            let (px, py) = aim(x, y);
            ch03_lambert::trace(scene, &camera.ray_through(px, py))
        },
        || {},
    );
    image
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

#[test]
fn a_wrong_size_fails_with_a_clear_message() {
    let small = image::RgbImage::new(320, 240);
    let path = save("big.png", &small);
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
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
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "07-termination"])
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    assert!(stdout.starts_with("PASS"), "{stdout}");
    assert!(path.with_extension("diff.png").exists());
}

#[test]
fn a_picture_upside_down_is_named() {
    let flipped = image::imageops::flip_vertical(&reference_image("4"));
    assert_named(
        "4",
        &flipped,
        "upside-down.png",
        Mistake::FlippedTopToBottom,
        "upside down",
    );
}

#[test]
fn a_mirrored_picture_is_named() {
    let mirrored = image::imageops::flip_horizontal(&reference_image("3"));
    assert_named(
        "3",
        &mirrored,
        "mirrored.png",
        Mistake::MirroredLeftToRight,
        "mirrored",
    );
}

/// The reference with every channel passed through `encode` (values in [0, 1]).
fn encoded(chapter: &str, encode: impl Fn(f32) -> f32) -> image::RgbImage {
    let mut picture = reference_image(chapter);
    for p in picture.pixels_mut() {
        p.0 =
            p.0.map(|b| (encode(f32::from(b) / 255.0) * 255.0).round() as u8);
    }
    picture
}

#[test]
fn an_srgb_encoded_picture_is_named() {
    let srgb = |v: f32| {
        if v <= 0.0031308 {
            12.92 * v
        } else {
            1.055 * v.powf(1.0 / 2.4) - 0.055
        }
    };
    let picture = encoded("5", srgb);
    assert_named("5", &picture, "srgb.png", Mistake::GammaEncoded, "gamma");
}

#[test]
fn a_gamma_2_2_picture_is_named() {
    let picture = encoded("6", |v| v.powf(1.0 / 2.2));
    assert_named("6", &picture, "gamma.png", Mistake::GammaEncoded, "gamma");
}

#[test]
fn channels_in_bgr_order_are_named() {
    let mut picture = reference_image("2");
    picture.pixels_mut().for_each(|p| p.0.reverse());
    assert_named("2", &picture, "bgr.png", Mistake::ChannelsBgr, "BGR");
}

#[test]
fn wrapped_colours_are_named() {
    // Chapter 3's picture before clamping has channels above 1 under the
    // spot light; a C cast (unsigned char)(v*255 + 0.5) wraps them around.
    let (image, _) = ch03_lambert::render_lambert(&chapter3_scene(), || {});
    assert!(image.pixels.iter().any(|c| c.max_element() > 1.1));
    let bytes = image
        .pixels
        .iter()
        .flat_map(|c| c.to_array())
        .map(|v| (v * 255.0 + 0.5) as u32 as u8)
        .collect();
    let wrapped = image::RgbImage::from_raw(160, 120, bytes).unwrap();
    assert_named(
        "3",
        &wrapped,
        "wrapped.png",
        Mistake::ColoursWrapped,
        "clamp",
    );
}

#[test]
fn rays_through_pixel_corners_are_named() {
    // The chapter's tracer, its rays aimed at (x, y) instead of (x + 0.5, y + 0.5).
    let scene = chapter3_scene();
    let camera = Camera::new(&scene.camera, 160, 120);
    let corners = render_chapter3(&scene, &camera, |x, y| (x as f32, y as f32));
    // The same picture, up to the last bits of the rays' directions, as
    // chapter_through_corners makes for the showcase.
    let emulated =
        chapter_through_corners(&scene, |scene| ch03_lambert::render_lambert(scene, || {}).0);
    let same = compare(&corners.to_rgb8(), &emulated, Tolerance::for_size(160, 120));
    assert!(same.passed(), "{same}");
    assert_named(
        "3",
        &corners.to_rgb8(),
        "corners.png",
        Mistake::HalfPixelShift(workbook::verify::Corner::TopLeft),
        "half a pixel",
    );
}

#[test]
fn the_fov_taken_as_horizontal_is_named() {
    // The chapter's camera, with half_width = tan(fov/2) and half_height from
    // the aspect ratio: the scene's vertical fov used as the horizontal one.
    let scene = chapter3_scene();
    let mut camera = Camera::new(&scene.camera, 160, 120);
    camera.half_width = (scene.camera.vfov_degrees.to_radians() / 2.0).tan();
    camera.half_height = camera.half_width * 120.0 / 160.0;
    let centres = render_chapter3(&scene, &camera, |x, y| (x as f32 + 0.5, y as f32 + 0.5));
    assert_named(
        "3",
        &centres.to_rgb8(),
        "horizontal-fov.png",
        Mistake::FovUsedAsHorizontal,
        "vertical field of view",
    );
}

/// A chapter's picture of `scene` with the rays through the pixels'
/// top-left corners, by the chapter's own `render`: rendered one pixel
/// larger each way with the image plane grown to match, so that the pixel
/// centres of the larger picture fall on the corners of the smaller, and
/// cropped to 160×120.
fn chapter_through_corners(scene: &Scene, render: impl Fn(&Scene) -> Image) -> image::RgbImage {
    let mut larger = scene.clone().with_size(161, 121);
    let half_height = (scene.camera.vfov_degrees.to_radians() / 2.0).tan() * 121.0 / 120.0;
    larger.camera.vfov_degrees = 2.0 * half_height.atan().to_degrees();
    let picture = render(&larger).to_rgb8();
    image::imageops::crop_imm(&picture, 0, 0, 160, 120).to_image()
}

/// Chapter 7's default scene (the showcase: a checkerboard, a mirror and a
/// glass sphere) at the reference size.
fn chapter7_scene() -> Scene {
    ch07_termination::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(160, 120)
}

/// Chapter 7's picture of a scene.
fn render_chapter7(scene: &Scene) -> Image {
    let termination = ch07_termination::Termination::of(scene);
    ch07_termination::render_terminated(scene, termination, || {}).0
}

#[test]
fn rays_through_pixel_corners_are_named_in_the_showcase() {
    // Fine detail (the far checkerboard, the glass sphere) differs by more
    // than a half-pixel resampling of the reference explains.
    let corners = chapter_through_corners(&chapter7_scene(), render_chapter7);
    let corner = Mistake::HalfPixelShift(workbook::verify::Corner::TopLeft);
    assert_named("7", &corners, "corners-7.png", corner, "top-left corner");
}

#[test]
fn the_fov_taken_as_horizontal_is_named_in_the_showcase() {
    // A tracer taking the fov as horizontal sees tan(fov/2)·height/width
    // above the centre: the same rays as a camera of that vertical fov.
    let mut scene = chapter7_scene();
    let half_height = (scene.camera.vfov_degrees.to_radians() / 2.0).tan() * 120.0 / 160.0;
    scene.camera.vfov_degrees = 2.0 * half_height.atan().to_degrees();
    let zoomed = render_chapter7(&scene).to_rgb8();
    let mistake = Mistake::FovUsedAsHorizontal;
    assert_named(
        "7",
        &zoomed,
        "horizontal-fov-7.png",
        mistake,
        "zoomed in by 4/3",
    );
}

#[test]
fn a_swapped_size_is_named() {
    // The right pixels in a file written 120 wide and 160 tall.
    let picture = reference_image("7");
    let reread = image::RgbImage::from_raw(120, 160, picture.clone().into_raw()).unwrap();
    let swap = Mistake::SizeSwapped(Swap::SizeOnly);
    assert_named("7", &reread, "size-only.png", swap, "120 wide and 160 tall");
    // Pixel (x, y) stored at (y, x).
    let transposed = image::RgbImage::from_fn(120, 160, |x, y| *picture.get_pixel(y, x));
    let swap = Mistake::SizeSwapped(Swap::Transposed);
    assert_named(
        "7",
        &transposed,
        "transposed.png",
        swap,
        "x and y exchanged",
    );
    // The scene rendered 120 wide and 160 tall.
    let (tall, _) = ch03_lambert::render_lambert(&chapter3_scene().with_size(120, 160), || {});
    let swap = Mistake::SizeSwapped(Swap::Other);
    assert_named(
        "3",
        &tall.to_rgb8(),
        "tall.png",
        swap,
        "render 160 pixels across",
    );
}

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

#[test]
fn the_command_names_the_mistake_and_its_fix() {
    let flipped = image::imageops::flip_vertical(&reference_image("3"));
    let path = save("flipped-command.png", &flipped);
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "3"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!output.status.success());
    let stdout = String::from_utf8_lossy(&output.stdout);
    println!("{stdout}");
    assert!(stdout.starts_with("FAIL"), "{stdout}");
    assert!(
        stdout.contains("diff (reference | mask | yours)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("likely mistake: your picture is upside down"),
        "{stdout}"
    );
    assert!(stdout.contains("\nfix: row 0 is the top"), "{stdout}");
}

/// The object map of a reference, computed from its chapter's default scene
/// as the reference is rendered (160×120, one ray per pixel through its
/// centre): each pixel's first object hit, by chapter 2's closest hit
/// through chapter 1's camera.
fn object_map(reference: &Reference) -> ObjectMap {
    let scene = scene_files::load(workspace_root().join(reference.chapter.default_scene_path()))
        .unwrap()
        .with_size(160, 120);
    assert!(
        scene.image.samples <= 1,
        "a reference has one ray per pixel"
    );
    let camera = ch02_hits::Camera::new(&scene.camera, 160, 120);
    let hit = |x, y| {
        ch02_hits::closest_hit(
            &scene.objects,
            &camera.primary_ray(x, y),
            0.0,
            f32::INFINITY,
        )
        .map(|hit| hit.object)
    };
    let objects = scene.objects.iter().map(|object| ObjectName {
        shape: shape_name(&object.shape).to_owned(),
        material: scene.material(object).name.clone(),
    });
    ObjectMap {
        width: 160,
        height: 120,
        objects: objects.collect(),
        pixels: (0..120)
            .flat_map(|y| (0..160).map(move |x| hit(x, y)))
            .collect(),
    }
}

#[test]
fn the_object_maps_are_current() {
    let write = std::env::var_os("RAYBOOK_WRITE_OBJECT_MAPS").is_some();
    let mut stale = Vec::new();
    for reference in references() {
        let name = reference.objects_path();
        let path = workspace_root().join("snapshots").join(&name);
        let picture = name
            .rsplit('/')
            .next()
            .unwrap()
            .replace(".objects.txt", ".snap.png");
        let text = object_map(&reference).to_text(&picture);
        assert_eq!(ObjectMap::parse(&text).unwrap(), object_map(&reference));
        if write {
            std::fs::write(&path, &text).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(&text) {
            stale.push(path);
        } else {
            assert_eq!(
                reference.objects,
                Some(text.as_str()),
                "the workbook binary embeds an older {name}: rebuild it (touch crates/workbook/src/verify/mod.rs)"
            );
        }
    }
    assert!(
        stale.is_empty(),
        "stale or missing object maps {stale:?}; regenerate them with\n  \
         RAYBOOK_WRITE_OBJECT_MAPS=1 cargo test -p workbook --test verify the_object_maps_are_current"
    );
}
