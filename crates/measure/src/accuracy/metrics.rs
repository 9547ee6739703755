//! How far one picture is from the reference: on the linear values the
//! tracer computes (MSE, relative MSE), on the 8-bit values a PNG shows
//! (PSNR, pixels off), and as a viewer sees it (ꟻLIP, with the `flip`
//! feature).

use raybook::toolkit::{Color, Image};

/// The ε of the relative MSE: it keeps dark pixels, whose reference is
/// near 0, from dominating (the value used by Rousselle et al. 2011 and
/// most denoising papers since).
pub const RELATIVE_EPSILON: f64 = 0.01;

/// One render's errors against the reference.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Errors {
    /// Mean squared error over every channel of every pixel, on the
    /// unclamped linear values: MSE = (1/3P) Σ (x − r)².
    pub mse: f64,
    /// Relative MSE: (1/3P) Σ (x − r)² / (r² + ε), so that an error counts
    /// in proportion to the brightness it is seen against.
    pub relative_mse: f64,
    /// MSE of the 8-bit values a PNG stores, in steps of 1/255 squared.
    pub mse_8bit: f64,
    /// The share of pixels with some channel off by more than one 8-bit
    /// step in the PNG.
    pub pixels_off: f64,
    /// The mean ꟻLIP error (0 = no visible difference, 1 = the largest),
    /// when built with `--features flip`.
    pub flip: Option<f64>,
}

/// `image`'s errors against `reference`; the pictures must have one size.
pub fn errors(image: &Image, reference: &Image) -> Errors {
    let (a, b) = (image.to_rgb8(), reference.to_rgb8());
    let (mse_8bit, pixels_off) = errors_8bit(a.as_raw(), b.as_raw());
    Errors {
        mse: mse(image, reference),
        relative_mse: relative_mse(image, reference),
        mse_8bit,
        pixels_off,
        flip: flip(&a, &b),
    }
}

/// The mean over channels of `per_channel(x, r)` for every pixel pair.
fn mean_over_channels(
    image: &Image,
    reference: &Image,
    per_channel: impl Fn(f64, f64) -> f64,
) -> f64 {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "pictures of different sizes"
    );
    let channels = |c: Color| [c.x, c.y, c.z].map(f64::from);
    let sum: f64 = image
        .pixels
        .iter()
        .zip(&reference.pixels)
        .flat_map(|(&x, &r)| channels(x).into_iter().zip(channels(r)))
        .map(|(x, r)| per_channel(x, r))
        .sum();
    sum / (3 * image.pixels.len()).max(1) as f64
}

/// MSE = (1/3P) Σ (x − r)², on the unclamped linear values: what the
/// tracer computed, before the PNG clamps it.
pub fn mse(image: &Image, reference: &Image) -> f64 {
    mean_over_channels(image, reference, |x, r| (x - r) * (x - r))
}

/// relMSE = (1/3P) Σ (x − r)² / (r² + ε), ε = [`RELATIVE_EPSILON`].
pub fn relative_mse(image: &Image, reference: &Image) -> f64 {
    mean_over_channels(image, reference, |x, r| {
        (x - r) * (x - r) / (r * r + RELATIVE_EPSILON)
    })
}

/// The MSE of two 8-bit pictures in steps² and the share of pixels with a
/// channel more than one step apart.
fn errors_8bit(a: &[u8], b: &[u8]) -> (f64, f64) {
    let mut squares = 0u64;
    let mut off = 0usize;
    for (p, q) in a.chunks_exact(3).zip(b.chunks_exact(3)) {
        let steps = p.iter().zip(q).map(|(&x, &y)| x.abs_diff(y));
        let mut largest = 0;
        for d in steps {
            squares += u64::from(d) * u64::from(d);
            largest = largest.max(d);
        }
        off += usize::from(largest > 1);
    }
    let pixels = (a.len() / 3).max(1);
    (
        squares as f64 / (3 * pixels) as f64,
        off as f64 / pixels as f64,
    )
}

/// A PSNR on the 8-bit values: 10·log10(255² / MSE), MSE in steps². An
/// MSE of 0 has no finite PSNR; it is reported as above the PSNR of the
/// smallest error there could be, one step in one channel of one pixel
/// of `pixels` pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Psnr {
    /// The PSNR in dB.
    Db(f64),
    /// No difference at all: the PSNR is above this many dB.
    Above(f64),
}

impl Psnr {
    /// The PSNR of an 8-bit MSE (in steps²) over `pixels` pixels.
    pub fn of(mse_8bit: f64, pixels: usize) -> Psnr {
        let db = |mse: f64| 10.0 * (255.0 * 255.0 / mse).log10();
        if mse_8bit > 0.0 {
            Psnr::Db(db(mse_8bit))
        } else {
            Psnr::Above(db(1.0 / (3 * pixels.max(1)) as f64))
        }
    }
}

impl std::fmt::Display for Psnr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Psnr::Db(db) => write!(f, "{db:.1}"),
            Psnr::Above(db) => write!(f, "> {db:.1}"),
        }
    }
}

/// The mean ꟻLIP error of the 8-bit `image` against `reference` (NVIDIA's
/// implementation, through the `nv-flip` crate), the bytes read as sRGB
/// as a viewer shows the PNG, at 67 pixels per degree (a 0.7 m view of a
/// 0.7 m wide 4K screen, ꟻLIP's default).
#[cfg(feature = "flip")]
fn flip(image: &image::RgbImage, reference: &image::RgbImage) -> Option<f64> {
    let as_flip =
        |i: &image::RgbImage| nv_flip::FlipImageRgb8::with_data(i.width(), i.height(), i.as_raw());
    let map = nv_flip::flip(
        as_flip(reference),
        as_flip(image),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    );
    Some(f64::from(nv_flip::FlipPool::from_image(&map).mean()))
}

/// Without the `flip` feature: no ꟻLIP.
#[cfg(not(feature = "flip"))]
fn flip(_: &image::RgbImage, _: &image::RgbImage) -> Option<f64> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(values: &[f32]) -> Image {
        Image {
            width: values.len() as u32,
            height: 1,
            pixels: values.iter().map(|&v| Color::splat(v)).collect(),
        }
    }

    #[test]
    fn the_mse_counts_values_above_one_in_full() {
        // 2.0 against 1.0: clamped, both are white; unclamped, 1 apart.
        assert_eq!(mse(&image(&[2.0, 0.5]), &image(&[1.0, 0.5])), 0.5);
        let e = errors(&image(&[2.0, 0.5]), &image(&[1.0, 0.5]));
        assert_eq!((e.mse_8bit, e.pixels_off), (0.0, 0.0));
    }

    #[test]
    fn the_relative_mse_weighs_an_error_by_the_reference() {
        let dark = relative_mse(&image(&[0.1]), &image(&[0.0]));
        let bright = relative_mse(&image(&[1.1]), &image(&[1.0]));
        assert!((dark - 0.01 / 0.01).abs() < 1e-6, "{dark}");
        assert!((bright - 0.01 / 1.01).abs() < 1e-6, "{bright}");
    }

    #[test]
    fn equal_8bit_pictures_have_a_finite_psnr_bound_not_infinity() {
        assert_eq!(
            Psnr::of(1.0, 10),
            Psnr::Db(10.0 * (255.0f64 * 255.0).log10())
        );
        let Psnr::Above(db) = Psnr::of(0.0, 10) else {
            panic!("no difference is not a number of dB");
        };
        assert!(db.is_finite() && db > 48.0, "{db}");
        assert!(Psnr::of(0.0, 10).to_string().starts_with("> "));
    }

    #[test]
    fn a_pixel_is_off_when_a_channel_is_more_than_one_step_away() {
        let e = errors(&image(&[0.0, 0.0]), &image(&[1.0 / 255.0, 2.0 / 255.0]));
        assert_eq!(e.pixels_off, 0.5);
        assert!(
            (e.mse_8bit - (1.0 + 4.0) / 2.0).abs() < 1e-9,
            "{}",
            e.mse_8bit
        );
    }
}
