//! What every plot of the study is drawn with: log charts with chosen
//! ticks, the reference's floor as a band, curves and points with markers
//! of their own, and the legend.

use std::error::Error;
use std::ops::Range;

use plotters::coord::combinators::{BindKeyPoints, WithKeyPoints};
use plotters::prelude::*;

use super::super::Study;
use super::super::report::cost;
use super::super::settings::Sampling;
use super::super::summary::Summary;
use super::{TEXT, TITLE};

/// A chart with both axes on log scales, the x axis with ticks and grid
/// lines only at chosen values (a log axis's own, at 1, 2, … 9 of every
/// decade, crowd and overlap their labels).
pub(super) type LogChart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<WithKeyPoints<LogCoord<f64>>, LogCoord<f64>>>;

/// The colours of successive curves.
pub(super) const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

pub(super) type Drawn = Result<(), Box<dyn Error>>;

/// A log-log chart on `path` with its title, axis names and ranges, the x
/// axis ticked at `x_ticks`.
pub(super) fn log_chart<'a, 'b>(
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
pub(super) fn n_ticks(study: &Study) -> Vec<f64> {
    study
        .plan
        .samplings
        .iter()
        .map(|s| f64::from(s.samples()))
        .collect()
}

/// Ticks at 1, 2 and 5 times the powers of ten from `low` to `high`.
pub(super) fn one_two_five(low: f64, high: f64) -> Vec<f64> {
    let first = low.log10().floor() as i32;
    let last = high.log10().ceil() as i32;
    (first..=last)
        .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
        .filter(|v| (low..=high).contains(v))
        .collect()
}

/// The RMSE axis: from below the floor band to above the largest error
/// bar, so that the band and every point show.
pub(super) fn rmse_range<'a>(
    rows: impl IntoIterator<Item = &'a Summary>,
    floor_rmse: f64,
) -> Range<f64> {
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
pub(super) fn draw_floor(chart: &mut LogChart, study: &Study) -> Drawn {
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
pub(super) struct Look {
    pub(super) colour: RGBColor,
    pub(super) marker: Marker,
    pub(super) shift: f64,
}

/// The markers of successive curves.
#[derive(Clone, Copy)]
pub(super) enum Marker {
    Circle,
    Triangle,
    Square,
    Diamond,
}

pub(super) const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Triangle,
    Marker::Square,
    Marker::Diamond,
];

impl Marker {
    /// The marker's outline in pixels around its point, moved by `dx`.
    pub(super) fn outline(self, dx: i32) -> Vec<(i32, i32)> {
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
pub(super) fn draw_curve<'a, 'b: 'a>(
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

/// The rows of one sampling as markers with their spread bars.
pub(super) fn draw_points<'a, 'b: 'a>(
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
pub(super) fn finish<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    root: &DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
) -> Drawn {
    finish_at(chart, root, SeriesLabelPosition::UpperRight)
}

/// The legend at `position`, and the file written.
pub(super) fn finish_at<'a, 'b: 'a>(
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
