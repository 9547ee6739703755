//! The report as Markdown: how the study was made and how good its
//! reference is, then the tables a reader acts on. Printed, and written
//! beside the plots as accuracy.md.

use std::fmt::Write;

use crate::bench::table::markdown;

use super::Study;
use super::report::{by_efficiency, equal_rays_table, named, pareto, slope, table};
use super::settings::Sampling;
use super::summary::{FLOOR_FACTOR, NEGLIGIBLE_BIAS, STANDARD_ERRORS, Spread, Summary, Verdict};

/// The budgets of the equal-cost table, in rays (of every kind) per pixel.
pub const BUDGETS: [f64; 4] = [2.0, 8.0, 32.0, 128.0];

/// The whole report.
pub fn page(study: &Study) -> String {
    let mut page = String::new();
    method(&mut page, study);
    seeds(&mut page, study);
    knobs(&mut page, study);
    bias(&mut page, study);
    convergence(&mut page, study);
    choices(&mut page, study);
    time(&mut page, study);
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
         RMSE {floor_rmse:.2e} (MSE {mse:.2e}, the floor). The limit is {FLOOR_FACTOR}× the \
         floor's MSE, {limit:.2e} (an RMSE within 2× the reference's): below it the reference \
         cannot tell a row's error from its own.\n\n\
         Each setting is rendered {k} times, with seeds {first} to {last} where it is jittered. \
         MSE = bias² + variance: bias² is the mean product of two different seeds' errors \
         (independent noise multiplies out, the bias stays), the variance is half the mean \
         squared difference of two seeds' pictures. Measured against the reference, a bias² \
         of zero reads as the floor, not 0. Each carries its standard error (± SE over the \
         seeds: an average over pairs of seeds, whose variance is Hoeffding's, estimated pixel \
         by pixel; one centre ray has no seed, its bias² is exact). A value reads \"at floor\" \
         only where even {STANDARD_ERRORS} SE above it is below the limit and {STANDARD_ERRORS} SE \
         fit between the floor and the limit, \"above\" only where {STANDARD_ERRORS} SE below it \
         is above the limit; \
         between the two the cell says \"can't tell\" and how many \
         seeds would, if the estimate stayed where it is (the SE falls as 1/√(K(K−1))). \
         RMSE is the mean over the renders ± their standard deviation. MSE, RMSE and relative \
         MSE (ε = 0.01) use the unclamped linear values; PSNR and \"px off\" (a channel more \
         than one step away) the 8-bit values of the PNG.\n\n\
         Rays are exact, and every ranking below is by rays. Time is the wall time of one \
         render with its BVH build, the median of the {k} renders with its min–max; at this \
         size, on a shared machine, it moves by several times between renders, so it is shown \
         and never ranked by (what a ray costs is at the end, from the largest renders). \
         Efficiency, 1/(MSE × rays), is shown only where bias² is negligible (even \
         {STANDARD_ERRORS} SE above it below {negligible}% of the MSE, or at floor): for a biased \
         row more rays buy nothing against its bias.\n",
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
        limit = study.floor.limit(),
        k = plan.seeds,
        first = plan.first_seed,
        last = plan.first_seed + u64::from(plan.seeds) - 1,
        negligible = 100.0 * NEGLIGIBLE_BIAS,
    );
}

/// How many seeds the study used and what they resolve: for each sampling,
/// how many rows' bias² reads at floor, above it, or cannot tell, its
/// largest SE, and the seeds that would tell every row.
fn seeds(page: &mut String, study: &Study) {
    let floor = study.floor;
    let room = floor.limit() - floor.mse;
    let _ = writeln!(
        page,
        "### How many seeds\n\n\
         {k} seeds a row. bias² reads \"at floor\" when 2 SE fit in the room between the floor \
         and its limit, {room:.2e}, so SE ≤ {half:.2e} is needed. A termination's bias does not \
         depend on the rays per pixel (jittered rays average the same paths), so it is judged \
         where its SE is smallest, at the most rays per pixel: every jittered row's verdict is \
         that of its termination's row with the most rays, and the seeds are chosen so that those \
         rows tell. Each row's own estimate stays in the tables, with its own SE, and the table \
         counts how many lie within 2 SE (of the difference) of the one they are judged by, as \
         they must if the bias does not depend on the rays per pixel.\n",
        k = study.plan.seeds,
        half = room / STANDARD_ERRORS,
    );
    let lines = study
        .plan
        .samplings
        .iter()
        .filter(|s| s.is_random())
        .map(|&sampling| seeds_line(study, sampling));
    let header = [
        "sampling",
        "judged at",
        "bias² at floor",
        "above the floor",
        "can't tell",
        "largest SE of its own bias²",
        "own within 2 SE of judged",
        "seeds to tell every row",
    ];
    let _ = writeln!(page, "{}\n", markdown(header, lines, 1));
}

/// One line of the seeds table: the grid's rows of `sampling`, counted by
/// the verdict they are judged by, and how many of them agree with it.
fn seeds_line(study: &Study, sampling: Sampling) -> Vec<String> {
    let floor = study.floor;
    let rows: Vec<&Summary> = study
        .grid
        .iter()
        .filter(|r| r.setting.sampling == sampling)
        .collect();
    let count = |v: Verdict| {
        rows.iter()
            .filter(|r| r.verdict(floor) == v)
            .count()
            .to_string()
    };
    let largest = rows.iter().map(|r| r.bias2.se).fold(0.0, f64::max);
    let judged_at = rows
        .iter()
        .find_map(|r| r.judged_on)
        .map_or("its own".to_owned(), |j| format!("{} jittered", j.samples));
    let agree = rows.iter().filter(|r| r.agrees_with_judged()).count();
    let needed = rows
        .iter()
        .filter(|r| r.judged_on.is_none() && r.verdict(floor) == Verdict::Unresolved)
        .map(|r| floor.seeds_to_tell(r.bias2, r.renders))
        .max()
        .map_or(format!("{} (all tell)", study.plan.seeds), |n| {
            if n < 10_000 {
                n.to_string()
            } else {
                "over 10000".to_owned()
            }
        });
    vec![
        sampling.name(),
        judged_at,
        count(Verdict::AtFloor),
        count(Verdict::Above),
        count(Verdict::Unresolved),
        format!("{largest:.1e}"),
        format!("{agree} of {}", rows.len()),
        needed,
    ]
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

/// The Pareto front by rays, the equal-rays table and the most efficient
/// rows.
fn choices(page: &mut String, study: &Study) {
    let floor = study.floor;
    let front = pareto(&study.grid, floor);
    let _ = writeln!(
        page,
        "### The Pareto front by rays traced\n\n\
         The settings of the grid ({} of them) that no other beats on both rays traced and MSE, \
         cheapest first (MSEs closer than the floor's limit count as equal).\n\n{}\n",
        study.grid.len(),
        table(front.into_iter().map(named), floor)
    );
    let _ = writeln!(
        page,
        "### Equal rays\n\nThe most accurate setting of the grid that traces at most so many \
         rays per pixel (of every kind), beside the best with one centre ray.\n\n{}\n",
        equal_rays_table(
            &study.grid,
            floor,
            &BUDGETS,
            study.plan.width * study.plan.height
        )
    );
    let top: Vec<&Summary> = by_efficiency(&study.grid, floor)
        .into_iter()
        .take(8)
        .collect();
    let _ = writeln!(
        page,
        "### The most efficient settings\n\nBy 1/(MSE × rays), highest first, of the rows whose \
         bias² is negligible (the others have none).\n\n{}\n",
        table(top.into_iter().map(named), floor)
    );
}

/// What a ray costs in time, from the grid's renders with the most rays
/// per pixel (the longest, so the least moved by the machine's jitter):
/// nanoseconds per ray, the median over those rows of their median, and
/// the least and most of any render.
fn time(page: &mut String, study: &Study) {
    let Some(most) = study.plan.samplings.iter().map(|s| s.samples()).max() else {
        return;
    };
    let per_ray = |seconds: f64, r: &Summary| 1e9 * seconds / r.rays.max(1) as f64;
    let rows: Vec<&Summary> = study
        .grid
        .iter()
        .filter(|r| r.setting.sampling.samples() == most && r.setting.sampling.is_random())
        .collect();
    if rows.is_empty() {
        return;
    }
    let medians: Vec<f64> = rows.iter().map(|r| per_ray(r.time.median, r)).collect();
    let spread = Spread::of(&medians);
    let least = rows
        .iter()
        .map(|r| per_ray(r.time.min, r))
        .fold(f64::MAX, f64::min);
    let most_ns = rows
        .iter()
        .map(|r| per_ray(r.time.max, r))
        .fold(0.0, f64::max);
    let _ = writeln!(
        page,
        "### What a ray costs in time\n\n\
         From the {n} rows with {most} jittered rays per pixel, {k} renders each, on {threads} \
         threads: {median:.0} ns of wall time per ray (median of the rows' medians; rows \
         {low:.0} to {high:.0}; single renders {least:.0} to {most_ns:.0}). Wall time, so it \
         includes the BVH's build and whatever else ran on the machine.\n",
        n = rows.len(),
        k = study.plan.seeds,
        threads = study.threads,
        median = spread.median,
        low = spread.min,
        high = spread.max,
    );
}
