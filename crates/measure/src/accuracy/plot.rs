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

use std::error::Error;
use std::ops::Range;
use std::path::{Path, PathBuf};

use plotters::coord::combinators::{BindKeyPoints, WithKeyPoints};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::Study;
use super::report::{cost, pareto};
use super::settings::Sampling;
use super::summary::Summary;

/// Each plot's size in pixels: about the book's column.
const SIZE: (u32, u32) = (760, 540);

/// The smallest text, in pixels: at the book's width, at least 12.
pub(super) const TEXT: u32 = 15;

/// The title's text, in pixels.
pub(super) const TITLE: u32 = 19;

/// A chart with both axes on log scales, the x axis with ticks and grid
/// lines only at chosen values (a log axis's own, at 1, 2, … 9 of every
/// decade, crowd and overlap their labels).
type LogChart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<WithKeyPoints<LogCoord<f64>>, LogCoord<f64>>>;

/// The colours of successive curves.
const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

type Drawn = Result<(), Box<dyn Error>>;

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

/// A log-log chart on `path` with its title, axis names and ranges, the x
/// axis ticked at `x_ticks`.
fn log_chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: &str,
    (x_name, x, x_ticks): (&str, Range<f64>, Vec<f64>),
    (y_name, y): (&str, Range<f64>),
) -> Result<LogChart<'a, 'b>, Box<dyn Error>> {
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", TITLE))
        .margin(16)
        .x_label_area_size(56)
        .y_label_area_size(84)
        .build_cartesian_2d(x.log_scale().with_key_points(x_ticks), y.log_scale())?;
    chart
        .configure_mesh()
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(220, 220, 220))
        .label_style(("sans-serif", TEXT))
        .axis_desc_style(("sans-serif", TEXT))
        .x_desc(x_name)
        .y_desc(y_name)
        .x_label_formatter(&|v| {
            if *v < 1000.0 {
                format!("{v}")
            } else {
                format!("{v:.0e}")
            }
        })
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    Ok(chart)
}

/// The ticks of a rays-per-pixel axis: the grid's numbers of rays.
fn n_ticks(study: &Study) -> Vec<f64> {
    study
        .plan
        .samplings
        .iter()
        .map(|s| f64::from(s.samples()))
        .collect()
}

/// Ticks at 1, 2 and 5 times the powers of ten from `low` to `high`.
fn one_two_five(low: f64, high: f64) -> Vec<f64> {
    let first = low.log10().floor() as i32;
    let last = high.log10().ceil() as i32;
    (first..=last)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|v| (low..=high).contains(v))
        .collect()
}

/// The RMSE axis: from below the floor band to above the largest error
/// bar, so that the band and every point show.
fn rmse_range<'a>(rows: impl IntoIterator<Item = &'a Summary>, floor_rmse: f64) -> Range<f64> {
    let (low, high) = rows
        .into_iter()
        .fold((floor_rmse, floor_rmse), |(lo, hi), r| {
            (lo.min(r.rmse), hi.max(r.rmse + r.rmse_sd))
        });
    // Headroom above the largest error, for the legend.
    low * 0.3..high * 10.0
}

/// The reference's floor: a grey band from the bottom of the chart up to
/// the RMSE at which a row is "at the floor", with the floor itself as a
/// line. Errors inside the band cannot be told from the reference's own.
fn draw_floor(chart: &mut LogChart, study: &Study) -> Drawn {
    let (x, y) = (chart.x_range(), chart.y_range());
    let limit = study.floor.limit().sqrt();
    let band = Rectangle::new(
        [(x.start, y.start), (x.end, limit)],
        BLACK.mix(0.1).filled(),
    );
    chart
        .draw_series([band])?
        .label(format!(
            "at the reference's floor (RMSE ≤ 2 × {:.1e})",
            study.floor.mse.sqrt()
        ))
        .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BLACK.mix(0.1).filled()));
    let floor = study.floor.mse.sqrt();
    chart.draw_series(LineSeries::new(
        [(x.start, floor), (x.end, floor)],
        BLACK.mix(0.4),
    ))?;
    Ok(())
}

/// How a curve looks: its colour, its marker and the factor by which its
/// points are shifted along N (1 for none), so that curves on the same
/// values stay apart.
#[derive(Clone, Copy)]
struct Look {
    colour: RGBColor,
    marker: Marker,
    shift: f64,
}

/// The markers of successive curves.
#[derive(Clone, Copy)]
enum Marker {
    Circle,
    Triangle,
    Square,
    Diamond,
}

const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Triangle,
    Marker::Square,
    Marker::Diamond,
];

impl Marker {
    /// The marker's outline in pixels around its point, moved by `dx`.
    fn outline(self, dx: i32) -> Vec<(i32, i32)> {
        let points = match self {
            Marker::Circle => (0..12)
                .map(|i| {
                    let a = std::f64::consts::TAU * f64::from(i) / 12.0;
                    (
                        (5.5 * a.cos()).round() as i32,
                        (5.5 * a.sin()).round() as i32,
                    )
                })
                .collect(),
            Marker::Triangle => vec![(0, -7), (6, 4), (-6, 4)],
            Marker::Square => vec![(-5, -5), (5, -5), (5, 5), (-5, 5)],
            Marker::Diamond => vec![(0, -7), (7, 0), (0, 7), (-7, 0)],
        };
        points.into_iter().map(|(x, y)| (x + dx, y)).collect()
    }
}

/// A curve of RMSE against rays per pixel: a line through the means, a
/// marker and a bar of ± one standard deviation over the seeds at each.
fn draw_curve<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    rows: &[&Summary],
    look: Look,
    label: String,
) -> Drawn {
    let y_floor = chart.y_range().start;
    let Look {
        colour,
        marker,
        shift,
    } = look;
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (shift * f64::from(r.setting.sampling.samples()), r.rmse))
        .collect();
    chart
        .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
        .label(label)
        .legend(move |(x, y)| {
            EmptyElement::at((x, y))
                + PathElement::new(vec![(0, 0), (24, 0)], colour.stroke_width(2))
                + Polygon::new(marker.outline(12), colour.filled())
        });
    chart.draw_series(
        points
            .iter()
            .map(|&p| EmptyElement::at(p) + Polygon::new(marker.outline(0), colour.filled())),
    )?;
    chart.draw_series(rows.iter().zip(&points).map(|(r, &(n, e))| {
        let low = (e - r.rmse_sd).max(y_floor);
        ErrorBar::new_vertical(n, low, e, e + r.rmse_sd, colour.stroke_width(1), 8)
    }))?;
    Ok(())
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

/// The rows of one sampling as markers with their spread bars.
fn draw_points<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    rows: &[&Summary],
    look: Look,
    sampling: Sampling,
) -> Drawn {
    let y_floor = chart.y_range().start;
    let Look { colour, marker, .. } = look;
    let point = |r: &Summary| (cost(r), r.rmse);
    chart
        .draw_series(rows.iter().map(|r| {
            EmptyElement::at(point(r)) + Polygon::new(marker.outline(0), colour.filled())
        }))?
        .label(match sampling {
            Sampling::Centre => "one ray through each pixel's centre".to_owned(),
            Sampling::Jittered(1) => "1 jittered ray per pixel".to_owned(),
            Sampling::Jittered(n) => format!("{n} jittered rays per pixel"),
        })
        .legend(move |(x, y)| {
            EmptyElement::at((x, y)) + Polygon::new(marker.outline(12), colour.filled())
        });
    chart.draw_series(rows.iter().map(|r| {
        let (x, e) = point(r);
        ErrorBar::new_vertical(
            x,
            (e - r.rmse_sd).max(y_floor),
            e,
            e + r.rmse_sd,
            colour.mix(0.6),
            4,
        )
    }))?;
    Ok(())
}

/// The legend, in the upper right (where the errors of many rays per
/// pixel never reach), and the file written.
fn finish<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    root: &DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
) -> Drawn {
    finish_at(chart, root, SeriesLabelPosition::UpperRight)
}

/// The legend at `position`, and the file written.
fn finish_at<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    root: &DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    position: SeriesLabelPosition,
) -> Drawn {
    chart
        .configure_series_labels()
        .position(position)
        .label_font(("sans-serif", TEXT))
        .legend_area_size(36)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
