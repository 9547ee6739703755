//! Comparing two pictures with a stated tolerance, and drawing the difference.
//!
//! A byte-exact comparison is too brittle: an independent, correct tracer
//! differs from ours in the last bits of its floating-point sums, and after
//! rounding to 8 bits that can move a channel by one step. A real mistake (a
//! sphere one pixel off, a flipped normal, a missing object) changes many
//! pixels by a lot. The tolerance sits between the two.

use image::{Rgb, RgbImage};

/// How far a picture may be from its reference and still pass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// A channel differing by at most this many 8-bit steps counts as equal.
    /// 2 covers last-bit differences (one rounding step) with one to spare.
    pub channel: u8,
    /// How many pixels may differ by more than `channel`: one pixel in 1000
    /// (at least 2). A ray that grazes an object's edge may hit in one tracer
    /// and miss in another, and behind a glass or mirror sphere such an edge
    /// is magnified: the showcase moved 1000 units away from the origin,
    /// where f32 steps are 6e-5, differs in 12 of 19 200 such pixels. A real
    /// mistake changes far more: a one-pixel shift of a 20-pixel sphere
    /// already changes about 80.
    pub pixels: usize,
}

impl Tolerance {
    /// The snapshot tolerance for an image of this size.
    pub fn for_size(width: u32, height: u32) -> Tolerance {
        let count = width as usize * height as usize;
        Tolerance {
            channel: 2,
            pixels: (count / 1000).max(2),
        }
    }
}

/// How much two same-size pictures differ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Difference {
    /// Pixels with some channel off by more than the tolerance.
    pub pixels_over: usize,
    /// The largest difference of any channel, in 8-bit steps.
    pub largest: u8,
    /// All pixels compared.
    pub total: usize,
}

/// The outcome of comparing a picture with its reference.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Within the tolerance.
    Pass(Difference),
    /// Same size, too different.
    Differs(Difference),
    /// Not the same size: (width, height) expected and found.
    WrongSize {
        expected: (u32, u32),
        found: (u32, u32),
    },
}

impl Verdict {
    pub fn passed(&self) -> bool {
        matches!(self, Verdict::Pass(_))
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Verdict::Pass(d) | Verdict::Differs(d) => write!(
                f,
                "{} of {} pixels differ by more than the tolerance; largest channel difference {}/255",
                d.pixels_over, d.total, d.largest
            ),
            Verdict::WrongSize { expected, found } => write!(
                f,
                "the image is {}×{} but the reference is {}×{}",
                found.0, found.1, expected.0, expected.1
            ),
        }
    }
}

/// The largest channel difference of two pixels.
fn pixel_difference(a: &Rgb<u8>, b: &Rgb<u8>) -> u8 {
    (0..3).map(|i| a[i].abs_diff(b[i])).max().unwrap_or(0)
}

/// Compares `actual` with `expected` under `tolerance`.
pub fn compare(expected: &RgbImage, actual: &RgbImage, tolerance: Tolerance) -> Verdict {
    if expected.dimensions() != actual.dimensions() {
        return Verdict::WrongSize {
            expected: expected.dimensions(),
            found: actual.dimensions(),
        };
    }
    let mut difference = Difference {
        pixels_over: 0,
        largest: 0,
        total: expected.pixels().len(),
    };
    for (a, b) in expected.pixels().zip(actual.pixels()) {
        let d = pixel_difference(a, b);
        difference.largest = difference.largest.max(d);
        if d > tolerance.channel {
            difference.pixels_over += 1;
        }
    }
    if difference.pixels_over <= tolerance.pixels {
        Verdict::Pass(difference)
    } else {
        Verdict::Differs(difference)
    }
}

/// Three panels side by side: expected | mask | actual. The mask is black
/// where the pictures agree, grey where they differ within the tolerance and
/// red where they differ by more.
pub fn diff_image(expected: &RgbImage, actual: &RgbImage, tolerance: Tolerance) -> RgbImage {
    let (w, h) = (
        expected.width().max(actual.width()),
        expected.height().max(actual.height()),
    );
    let mut out = RgbImage::new(3 * w, h);
    for (x, y, p) in expected.enumerate_pixels() {
        out.put_pixel(x, y, *p);
    }
    for (x, y, p) in actual.enumerate_pixels() {
        out.put_pixel(2 * w + x, y, *p);
    }
    for y in 0..h {
        for x in 0..w {
            let (a, b) = (
                expected.get_pixel_checked(x, y),
                actual.get_pixel_checked(x, y),
            );
            let d = match (a, b) {
                (Some(a), Some(b)) => pixel_difference(a, b),
                _ => u8::MAX,
            };
            let mask = match d {
                0 => Rgb([0, 0, 0]),
                d if d <= tolerance.channel => Rgb([96, 96, 96]),
                _ => Rgb([255, 0, 0]),
            };
            out.put_pixel(w + x, y, mask);
        }
    }
    out
}

/// The root mean square difference of two same-size pictures in linear RGB,
/// over every channel of every pixel, as they are (values above 1 count in
/// full). Panics if the sizes differ.
pub fn rmse(expected: &ch00_toolkit::Image, actual: &ch00_toolkit::Image) -> f64 {
    squared_error(expected, actual, |c| c).sqrt()
}

/// [`rmse`] of the pictures as a PNG shows them: each channel clamped to
/// [0, 1] first (before the rounding to 8 bits).
pub fn rmse_clamped(expected: &ch00_toolkit::Image, actual: &ch00_toolkit::Image) -> f64 {
    squared_error(expected, actual, |c| {
        c.clamp(ch00_toolkit::Color::ZERO, ch00_toolkit::Color::ONE)
    })
    .sqrt()
}

/// The peak signal-to-noise ratio in decibels of an `rmse` measured on
/// values whose peak (white) is 1: 20·log10(1 / rmse). Infinite for equal
/// pictures; 48.1 dB for an error of one 8-bit step (1/255).
pub fn psnr(rmse: f64) -> f64 {
    -20.0 * rmse.log10()
}

/// The mean squared difference of two same-size pictures, each channel
/// first passed through `view`.
fn squared_error(
    expected: &ch00_toolkit::Image,
    actual: &ch00_toolkit::Image,
    view: impl Fn(ch00_toolkit::Color) -> ch00_toolkit::Color,
) -> f64 {
    assert_eq!(
        (expected.width, expected.height),
        (actual.width, actual.height),
        "pictures of different sizes"
    );
    let sum: f64 = expected
        .pixels
        .iter()
        .zip(&actual.pixels)
        .map(|(&e, &a)| {
            let d = view(e) - view(a);
            f64::from(d.x).powi(2) + f64::from(d.y).powi(2) + f64::from(d.z).powi(2)
        })
        .sum();
    sum / (3 * expected.pixels.len()).max(1) as f64
}
