//! The rows as the terminal and the performance page show them (Markdown
//! tables), as a file keeps them (CSV), and the choices they support: the
//! Pareto front, the best row within a budget of rays, the most efficient
//! rows, and the rate at which jittered samples converge. Every ranking is
//! computed from the rows' own numbers (the tests change one and watch the
//! ranking follow).

use serde::Serialize;

use super::summary::{Floor, Summary, Verdict};
use crate::bench::table::markdown;

/// The cost every ranking uses: the rays of every kind one render traces.
/// Exact, and the same on any machine; a render's time at the study's
/// sizes moves by several times from one render to the next on a shared
/// machine, so the report shows it and ranks by rays.
pub fn cost(row: &Summary) -> f64 {
    row.rays as f64
}

/// Rays counts closer than this share of each other rank as equal: the
/// rays of a jittered row differ from seed to seed by less than 0.1%.
pub const RAYS_TOLERANCE: f64 = 0.01;

/// The rows on the Pareto front, cheapest first: those that no other row
/// beats on both cost and error. Errors closer than the reference's floor
/// (its [`Floor::limit`]) cannot be told apart, so a row is beaten only by
/// one that costs no more and whose error is no more than that much above
/// its own, and is lower in cost (by more than [`RAYS_TOLERANCE`]) or lower
/// in error by more than that. Each
/// row on the front is the cheapest way the study found to its error; of
/// rows that tie, the cheapest.
pub fn pareto(rows: &[Summary], floor: Floor) -> Vec<&Summary> {
    let tolerance = floor.limit();
    let point = |r: &Summary| (cost(r), r.ranked_error(floor));
    // A jittered row's rays move with its seeds by a few in ten thousand:
    // costs within RAYS_TOLERANCE count as equal.
    let (less, more) = (1.0 - RAYS_TOLERANCE, 1.0 + RAYS_TOLERANCE);
    let beats = |o: &Summary, m: &Summary| {
        let ((oc, oe), (mc, me)) = (point(o), point(m));
        oc <= mc * more && oe <= me + tolerance && (oc < mc * less || oe < me - tolerance)
    };
    let mut front: Vec<&Summary> = rows
        .iter()
        .filter(|m| !rows.iter().any(|o| beats(o, m)))
        .collect();
    front.sort_by(|a, b| point(a).0.total_cmp(&point(b).0));
    // Rows that tie (rays within RAYS_TOLERANCE, errors within the floor's
    // limit: a threshold that never ends a path at depth 1) are one point:
    // the cheapest stands for all.
    front.dedup_by(|b, a| {
        let ((ac, ae), (bc, be)) = (point(a), point(b));
        bc <= ac * more && (ae - be).abs() <= tolerance
    });
    front
}

/// The most accurate row that traces at most `rays`: of the rows within
/// [`Floor::limit`] of the lowest error there, the cheapest. `None` if no
/// row is that cheap.
pub fn best_within(rows: &[Summary], floor: Floor, rays: f64) -> Option<&Summary> {
    let cheap: Vec<&Summary> = rows.iter().filter(|r| cost(r) <= rays).collect();
    let lowest = cheap
        .iter()
        .map(|r| r.ranked_error(floor))
        .min_by(f64::total_cmp)?;
    cheap
        .into_iter()
        .filter(|r| r.ranked_error(floor) <= lowest + floor.limit())
        .min_by(|a, b| cost(a).total_cmp(&cost(b)))
}

/// The rows that have an efficiency ([`Summary::efficiency`]), most
/// efficient first.
pub fn by_efficiency(rows: &[Summary], floor: Floor) -> Vec<&Summary> {
    let mut sorted: Vec<(&Summary, f64)> = rows
        .iter()
        .filter_map(|r| Some((r, r.efficiency(floor)?)))
        .collect();
    sorted.sort_by(|a, b| b.1.total_cmp(&a.1));
    sorted.into_iter().map(|(r, _)| r).collect()
}

/// The slope of log(error) against log(samples), fitted by least squares
/// to `points` (samples, error): −½ for plain Monte Carlo, −¾ for
/// jittered sampling of a picture with edges (Mitchell 1996), −1 at best.
/// `None` for fewer than two points.
pub fn slope(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < 2 {
        return None;
    }
    let logs: Vec<(f64, f64)> = points.iter().map(|&(n, e)| (n.ln(), e.ln())).collect();
    let count = logs.len() as f64;
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(x, y), &(a, b)| (x + a / count, y + b / count));
    let (sxy, sxx) = logs.iter().fold((0.0, 0.0), |(xy, xx), &(a, b)| {
        (xy + (a - mx) * (b - my), xx + (a - mx) * (a - mx))
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// A number in the tables: three significant digits, scientific.
fn sci(v: f64) -> String {
    format!("{v:.2e}")
}

/// An error cell: the value, or "at floor" where it cannot be told from
/// the reference's own.
fn error_cell(v: f64, at_floor: bool) -> String {
    if at_floor {
        "at floor".to_owned()
    } else {
        sci(v)
    }
}

/// The bias² cell: the estimate ± its SE, and what it allows: "at floor"
/// only where even 2 SE above it is within the floor's limit, and where the
/// seeds cannot tell, how many would (if the setting had no bias). A
/// jittered row judged on its termination's most rays per pixel
/// ([`super::summary::judge_at_most_rays`]) says so, and says if its own
/// estimate misses that one by over 2 SE.
pub fn bias_cell(r: &Summary, floor: Floor) -> String {
    let Some(judged) = r.judged_on else {
        return own_bias_cell(r, floor);
    };
    let verdict = match r.verdict(floor) {
        Verdict::AtFloor => "at floor",
        Verdict::Above => "above the floor",
        Verdict::Unresolved => "can't tell",
    };
    let check = if r.agrees_with_judged() {
        ""
    } else {
        "; misses it by over 2 SE"
    };
    format!(
        "{}; {verdict} at {} jittered{check}",
        r.bias2, judged.samples
    )
}

/// [`bias_cell`] for a row judged on its own bias².
fn own_bias_cell(r: &Summary, floor: Floor) -> String {
    match floor.judge(r.bias2) {
        Verdict::AtFloor => format!("at floor ({})", r.bias2),
        Verdict::Above => r.bias2.to_string(),
        Verdict::Unresolved => {
            let seeds = floor.seeds_to_tell(r.bias2, r.renders);
            if seeds < 10_000 {
                format!("{}, can't tell ({seeds} seeds would)", r.bias2)
            } else {
                format!("{}, can't tell", r.bias2)
            }
        }
    }
}

/// The header of [`table`]; ꟻLIP only when it was measured.
fn header(flip: bool) -> Vec<&'static str> {
    let mut header = vec![
        "setting",
        "rays",
        "time (s): median (min–max)",
        "RMSE: mean ± sd",
        "bias² ± SE",
        "variance ± SE",
        "rel. MSE",
        "PSNR 8-bit (dB)",
        "px off",
    ];
    if flip {
        header.push("ꟻLIP");
    }
    header.push("1/(MSE·rays)");
    header
}

/// One row of [`table`], named `name`.
fn cells(name: &str, r: &Summary, floor: Floor, flip: bool) -> Vec<String> {
    let t = r.time;
    let rmse = if r.at_floor {
        "at floor".to_owned()
    } else if r.renders > 1 && r.rmse_sd > 0.0 {
        format!("{} ± {:.1e}", sci(r.rmse), r.rmse_sd)
    } else {
        sci(r.rmse)
    };
    let mut cells = vec![
        name.to_owned(),
        r.rays.to_string(),
        format!("{:.3} ({:.3}–{:.3})", t.median, t.min, t.max),
        rmse,
        bias_cell(r, floor),
        if r.setting.sampling.is_random() {
            r.variance.to_string()
        } else {
            "0 (no seed)".to_owned()
        },
        error_cell(r.relative_mse, r.at_floor),
        if r.at_floor {
            "at floor".to_owned()
        } else {
            r.psnr.to_string()
        },
        format!("{:.2}%", 100.0 * r.pixels_off),
    ];
    if flip {
        cells.push(r.flip.map_or("–".to_owned(), |f| format!("{f:.4}")));
    }
    cells.push(match r.efficiency(floor) {
        Some(e) if r.at_floor => format!("≥ {}", sci(e)),
        Some(e) => sci(e),
        None => "– (biased)".to_owned(),
    });
    cells
}

/// `rows` as a Markdown table, each with its name.
pub fn table<'a>(rows: impl IntoIterator<Item = (String, &'a Summary)>, floor: Floor) -> String {
    let rows: Vec<(String, &Summary)> = rows.into_iter().collect();
    let flip = rows.iter().any(|(_, r)| r.flip.is_some());
    let lines = rows.iter().map(|(name, r)| cells(name, r, floor, flip));
    markdown(header(flip), lines, 1)
}

/// A row named by its setting, for [`table`].
pub fn named(row: &Summary) -> (String, &Summary) {
    (row.setting.name(), row)
}

/// The equal-cost table: for each budget of rays per pixel (of every
/// kind), the best row within it, and the best with one centre ray, for
/// comparison; `pixels` is the picture's pixel count.
pub fn equal_rays_table(rows: &[Summary], floor: Floor, budgets: &[f64], pixels: u32) -> String {
    let centre: Vec<Summary> = rows
        .iter()
        .filter(|r| !r.setting.sampling.is_random())
        .cloned()
        .collect();
    let per_pixel = |r: &Summary| r.rays as f64 / f64::from(pixels.max(1));
    let describe = |best: Option<&Summary>| match best {
        Some(r) => [
            r.setting.name(),
            error_cell(r.rmse, r.at_floor),
            format!("{:.1}", per_pixel(r)),
        ],
        None => [
            "none is this cheap".to_owned(),
            "–".to_owned(),
            "–".to_owned(),
        ],
    };
    let lines = budgets.iter().map(|&budget| {
        let rays = budget * f64::from(pixels);
        let [name, rmse, used] = describe(best_within(rows, floor, rays));
        let [c_name, c_rmse, _] = describe(best_within(&centre, floor, rays));
        vec![format!("{budget}"), name, rmse, used, c_name, c_rmse]
    });
    let header = [
        "rays per pixel",
        "best setting",
        "RMSE",
        "its rays per pixel",
        "best with one centre ray",
        "its RMSE",
    ];
    markdown(header, lines, 2)
}

/// One line of the CSV file: a row in full precision.
#[derive(Debug, Serialize)]
struct CsvRecord {
    group: String,
    max_depth: u32,
    min_weight: f32,
    sampling: String,
    samples: u32,
    effects: String,
    renders: usize,
    rays: u64,
    seconds_median: f64,
    seconds_min: f64,
    seconds_max: f64,
    mse: f64,
    mse_se: f64,
    rmse_mean: f64,
    rmse_sd: f64,
    bias2: f64,
    bias2_se: f64,
    bias2_verdict: String,
    variance: f64,
    variance_se: f64,
    relative_mse: f64,
    psnr_8bit_db: String,
    pixels_off: f64,
    flip: Option<f64>,
    at_floor: bool,
    efficiency: Option<f64>,
    /// The rays per pixel of the row `bias2_verdict` was judged on, where
    /// not this row's own (last, so that older readers keep their columns).
    bias2_judged_at: Option<u32>,
}

/// `rows` as CSV, each with its group ("grid" or "effects"): a header,
/// then one line per row, numbers in full precision.
pub fn csv<'a>(rows: impl IntoIterator<Item = (&'a str, &'a Summary)>, floor: Floor) -> String {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for (group, r) in rows {
        let record = CsvRecord {
            group: group.to_owned(),
            max_depth: r.setting.termination.max_depth,
            min_weight: r.setting.termination.min_weight,
            sampling: r.setting.sampling.name(),
            samples: r.setting.sampling.samples(),
            effects: r.setting.effects.to_string(),
            renders: r.renders,
            rays: r.rays,
            seconds_median: r.time.median,
            seconds_min: r.time.min,
            seconds_max: r.time.max,
            mse: r.mse.value,
            mse_se: r.mse.se,
            rmse_mean: r.rmse,
            rmse_sd: r.rmse_sd,
            bias2: r.bias2.value,
            bias2_se: r.bias2.se,
            bias2_verdict: format!("{:?}", r.verdict(floor)),
            bias2_judged_at: r.judged_on.map(|j| j.samples),
            variance: r.variance.value,
            variance_se: r.variance.se,
            relative_mse: r.relative_mse,
            psnr_8bit_db: r.psnr.to_string(),
            pixels_off: r.pixels_off,
            flip: r.flip,
            at_floor: r.at_floor,
            efficiency: r.efficiency(floor),
        };
        writer
            .serialize(record)
            .expect("a record of plain fields always serialises into memory");
    }
    let bytes = writer.into_inner().expect("writing to memory cannot fail");
    String::from_utf8(bytes).expect("CSV of UTF-8 text is UTF-8")
}
