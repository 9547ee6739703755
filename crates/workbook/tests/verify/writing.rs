//! Mistakes in writing the picture that verify names: upside down, mirrored,
//! gamma-encoded, channels in BGR order, colours wrapped instead of clamped.

use workbook::verify::Mistake;

use super::{assert_named, chapter3_scene, reference_image};

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

/// Chapters 1 and 2 first show the camera's commonest mistake, right =
/// up₀ × forward, which turns the picture by 180° (right and up both
/// reversed: exactly the reference turned round).
#[test]
fn a_picture_turned_by_180_degrees_is_named_in_chapters_1_and_2() {
    for chapter in ["1", "2"] {
        let turned = image::imageops::rotate180(&reference_image(chapter));
        assert_named(
            chapter,
            &turned,
            &format!("turned-{chapter}.png"),
            Mistake::TurnedHalfway,
            "turned by 180°",
        );
    }
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
