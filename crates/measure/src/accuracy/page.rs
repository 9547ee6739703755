//! The report as Markdown: how the study was made and how good its
//! reference is, then the tables a reader acts on. Printed, and written
//! beside the plots as accuracy.md.

use std::fmt::Write;

use super::Study;
use super::report::{Cost, by_efficiency, equal_time_table, named, pareto, slope, table};
use super::summary::{FLOOR_FACTOR, Summary};

/// The time budgets of the equal-time table, in seconds.
pub const BUDGETS: [f64; 4] = [0.0625, 0.25, 1.0, 4.0];

/// The whole report.
pub fn page(study: &Study) -> String {
    let mut page = String::new();
    method(&mut page, study);
    knobs(&mut page, study);
    bias(&mut page, study);
    convergence(&mut page, study);
    choices(&mut page, study);
    page
}

/// How the numbers were made, and the reference's own error.
fn method(page: &mut String, study: &Study) {
    let plan = &study.plan;
    let r = &study.reference;
    let floor_rmse = study.floor.mse.sqrt();
    let cached = if r.from_cache {
        "read from the cache"
    } else {
        "rendered now"
    };
    let _ = writeln!(
        page,
        "### How it was measured\n\n\
         The showcase at {w}×{h} pixels, {threads} threads. Every row is compared with one \
         reference: depth {d}, threshold {t}, {s} jittered rays per pixel, rendered twice \
         with independent seeds and averaged ({rays} rays, {secs:.1} s when made; {cached}, \
         {path}). Its own error, estimated from its two renders as mean((R₁ − R₂)²)/4: \
         RMSE {floor_rmse:.2e} (MSE {mse:.2e}). A row whose MSE is within {FLOOR_FACTOR}× \
         of that (its RMSE within 2×) cannot be told from the reference and reads \"at floor\".\n\n\
         Each setting is rendered {k} times, with seeds 1 to {k} where it is jittered. \
         RMSE is the mean over those renders ± their standard deviation; MSE = bias² + \
         variance, the variance from the spread between seeds (one centre ray has none). \
         MSE, RMSE and relative MSE (ε = 0.01) use the unclamped linear values; PSNR and \
         \"px off\" (a channel more than one step away) the 8-bit values of the PNG. Time \
         is the wall time of one render with its BVH build: the median of the {k} renders, \
         taken in turn with every other setting's (interleaved), after one untimed warm-up \
         render per termination, with the min–max spread. Rays are exact. \
         Efficiency is 1/(MSE × median seconds).\n",
        w = plan.width,
        h = plan.height,
        threads = study.threads,
        d = r.setting.termination.max_depth,
        t = r.setting.termination.min_weight,
        s = r.setting.sampling.samples(),
        rays = r.rays,
        secs = r.seconds,
        path = r.cache.display(),
        mse = study.floor.mse,
        k = plan.seeds,
    );
}

/// Every knob turned alone from the scene's settings, and the effects.
fn knobs(page: &mut String, study: &Study) {
    let base = study.base();
    let t = base.termination;
    let rows = study.one_knob_rows();
    let _ = writeln!(
        page,
        "### One knob at a time, from the scene's settings\n\n\
         From depth {}, threshold {}, one centre ray (what the chapter binaries render), \
         one knob turned at a time; every other setting is in the CSV.\n",
        t.max_depth, t.min_weight
    );
    let _ = writeln!(page, "{}\n", table(rows, study.floor));
    let _ = writeln!(
        page,
        "The effects, added a chapter at a time (same depth, threshold and centre ray):\n"
    );
    let effects = study.effects.iter().map(|(n, r)| (n.to_string(), r));
    let _ = writeln!(page, "{}\n", table(effects, study.floor));
}

/// Depth and threshold at the grid's most jittered rays, where their bias
/// stands out of the sampling noise.
fn bias(page: &mut String, study: &Study) {
    let Some(&largest) = study
        .plan
        .samplings
        .iter()
        .filter(|s| s.is_random())
        .max_by_key(|s| s.samples())
    else {
        return;
    };
    let best = study.most_accurate();
    let at = |max_depth, min_weight| {
        let termination = raybook::tracer::Termination {
            max_depth,
            min_weight,
        };
        study
            .grid
            .iter()
            .find(|r| r.setting.termination == termination && r.setting.sampling == largest)
    };
    let rows: Vec<&Summary> = (study
        .plan
        .depths
        .iter()
        .filter_map(|&d| at(d, best.min_weight)))
    .chain(
        study
            .plan
            .thresholds
            .iter()
            .filter_map(|&w| at(best.max_depth, w)),
    )
    .collect();
    let _ = writeln!(
        page,
        "### Where the termination's bias shows\n\n\
         With {} per pixel, the sampling noise is small and shows as variance; what depth and \
         threshold leave out shows as bias². Depths at threshold {}, then thresholds at depth {}.\n",
        largest.name(),
        best.min_weight,
        best.max_depth
    );
    let _ = writeln!(
        page,
        "{}\n",
        table(rows.into_iter().map(named), study.floor)
    );
}

/// How the RMSE of jittered sampling falls with the rays per pixel.
fn convergence(page: &mut String, study: &Study) {
    let best = study.most_accurate();
    let curve = study.curve(best);
    let points: Vec<(f64, f64)> = curve
        .iter()
        .filter(|r| !r.at_floor)
        .map(|r| (f64::from(r.setting.sampling.samples()), r.rmse))
        .collect();
    let _ = writeln!(page, "### How jittered samples converge\n");
    if let Some(s) = slope(&points) {
        let _ = writeln!(
            page,
            "At depth {}, threshold {}: the RMSE falls as N^{s:.2} over N = {} to {} jittered \
             rays per pixel (least squares on log–log; N^-0.5 would be independent samples, \
             N^-0.75 is what jittering a picture with edges gives, N^-1 the best case).\n",
            best.max_depth,
            best.min_weight,
            points.first().map_or(0.0, |p| p.0),
            points.last().map_or(0.0, |p| p.0),
        );
    }
    let rows = study.centre(best).into_iter().chain(curve.iter().copied());
    let _ = writeln!(
        page,
        "{}\n",
        table(rows.into_iter().map(named), study.floor)
    );
}

/// The Pareto fronts, the equal-time table and the most efficient rows.
fn choices(page: &mut String, study: &Study) {
    let floor = study.floor;
    for (cost, what) in [(Cost::Time, "median time"), (Cost::Rays, "rays traced")] {
        let front = pareto(&study.grid, floor, cost);
        let _ = writeln!(
            page,
            "### The Pareto front by {what}\n\n\
             The settings of the grid ({} of them) that no other beats on both {what} and MSE, \
             cheapest first (rows at the floor count as equally accurate).\n\n{}\n",
            study.grid.len(),
            table(front.into_iter().map(named), floor)
        );
    }
    let _ = writeln!(
        page,
        "### Equal time\n\nThe most accurate setting of the grid whose median time is within \
         each budget, on this machine at {}×{} pixels ({} threads), beside the best with one \
         centre ray.\n\n{}\n",
        study.plan.width,
        study.plan.height,
        study.threads,
        equal_time_table(&study.grid, floor, &BUDGETS)
    );
    let top: Vec<&Summary> = by_efficiency(&study.grid, floor)
        .into_iter()
        .take(8)
        .collect();
    let _ = writeln!(
        page,
        "### The most efficient settings\n\nBy 1/(MSE × median seconds), highest first.\n\n{}\n",
        table(top.into_iter().map(named), floor)
    );
}
