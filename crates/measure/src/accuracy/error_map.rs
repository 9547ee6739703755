//! Error maps: where in the picture a setting's error is. Each pixel's
//! RMSE over its three channels against the reference, on a log scale from
//! 10⁻⁴ (black) to 1 (white), through magenta and orange. The scale is a
//! picture of its own, `error-scale.svg`, with a labelled tick per decade.

use std::path::{Path, PathBuf};

use raybook::toolkit::image::{encode_png, write_atomically};
use raybook::toolkit::{Color, Image};

use super::settings::{Sampling, Setting};

/// The smallest error the map tells from none: black below it.
pub const SMALLEST: f64 = 1e-4;

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

/// The map of `image` against `reference`.
pub fn map(image: &Image, reference: &Image) -> ::image::RgbImage {
    let (w, h) = (image.width, image.height);
    let mut out = ::image::RgbImage::new(w, h);
    for (i, (&x, &r)) in image.pixels.iter().zip(&reference.pixels).enumerate() {
        let d: Color = x - r;
        let e = (f64::from(d.dot(d)) / 3.0).sqrt();
        out.put_pixel(i as u32 % w, i as u32 / w, ::image::Rgb(colour(e)));
    }
    out
}

/// The colour bar of the maps, as SVG into `path`: the scale from
/// [`SMALLEST`] to 1 with a tick and a label at each decade, and its name.
pub fn scale_plot(path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::coord::combinators::BindKeyPoints;
    use plotters::prelude::*;
    let root = SVGBackend::new(path, (560, 110)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .margin_left(30)
        .margin_right(40)
        .margin_top(10)
        .x_label_area_size(60)
        .build_cartesian_2d(
            (SMALLEST..1.0)
                .log_scale()
                .with_key_points(vec![1e-4, 1e-3, 1e-2, 1e-1, 1.0]),
            0.0..1.0,
        )?;
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(("sans-serif", super::plot::TEXT))
        .axis_desc_style(("sans-serif", super::plot::TEXT))
        .x_desc("each pixel's RMSE against the reference (black: below 1e-4)")
        .draw()?;
    let steps = 200;
    let decades = -SMALLEST.log10();
    chart.draw_series((0..steps).map(|i| {
        let at = |i: i32| SMALLEST * 10f64.powf(decades * f64::from(i) / f64::from(steps));
        let [r, g, b] = colour(at(i) * 1.0001);
        Rectangle::new([(at(i), 0.0), (at(i + 1), 1.0)], RGBColor(r, g, b).filled())
    }))?;
    root.present()?;
    Ok(())
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
