//! The study drawn, as SVG files: RMSE against rays per pixel with the
//! guide slopes N^-½ and N^-1, the same for several depths, RMSE against
//! time and against rays with the Pareto front, and the effects as bars.
//! Every error is drawn where it was measured; the reference's floor is a
//! shaded band, under which no measured error can be trusted.

use std::error::Error;
use std::ops::Range;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

use super::Study;
use super::report::{Cost, pareto};
use super::settings::Sampling;
use super::summary::Summary;

/// Each plot's size in pixels.
const SIZE: (u32, u32) = (820, 560);

/// A chart with both axes on log scales.
type LogChart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

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
        ("accuracy-time.svg", &|s, p| cost_plot(s, Cost::Time, p)),
        ("accuracy-rays.svg", &|s, p| cost_plot(s, Cost::Rays, p)),
        ("accuracy-effects.svg", &super::bars::effects_plot),
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

/// A log-log chart on `path` with its title, axis names and ranges.
fn log_chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: &str,
    (x_name, x): (&str, Range<f64>),
    (y_name, y): (&str, Range<f64>),
) -> Result<LogChart<'a, 'b>, Box<dyn Error>> {
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 22))
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(x.log_scale(), y.log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x_name)
        .y_desc(y_name)
        .x_label_formatter(&|v| format!("{v}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    Ok(chart)
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
            "reference's floor (RMSE {:.1e}); within 2× of it: at the floor",
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

/// A curve of RMSE against rays per pixel: a line through the means, a
/// dot and a bar of ± one standard deviation over the seeds at each.
fn draw_curve(chart: &mut LogChart, rows: &[&Summary], colour: RGBColor, label: String) -> Drawn {
    let y_floor = chart.y_range().start;
    let points: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (f64::from(r.setting.sampling.samples()), r.rmse))
        .collect();
    chart
        .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
        .label(label)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
    chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, colour.filled())))?;
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
        ("rays per pixel N", 0.7..largest * 1.5),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    if let Some(first) = curve.first() {
        for (power, name, colour) in [
            (0.5, "guide: N^-½", BLACK),
            (1.0, "guide: N^-1", RGBColor(120, 120, 120)),
        ] {
            let guide = (0..=40).map(|i| {
                let n = largest.powf(f64::from(i) / 40.0);
                (n, first.rmse * n.powf(-power))
            });
            chart
                .draw_series(DashedLineSeries::new(guide, 6, 4, colour.stroke_width(1)))?
                .label(name)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        }
    }
    draw_curve(
        &mut chart,
        &curve,
        COLOURS[0],
        "jittered: mean ± sd over seeds".to_owned(),
    )?;
    if let Some(c) = centre {
        chart
            .draw_series([TriangleMarker::new((1.0, c.rmse), 8, COLOURS[3].filled())])?
            .label("one ray through the centre")
            .legend(|(x, y)| TriangleMarker::new((x + 10, y), 6, COLOURS[3].filled()));
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
        ("rays per pixel N (jittered)", 0.7..largest * 1.5),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    for ((depth, curve), colour) in curves.iter().zip(COLOURS.iter().cycle()) {
        draw_curve(&mut chart, curve, *colour, format!("max depth {depth}"))?;
    }
    finish(&mut chart, &root)
}

/// RMSE against the cost of a render (median time with its min–max, or
/// rays), every row of the grid coloured by its sampling, the Pareto
/// front joined.
fn cost_plot(study: &Study, cost: Cost, path: &Path) -> Drawn {
    let rows = &study.grid;
    let (low, high) = rows
        .iter()
        .fold((f64::MAX, 0.0f64), |(lo, hi), r| match cost {
            Cost::Time => (lo.min(r.time.min), hi.max(r.time.max)),
            Cost::Rays => (lo.min(r.rays as f64), hi.max(r.rays as f64)),
        });
    let y = rmse_range(rows, study.floor.mse.sqrt());
    let x_name = match cost {
        Cost::Time => format!(
            "seconds per render: median, bar from min to max ({} threads)",
            study.threads
        ),
        Cost::Rays => "rays traced per render (exact)".to_owned(),
    };
    let root = SVGBackend::new(path, SIZE).into_drawing_area();
    let title = format!(
        "RMSE against {}, every setting of the grid",
        if cost == Cost::Time { "time" } else { "rays" }
    );
    let mut chart = log_chart(
        &root,
        &title,
        (&x_name, low * 0.7..high * 1.5),
        ("RMSE against the reference (linear RGB)", y),
    )?;
    draw_floor(&mut chart, study)?;
    for (sampling, colour) in study.plan.samplings.iter().zip(COLOURS.iter().cycle()) {
        let group: Vec<&Summary> = rows
            .iter()
            .filter(|r| r.setting.sampling == *sampling)
            .collect();
        draw_points(&mut chart, &group, cost, *colour, *sampling)?;
    }
    let front: Vec<(f64, f64)> = pareto(rows, study.floor, cost)
        .into_iter()
        .map(|r| (cost.of(r), r.rmse))
        .collect();
    chart
        .draw_series(LineSeries::new(front.clone(), BLACK.stroke_width(1)))?
        .label("Pareto front: cheapest for its error")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    chart.draw_series(
        front
            .into_iter()
            .map(|p| Circle::new(p, 7, BLACK.stroke_width(1))),
    )?;
    finish(&mut chart, &root)
}

/// The rows of one sampling as dots with their spread bars.
fn draw_points(
    chart: &mut LogChart,
    rows: &[&Summary],
    cost: Cost,
    colour: RGBColor,
    sampling: Sampling,
) -> Drawn {
    let y_floor = chart.y_range().start;
    let point = |r: &Summary| (cost.of(r), r.rmse);
    chart
        .draw_series(
            rows.iter()
                .map(|r| Circle::new(point(r), 3, colour.filled())),
        )?
        .label(format!("{} per pixel", sampling.name()))
        .legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
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
    if cost == Cost::Time {
        chart.draw_series(rows.iter().map(|r| {
            let t = r.time;
            ErrorBar::new_horizontal(r.rmse, t.min, t.median, t.max, colour.mix(0.6), 4)
        }))?;
    }
    Ok(())
}

/// The legend, and the file written.
fn finish<'a, 'b: 'a>(
    chart: &mut LogChart<'a, 'b>,
    root: &DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
) -> Drawn {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
