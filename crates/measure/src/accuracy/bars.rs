//! The effects as bars, not a curve: they are categories, each a chapter's
//! effect added to the ones before, at the scene's own criteria and one
//! centre ray. Left: the RMSE against the reference; right: the rays a
//! render traces (exact; times at this size are the machine's noise).

use std::path::Path;

use plotters::prelude::*;

use super::Study;
use super::plot::{TEXT, TITLE};
use super::summary::Summary;

/// The plot's size in pixels.
const SIZE: (u32, u32) = (760, 420);

/// Draws the effects' bars into `path`.
pub fn effects_plot(study: &Study, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let title = root.titled(
        "each chapter's effect added (scene's depth and threshold, centre ray)",
        ("sans-serif", TITLE),
    )?;
    let (left, right) = title.split_horizontally(SIZE.0 / 2);
    let steps: Vec<(&str, &Summary)> = study.effects.iter().map(|(n, s)| (*n, s)).collect();
    panel(&left, &steps, "RMSE against the reference", |s| {
        (s.rmse, s.rmse, s.rmse)
    })?;
    panel(&right, &steps, "rays traced per render", |s| {
        let rays = s.rays as f64;
        (rays, rays, rays)
    })?;
    root.present()?;
    Ok(())
}

/// One panel: a bar per step of height `value(step).1`, with a bar from
/// `.0` to `.2` where they differ (the spread).
fn panel(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    steps: &[(&str, &Summary)],
    name: &str,
    value: impl Fn(&Summary) -> (f64, f64, f64),
) -> Result<(), Box<dyn std::error::Error>> {
    let top = steps.iter().map(|(_, s)| value(s).2).fold(0.0, f64::max) * 1.15;
    let labels: Vec<String> = steps.iter().map(|(n, _)| n.to_string()).collect();
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(84)
        .build_cartesian_2d(-0.5f64..steps.len() as f64 - 0.5, 0.0..top.max(1e-9))?;
    let label = |x: &f64| {
        let i = x.round();
        let near = (x - i).abs() < 1e-6 && i >= 0.0;
        near.then(|| labels.get(i as usize).cloned())
            .flatten()
            .unwrap_or_default()
    };
    chart
        .configure_mesh()
        .disable_x_mesh()
        .light_line_style(TRANSPARENT)
        .label_style(("sans-serif", TEXT))
        .axis_desc_style(("sans-serif", TEXT))
        .y_label_formatter(&|v| {
            // RMSEs in two decimals, ray counts in whole numbers.
            if top < 10.0 {
                format!("{v:.2}")
            } else {
                format!("{v:.0}")
            }
        })
        .x_labels(steps.len() * 2 + 1)
        .x_label_formatter(&label)
        .y_desc(name)
        .draw()?;
    let colour = RGBColor(31, 119, 180);
    chart.draw_series(steps.iter().enumerate().map(|(i, (_, s))| {
        let x = i as f64;
        Rectangle::new(
            [(x - 0.3, 0.0), (x + 0.3, value(s).1)],
            colour.mix(0.8).filled(),
        )
    }))?;
    let spreads = steps.iter().enumerate().filter_map(|(i, (_, s))| {
        let (low, mid, high) = value(s);
        (low < high)
            .then(|| ErrorBar::new_vertical(i as f64, low, mid, high, BLACK.stroke_width(1), 10))
    });
    chart.draw_series(spreads)?;
    Ok(())
}
