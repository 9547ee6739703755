//! Error against time, drawn: one curve per knob, the Pareto front marked.

use std::error::Error;
use std::ops::Range;
use std::path::Path;

use plotters::prelude::*;

use super::measure::Measurement;
use super::report::pareto;
use super::settings::Knob;

/// The smallest error drawn on the log scale: exact matches sit on it.
const ERROR_FLOOR: f64 = 1e-5;

/// The plot's size in pixels.
const SIZE: (u32, u32) = (900, 600);

/// A chart with time and error on log scales.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// Error against time on log scales, one curve per knob, the Pareto front
/// marked, as an SVG file.
pub fn plot(measurements: &[Measurement], path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let (times, errors) = axis_ranges(measurements);
    let mut chart = ChartBuilder::on(&root)
        .caption("error against time", ("sans-serif", 24))
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(times.log_scale(), errors.log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time per render (s, median)")
        .y_desc("RMSE against the reference (linear RGB)")
        .draw()?;
    draw_knobs(&mut chart, measurements)?;
    draw_pareto_front(&mut chart, measurements)?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// The error as drawn: exact matches on the floor.
fn error(m: &Measurement) -> f64 {
    m.rmse.max(ERROR_FLOOR)
}

/// A measurement's point: its time and its error.
fn point(m: &Measurement) -> (f64, f64) {
    (m.seconds, error(m))
}

/// The ranges of time and error drawn: every point, with a margin.
fn axis_ranges(measurements: &[Measurement]) -> (Range<f64>, Range<f64>) {
    let (fastest, slowest) = measurements.iter().fold((f64::MAX, 0.0f64), |(lo, hi), m| {
        (lo.min(m.seconds), hi.max(m.seconds))
    });
    let largest = measurements
        .iter()
        .map(error)
        .fold(ERROR_FLOOR * 10.0, f64::max);
    (
        fastest * 0.8..slowest * 1.25,
        ERROR_FLOOR * 0.8..largest * 1.5,
    )
}

/// One line with dots per knob, in the knob's own order (least accurate
/// first), each in its colour with a legend entry.
fn draw_knobs(chart: &mut Chart, measurements: &[Measurement]) -> Result<(), Box<dyn Error>> {
    let colours = [RED, BLUE, GREEN, MAGENTA];
    for (knob, colour) in Knob::ALL.into_iter().zip(colours) {
        let points: Vec<(f64, f64)> = measurements
            .iter()
            .filter(|m| m.setting.knob == knob)
            .map(point)
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
            .label(knob.name())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        let dots = points
            .into_iter()
            .map(|p| Circle::new(p, 4, colour.filled()));
        chart.draw_series(dots)?;
    }
    Ok(())
}

/// The Pareto front: a thin black line through rings round its points.
fn draw_pareto_front(
    chart: &mut Chart,
    measurements: &[Measurement],
) -> Result<(), Box<dyn Error>> {
    let front: Vec<(f64, f64)> = pareto(measurements).into_iter().map(point).collect();
    chart
        .draw_series(LineSeries::new(front.clone(), BLACK.stroke_width(1)))?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    let rings = front
        .into_iter()
        .map(|p| Circle::new(p, 8, BLACK.stroke_width(2)));
    chart.draw_series(rings)?;
    Ok(())
}
