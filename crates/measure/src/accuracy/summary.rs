//! A row's renders summed up in the numbers the report ranks by: the mean
//! error over the seeds with its spread, bias² and variance with their
//! standard errors, the rays, the time as a median with its spread, and
//! what those standard errors allow saying about the reference's floor.

use super::estimate::Estimate;
use super::measure::Row;
use super::metrics::Psnr;
use super::settings::Setting;

/// How many times the reference's own MSE a row's MSE (or bias²) may be
/// and still be "at the reference's floor": an RMSE within twice the
/// reference's. Below that the reference cannot tell a row's error from its
/// own, and the row's true error could be anything from 0 to about this.
pub const FLOOR_FACTOR: f64 = 4.0;

/// How many standard errors an estimate must keep from the floor's limit
/// before the report says on which side of it the truth lies: about 95%
/// of estimates fall within 2 SE of their expectation.
pub const STANDARD_ERRORS: f64 = 2.0;

/// A bias² counts as negligible against the MSE (so that the MSE is the
/// estimator's variance, and efficiency means what it says) when, even 2
/// SE above its estimate, it is below this share of the MSE.
pub const NEGLIGIBLE_BIAS: f64 = 0.1;

/// A median with the smallest and largest values around it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    pub median: f64,
    pub min: f64,
    pub max: f64,
}

impl Spread {
    /// The spread of `values` (at least one).
    pub fn of(values: &[f64]) -> Spread {
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        Spread {
            median: crate::bench::median(sorted.iter().copied()),
            min: sorted[0],
            max: sorted[sorted.len() - 1],
        }
    }
}

/// The reference's floor: the MSE below which a row cannot be told apart
/// from the reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Floor {
    /// The reference's own MSE, estimated from its two renders. A bias² is
    /// measured against the reference, so a bias² of zero reads as this
    /// ([`super::estimate`]).
    pub mse: f64,
}

/// What an estimate and its standard error allow the report to say.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Even 2 SE above the estimate is within the floor's limit, and 2 SE
    /// fit between the floor and its limit: the row cannot be told from
    /// the reference, and the seeds were enough to say so.
    AtFloor,
    /// Even 2 SE below the estimate is above the floor's limit: measured.
    Above,
    /// The limit is within 2 SE: these seeds cannot tell.
    Unresolved,
}

impl Floor {
    /// The MSE up to which a row is at the floor: [`FLOOR_FACTOR`] × the
    /// reference's own.
    pub fn limit(self) -> f64 {
        FLOOR_FACTOR * self.mse
    }

    /// On which side of [`Floor::limit`] `e` lies, if its standard error
    /// allows telling ([`STANDARD_ERRORS`] of them on either side).
    ///
    /// "At floor" asks for more than an upper bound below the limit: its
    /// 2 SE must also fit in the room between the floor and the limit. A
    /// bias² has the floor as its least expected value, so an estimate far
    /// below it (−2·10⁻⁴ ± 10⁻⁴ against a floor of 2·10⁻⁶, as 4 seeds of one
    /// jittered ray give) is noise that its SE, from a few seeds, did not
    /// catch, and says nothing about the floor.
    pub fn judge(self, e: Estimate) -> Verdict {
        let resolves = STANDARD_ERRORS * e.se <= self.limit() - self.mse;
        if resolves && e.value + STANDARD_ERRORS * e.se <= self.limit() {
            Verdict::AtFloor
        } else if e.value - STANDARD_ERRORS * e.se > self.limit() {
            Verdict::Above
        } else {
            Verdict::Unresolved
        }
    }

    /// The seeds a bias² measured with `seeds` seeds would need to be
    /// told from the limit, if its estimate stayed where it is (or at the
    /// floor, its least expected value, if below it): below the limit it
    /// needs 2 SE ≤ limit − that (which also fits 2 SE between floor and
    /// limit), above it 2 SE < estimate − limit. Where the noise rules, the
    /// bias²'s variance is 2σ⁴/(K(K−1)) over the values (the test of
    /// [`super::estimate`] checks it), so its SE falls as 1/√(K(K−1)).
    /// `usize::MAX` for an estimate exactly at the limit.
    pub fn seeds_to_tell(self, bias2: Estimate, seeds: usize) -> usize {
        let room = (self.limit() - bias2.value.max(self.mse)).abs();
        if room == 0.0 {
            return usize::MAX;
        }
        let k = seeds as f64;
        let needed = k * (k - 1.0) * (STANDARD_ERRORS * bias2.se / room).powi(2);
        // The smallest n with n(n − 1) ≥ needed.
        let n = (0.5 + (0.25 + needed).sqrt()).ceil();
        if n.is_finite() && n < 1e9 {
            (n as usize).max(seeds)
        } else {
            usize::MAX
        }
    }
}

/// One row as the report shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub setting: Setting,
    /// Rays of every kind traced by one render (exact, the mean over seeds).
    pub rays: u64,
    /// Wall time of one render, in seconds, over the renders (shown,
    /// never ranked by: see the page).
    pub time: Spread,
    /// Renders measured (seeds).
    pub renders: usize,
    /// The mean MSE over the seeds (unclamped linear values), with its SE.
    pub mse: Estimate,
    /// The RMSE, mean over the seeds, and its standard deviation over them.
    pub rmse: f64,
    pub rmse_sd: f64,
    /// The MSE split: mse = bias2 + variance, each with its SE
    /// ([`super::estimate`]).
    pub bias2: Estimate,
    pub variance: Estimate,
    /// The mean relative MSE over the seeds.
    pub relative_mse: f64,
    /// The PSNR of the mean 8-bit MSE.
    pub psnr: Psnr,
    /// The mean share of pixels off by more than one 8-bit step.
    pub pixels_off: f64,
    /// The mean ꟻLIP error, if measured.
    pub flip: Option<f64>,
    /// Whether the MSE, with its SE, is within the floor's limit.
    pub at_floor: bool,
    /// For a jittered row with fewer rays per pixel than its
    /// termination's most, the row its bias² is judged on
    /// ([`judge_at_most_rays`]); `None` where it is judged on its own.
    pub judged_on: Option<Judged>,
}

/// The bias² a jittered row is judged by: that of the same termination and
/// effects at the most jittered rays per pixel, with its SE.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Judged {
    /// The rays per pixel of the row judged on.
    pub samples: u32,
    pub bias2: Estimate,
}

/// Judges every jittered row's bias² where its SE is smallest.
///
/// Jittered rays put the expectation of a pixel at the average of the
/// radiance over the pixel's area, whatever their number N, and so does the
/// reference: what remains is the termination's bias (what depth and
/// threshold leave out), the same for every N. Only its noise falls with N,
/// and with 1 or 4 rays a bias² estimate from a few seeds is 10–100 times
/// the floor in either direction. So each jittered row is judged on the row
/// of the same termination and effects with the most rays per pixel; its
/// own estimate stays in the tables, and [`Summary::agrees_with_judged`]
/// checks that the two tell the same story.
pub fn judge_at_most_rays(rows: &mut [Summary]) {
    let judged: Vec<Option<Judged>> = rows
        .iter()
        .map(|row| {
            let most = rows
                .iter()
                .filter(|r| same_termination(r, row) && r.setting.sampling.is_random())
                .max_by_key(|r| r.setting.sampling.samples())?;
            (row.setting.sampling.is_random() && most.setting != row.setting).then(|| Judged {
                samples: most.setting.sampling.samples(),
                bias2: most.bias2,
            })
        })
        .collect();
    for (row, judged) in rows.iter_mut().zip(judged) {
        row.judged_on = judged;
    }
}

/// Whether two rows differ only in their sampling.
fn same_termination(a: &Summary, b: &Summary) -> bool {
    a.setting.termination == b.setting.termination
        && a.setting.effects == b.setting.effects
        && a.setting.tracer == b.setting.tracer
}

impl Summary {
    /// Sums up `row`; `pixels` is the picture's pixel count (for the PSNR
    /// bound of an exact 8-bit match).
    pub fn of(row: &Row, floor: Floor, pixels: usize) -> Summary {
        let k = row.errors.len().max(1) as f64;
        let mean =
            |f: &dyn Fn(&super::metrics::Errors) -> f64| row.errors.iter().map(f).sum::<f64>() / k;
        let rmses: Vec<f64> = row.errors.iter().map(|e| e.mse.sqrt()).collect();
        let rmse = rmses.iter().sum::<f64>() / k;
        let rmse_sd = if rmses.len() > 1 && row.setting.sampling.is_random() {
            let squares: f64 = rmses.iter().map(|r| (r - rmse) * (r - rmse)).sum();
            (squares / (k - 1.0)).sqrt()
        } else {
            0.0
        };
        let flips: Option<Vec<f64>> = row.errors.iter().map(|e| e.flip).collect();
        Summary {
            setting: row.setting,
            rays: row.rays,
            time: Spread::of(&row.seconds),
            renders: row.errors.len(),
            mse: row.mse,
            rmse,
            rmse_sd,
            bias2: row.bias2,
            variance: row.variance,
            relative_mse: mean(&|e| e.relative_mse),
            psnr: Psnr::of(mean(&|e| e.mse_8bit), pixels),
            pixels_off: mean(&|e| e.pixels_off),
            flip: flips.map(|f| f.iter().sum::<f64>() / k),
            at_floor: floor.judge(row.mse) == Verdict::AtFloor,
            judged_on: None,
        }
    }

    /// The bias² the row is judged by: its termination's at the most rays
    /// per pixel where [`judge_at_most_rays`] found one, else its own.
    pub fn judged_bias2(&self) -> Estimate {
        self.judged_on.map_or(self.bias2, |j| j.bias2)
    }

    /// What the floor says of [`Summary::judged_bias2`].
    pub fn verdict(&self, floor: Floor) -> Verdict {
        floor.judge(self.judged_bias2())
    }

    /// Whether the row's own bias² is within 2 SE (of the difference) of
    /// the one it is judged by, as it must be if the bias does not depend
    /// on the rays per pixel. Always true for a row judged on itself.
    pub fn agrees_with_judged(&self) -> bool {
        let judged = self.judged_bias2();
        let se = self.bias2.se.hypot(judged.se);
        (self.bias2.value - judged.value).abs() <= STANDARD_ERRORS * se
    }

    /// The error the report ranks by: the MSE, or for a row at the floor
    /// the floor's limit, since its MSE cannot be told from any other
    /// there (so among rows at the floor the cheapest wins).
    pub fn ranked_error(&self, floor: Floor) -> f64 {
        if self.at_floor {
            floor.limit()
        } else {
            self.mse.value
        }
    }

    /// Whether the row's bias² is negligible against its MSE: a jittered
    /// row whose judged bias² ([`Summary::judged_bias2`]), even [`STANDARD_ERRORS`] above its estimate, is
    /// below [`NEGLIGIBLE_BIAS`] of the MSE, or at the floor. One centre
    /// ray is all bias.
    pub fn bias_is_negligible(&self, floor: Floor) -> bool {
        let bias2 = self.judged_bias2();
        let upper = bias2.value + STANDARD_ERRORS * bias2.se;
        self.setting.sampling.is_random()
            && (upper <= NEGLIGIBLE_BIAS * self.mse.value
                || self.verdict(floor) == Verdict::AtFloor)
    }

    /// Efficiency = 1 / (MSE × rays traced), where the MSE is all
    /// variance: the higher, the more accuracy a ray buys. Defined for an
    /// unbiased estimator (Veach 1997, where it is 1/(variance × time));
    /// rays, not seconds, since they are exact. `None` where the bias is
    /// not negligible ([`Summary::bias_is_negligible`]): there more rays
    /// buy nothing against the bias, and the number would mislead.
    pub fn efficiency(&self, floor: Floor) -> Option<f64> {
        self.bias_is_negligible(floor)
            .then(|| 1.0 / (self.ranked_error(floor) * self.rays.max(1) as f64))
    }
}
