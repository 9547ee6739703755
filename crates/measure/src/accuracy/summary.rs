//! A row's renders summed up in the numbers the report ranks by: the mean
//! error over the seeds with its spread, bias² and variance, the rays, the
//! time as a median with its spread, and whether the error can be told
//! apart from the reference's own at all.

use super::measure::Row;
use super::metrics::Psnr;
use super::settings::Setting;

/// How many times the reference's own MSE a row's MSE must exceed to be
/// told apart from it: below that (an RMSE within twice the reference's),
/// the row is "at the reference's floor", and its true error could be
/// anything from 0 to about this.
pub const FLOOR_FACTOR: f64 = 4.0;

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
    /// The reference's own MSE, estimated from its two renders.
    pub mse: f64,
}

impl Floor {
    /// The MSE up to which a row is at the floor: [`FLOOR_FACTOR`] × the
    /// reference's own.
    pub fn limit(self) -> f64 {
        FLOOR_FACTOR * self.mse
    }

    /// Whether an MSE (or a bias², which may come out a little below 0)
    /// is at the floor.
    pub fn holds(self, mse: f64) -> bool {
        mse <= self.limit()
    }
}

/// One row as the report shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub setting: Setting,
    /// Rays of every kind traced by one render (exact, the mean over seeds).
    pub rays: u64,
    /// Wall time of one render, in seconds, over the timed renders.
    pub time: Spread,
    /// Renders measured (seeds).
    pub renders: usize,
    /// The mean MSE over the seeds (unclamped linear values).
    pub mse: f64,
    /// The RMSE, mean over the seeds, and its standard deviation over them.
    pub rmse: f64,
    pub rmse_sd: f64,
    /// The MSE split: mse = bias2 + variance.
    pub bias2: f64,
    pub variance: f64,
    /// The mean relative MSE over the seeds.
    pub relative_mse: f64,
    /// The PSNR of the mean 8-bit MSE.
    pub psnr: Psnr,
    /// The mean share of pixels off by more than one 8-bit step.
    pub pixels_off: f64,
    /// The mean ꟻLIP error, if measured.
    pub flip: Option<f64>,
    /// Whether the MSE is within [`FLOOR_FACTOR`] of the reference's.
    pub at_floor: bool,
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
        let rmse_sd = if rmses.len() > 1 {
            let squares: f64 = rmses.iter().map(|r| (r - rmse) * (r - rmse)).sum();
            (squares / (k - 1.0)).sqrt()
        } else {
            0.0
        };
        let mse = mean(&|e| e.mse);
        let flips: Option<Vec<f64>> = row.errors.iter().map(|e| e.flip).collect();
        Summary {
            setting: row.setting,
            rays: row.rays,
            time: Spread::of(&row.seconds),
            renders: row.errors.len(),
            mse,
            rmse,
            rmse_sd,
            bias2: row.bias2,
            variance: row.variance,
            relative_mse: mean(&|e| e.relative_mse),
            psnr: Psnr::of(mean(&|e| e.mse_8bit), pixels),
            pixels_off: mean(&|e| e.pixels_off),
            flip: flips.map(|f| f.iter().sum::<f64>() / k),
            at_floor: floor.holds(mse),
        }
    }

    /// The error the report ranks by: the MSE, or for a row at the floor
    /// the floor's limit, since its MSE cannot be told from any other
    /// there (so among rows at the floor the cheapest wins).
    pub fn ranked_error(&self, floor: Floor) -> f64 {
        if self.at_floor {
            floor.limit()
        } else {
            self.mse
        }
    }

    /// Efficiency = 1 / (MSE × median seconds): the higher, the more
    /// accuracy a second buys (for a row at the floor, a lower bound).
    pub fn efficiency(&self, floor: Floor) -> f64 {
        1.0 / (self.ranked_error(floor) * self.time.median)
    }
}
