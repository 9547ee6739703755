//! The study drawn, as SVG files: RMSE against rays per pixel with the
//! guide slopes N^-½ and N^-1, the same for several depths, RMSE against
//! rays with the Pareto front, and the effects as bars. Every error is
//! drawn where it was measured; the reference's floor is a shaded band,
//! under which no measured error can be trusted.
//!
//! Drawn for the book's column (about 750 pixels wide): each plot is
//! [`SIZE`] wide, so that it is shown near its own size, and no text is
//! smaller than [`TEXT`] pixels. The log axes have no minor grid lines
//! (between 1 and 16 they crowd into a grey band that reads as the floor's);
//! curves that coincide are set apart by a small shift along N and a marker
//! of their own.

use std::path::{Path, PathBuf};

use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::Study;
use super::report::{cost, pareto};
use super::summary::Summary;

mod chart;

use chart::*;

/// Each plot's size in pixels: about the book's column.
const SIZE: (u32, u32) = (760, 540);

/// The smallest text, in pixels: at the book's width, at least 12.
pub(super) const TEXT: u32 = 15;

/// The title's text, in pixels.
pub(super) const TITLE: u32 = 19;

/// A plot's file name and what draws it.
type Plot<'a> = (&'a str, &'a dyn Fn(&Study, &Path) -> Drawn);

/// Writes every plot into `folder`, each atomically, and returns their paths.
pub fn plot_all(study: &Study, folder: &Path) -> Result<Vec<PathBuf>, String> {
    let plots: [Plot; 5] = [
        ("accuracy-samples.svg", &samples_plot),
        ("accuracy-depths.svg", &depths_plot),
        ("accuracy-rays.svg", &rays_plot),
        ("accuracy-effects.svg", &super::bars::effects_plot),
        ("error-scale.svg", &|_, p| super::error_map::scale_plot(p)),
    ];
    std::fs::create_dir_all(folder).map_err(|e| e.to_string())?;
    let mut written = Vec::new();
    for (name, draw) in plots {
        let path = folder.join(name);
        let partial = path.with_extension("svg.partial");
        draw(study, &partial).map_err(|e| format!("{}: {e}", path.display()))?;
        std::fs::rename(&partial, &path).map_err(|e| e.to_string())?;
        written.push(path);
    }
    Ok(written)
}

/// RMSE against rays per pixel, jittered, at the grid's most accurate
/// termination, with the centre ray beside it and guide slopes through
/// the one-ray point: N^-½ (independent samples) and N^-1.
fn samples_plot(study: &Study, path: &Path) -> Drawn {
    let termination = study.most_accurate();
    let curve = study.curve(termination);
    let centre = study.centre(termination);
    let rows = curve.iter().copied().chain(centre);
    let y = rmse_range(rows, study.floor.mse.sqrt());
    let largest = curve
        .last()
        .map_or(64.0, |r| f64::from(r.setting.sampling.samples()));
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    let title = format!(
        "RMSE against rays per pixel (depth {}, threshold {})",
        termination.max_depth, termination.min_weight
    );
    let mut chart = log_chart(
        &root,
        &title,
        ("rays per pixel N", 0.7..largest * 1.5, n_ticks(study)),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    if let Some(first) = curve.first() {
        // Each guide's dashes, drawn the same in the legend.
        for (power, name, (dash, gap)) in [
            (0.5, "guide: N^-½ (independent samples)", (10, 5)),
            (1.0, "guide: N^-1", (3, 4)),
        ] {
            let guide = (0..=40).map(|i| {
                let n = largest.powf(f64::from(i) / 40.0);
                (n, first.rmse * n.powf(-power))
            });
            let style = BLACK.stroke_width(2);
            chart
                .draw_series(DashedLineSeries::new(guide, dash, gap, style))?
                .label(name)
                .legend(move |(x, y)| {
                    DashedPathElement::new([(x, y), (x + 24, y)], dash, gap, style)
                });
        }
    }
    let look = Look {
        colour: COLOURS[0],
        marker: Marker::Circle,
        shift: 1.0,
    };
    draw_curve(
        &mut chart,
        &curve,
        look,
        "jittered: mean ± sd over seeds".to_owned(),
    )?;
    if let Some(c) = centre {
        // Beside N = 1, so that it does not cover the jittered ray's dot.
        let colour = COLOURS[3];
        chart
            .draw_series([EmptyElement::at((1.12, c.rmse))
                + Polygon::new(Marker::Triangle.outline(0), colour.filled())])?
            .label("one ray through the centre (at N = 1)")
            .legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + Polygon::new(Marker::Triangle.outline(12), colour.filled())
            });
    }
    finish(&mut chart, &root)
}

/// RMSE against rays per pixel at threshold 0 for every depth of the
/// grid: each curve flattens where its bias is reached.
fn depths_plot(study: &Study, path: &Path) -> Drawn {
    let threshold = study.most_accurate().min_weight;
    let curves: Vec<(u32, Vec<&Summary>)> = study
        .plan
        .depths
        .iter()
        .map(|&d| {
            let mut termination = study.most_accurate();
            termination.max_depth = d;
            termination.min_weight = threshold;
            (d, study.curve(termination))
        })
        .collect();
    let all = curves.iter().flat_map(|(_, c)| c.iter().copied());
    let y = rmse_range(all, study.floor.mse.sqrt());
    let largest = f64::from(
        study
            .plan
            .samplings
            .iter()
            .map(|s| s.samples())
            .max()
            .unwrap_or(1),
    );
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    let title = format!("RMSE against rays per pixel, one curve per depth (threshold {threshold})");
    let mut chart = log_chart(
        &root,
        &title,
        (
            "jittered rays per pixel N (each depth shifted a little, to stay apart)",
            0.7..largest * 1.5,
            n_ticks(study),
        ),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    // Depths whose curves coincide (their bias at the floor) would hide
    // one another: each is shifted along N by a few percent and has its
    // own marker.
    let middle = (curves.len() as f64 - 1.0) / 2.0;
    for (i, (depth, curve)) in curves.iter().enumerate() {
        let look = Look {
            colour: COLOURS[i % COLOURS.len()],
            marker: MARKERS[i % MARKERS.len()],
            shift: 1.07f64.powf(i as f64 - middle),
        };
        draw_curve(&mut chart, curve, look, format!("max depth {depth}"))?;
    }
    // Lower left: the curves start high at N = 1 and fall to the right,
    // and the upper right holds the shallow depths' flat curves.
    finish_at(&mut chart, &root, SeriesLabelPosition::LowerLeft)
}

/// RMSE against the rays a render traces, every row of the grid coloured
/// and marked by its sampling, the Pareto front joined.
fn rays_plot(study: &Study, path: &Path) -> Drawn {
    let rows = &study.grid;
    let (low, high) = rows.iter().fold((f64::MAX, 0.0f64), |(lo, hi), r| {
        (lo.min(cost(r)), hi.max(cost(r)))
    });
    let y = rmse_range(rows, study.floor.mse.sqrt());
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    let mut chart = log_chart(
        &root,
        "RMSE against rays, every setting of the grid",
        (
            "rays traced per render (exact)",
            low * 0.7..high * 1.5,
            one_two_five(low * 0.7, high * 1.5),
        ),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    for (i, sampling) in study.plan.samplings.iter().enumerate() {
        let group: Vec<&Summary> = rows
            .iter()
            .filter(|r| r.setting.sampling == *sampling)
            .collect();
        let look = Look {
            colour: COLOURS[i % COLOURS.len()],
            marker: MARKERS[i % MARKERS.len()],
            shift: 1.0,
        };
        draw_points(&mut chart, &group, look, *sampling)?;
    }
    let front: Vec<(f64, f64)> = pareto(rows, study.floor)
        .into_iter()
        .map(|r| (cost(r), r.rmse))
        .collect();
    chart
        .draw_series(LineSeries::new(front.clone(), BLACK.stroke_width(1)))?
        .label("Pareto front: cheapest for its error")
        .legend(|(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (24, 0)], BLACK)
                + Circle::new((12, 0), 8, BLACK.stroke_width(1))
        });
    chart.draw_series(
        front
            .into_iter()
            .map(|p| Circle::new(p, 9, BLACK.stroke_width(1))),
    )?;
    // Lower left: few rays never give errors that small.
    finish_at(&mut chart, &root, SeriesLabelPosition::LowerLeft)
}
