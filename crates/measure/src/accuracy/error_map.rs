//! Error maps: where in the picture a setting's error is. Each pixel's
//! RMSE over its three channels against the reference, on a log scale from
//! 10⁻⁴ (black) to 1 (white), through magenta and orange; a strip at the
//! bottom shows the scale, one decade per quarter.

use std::path::{Path, PathBuf};

use raybook::toolkit::image::{encode_png, write_atomically};
use raybook::toolkit::{Color, Image};

use super::settings::{Sampling, Setting};

/// The smallest error the map tells from none: black below it.
pub const SMALLEST: f64 = 1e-4;

/// Rows of the scale strip under the map.
const STRIP: u32 = 12;

/// A name for `setting`'s map file: depth, threshold, sampling.
pub fn file_name(setting: &Setting) -> String {
    let sampling = match setting.sampling {
        Sampling::Centre => "centre".to_owned(),
        Sampling::Jittered(n) => format!("jittered{n}"),
    };
    let t = setting.termination;
    format!(
        "error-depth{}-threshold{}-{sampling}.png",
        t.max_depth, t.min_weight
    )
}

/// The colour of an error `e` ≥ 0: its place t ∈ [0, 1] on the log scale
/// from [`SMALLEST`] to 1, through black, magenta, orange, white.
fn colour(e: f64) -> [u8; 3] {
    let t =
        ((e.max(SMALLEST * 0.999).log10() - SMALLEST.log10()) / -SMALLEST.log10()).clamp(0.0, 1.0);
    if e < SMALLEST {
        return [0, 0, 0];
    }
    let stops = [
        (0.0, [20.0, 10.0, 40.0]),
        (0.35, [160.0, 30.0, 130.0]),
        (0.7, [250.0, 140.0, 40.0]),
        (1.0, [255.0, 255.0, 255.0]),
    ];
    let i = stops
        .iter()
        .rposition(|&(at, _)| at <= t)
        .unwrap_or(0)
        .min(2);
    let ((a, ca), (b, cb)) = (stops[i], stops[i + 1]);
    let f = (t - a) / (b - a);
    [0, 1, 2].map(|k| (ca[k] + f * (cb[k] - ca[k])).round() as u8)
}

/// The map of `image` against `reference`, with the scale strip.
pub fn map(image: &Image, reference: &Image) -> ::image::RgbImage {
    let (w, h) = (image.width, image.height);
    let mut out = ::image::RgbImage::new(w, h + STRIP);
    for (i, (&x, &r)) in image.pixels.iter().zip(&reference.pixels).enumerate() {
        let d: Color = x - r;
        let e = (f64::from(d.dot(d)) / 3.0).sqrt();
        out.put_pixel(i as u32 % w, i as u32 / w, ::image::Rgb(colour(e)));
    }
    for x in 0..w {
        let t = (f64::from(x) + 0.5) / f64::from(w);
        let e = SMALLEST.powf(1.0 - t);
        for y in h + 2..h + STRIP {
            out.put_pixel(x, y, ::image::Rgb(colour(e)));
        }
    }
    out
}

/// Writes the map of each kept picture into `folder`, each atomically;
/// returns the files written.
pub fn write_maps(
    kept: &[(Setting, Image)],
    reference: &Image,
    folder: &Path,
) -> std::io::Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for (setting, image) in kept {
        let path = folder.join(file_name(setting));
        write_atomically(&path, &encode_png(&map(image, reference)))?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_runs_from_black_to_white_and_grows_brighter() {
        assert_eq!(colour(0.0), [0, 0, 0]);
        assert_eq!(colour(1.0), [255, 255, 255]);
        let brightness = |e: f64| colour(e).iter().map(|&c| u32::from(c)).sum::<u32>();
        let mut last = 0;
        for k in 0..=16 {
            let b = brightness(SMALLEST.powf(1.0 - f64::from(k) / 16.0));
            assert!(b >= last, "at step {k}: {b} < {last}");
            last = b;
        }
    }
}
