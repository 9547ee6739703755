//! Mistakes of the camera that verify names: right from the cross product
//! in the wrong order, rays through the pixels' corners, the fov taken as
//! horizontal, width and height swapped.

use ch03_lambert::Camera;
use workbook::toolkit::{Image, Scene};
use workbook::verify::{Mistake, Swap};
use workbook::workbench::compare::{Tolerance, compare};

use super::{assert_named, chapter3_scene, reference_image};

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
fn right_from_the_swapped_cross_product_is_named_a_turn_by_180_degrees() {
    // right = up₀ × forward, the order swapped, and up = right × forward
    // worked out from it: both point the wrong way.
    let scene = chapter3_scene();
    let mut camera = Camera::new(&scene.camera, 160, 120);
    camera.right = scene.camera.up.cross(camera.forward).normalize();
    camera.up = camera.right.cross(camera.forward);
    let turned = render_chapter3(&scene, &camera, |x, y| (x as f32 + 0.5, y as f32 + 0.5));
    assert_named(
        "3",
        &turned.to_rgb8(),
        "turned.png",
        Mistake::TurnedHalfway,
        "forward × up₀, not up₀ × forward",
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
fn half_a_pixel_added_twice_is_named_in_chapter_1s_sky() {
    // A student's slip: the ray of pixel (x, y) aimed at (x + 1, y + 1),
    // half a pixel added twice. Chapter 1's sky is the same along a row,
    // so the picture cannot tell the bottom-right corner from the
    // bottom-left: verify names the edge.
    let scene = ch01_rays::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(160, 120);
    let camera = ch01_rays::Camera::new(&scene.camera, 160, 120);
    let (image, _) = Image::render(
        160,
        120,
        |x, y, _| ch01_rays::sky(&camera.ray_through(x as f32 + 1.0, y as f32 + 1.0)),
        || {},
    );
    let shifted = Mistake::HalfPixelShift(workbook::verify::Corner::Bottom);
    assert_named("1", &image.to_rgb8(), "twice.png", shifted, "bottom edge");
}
