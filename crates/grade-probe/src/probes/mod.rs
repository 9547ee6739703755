//! The probe of each exercise: how its inputs are drawn, what it returns as
//! values, and how close two correct answers are. One table, so that a new
//! exercise is one entry.

use crate::draw::Rng;
use crate::{Case, Values};

#[cfg(feature = "ch01")]
mod ch01;
#[cfg(feature = "ch02")]
mod ch02;
#[cfg(feature = "ch03")]
mod ch03;
#[cfg(feature = "ch04")]
mod ch04;
#[cfg(feature = "ch05")]
mod ch05;
#[cfg(feature = "ch06")]
mod ch06;
#[cfg(feature = "ch07")]
mod ch07;

/// How many inputs each exercise is probed on.
pub const CASES: usize = 24;

/// One exercise's probe.
pub struct Probe {
    /// The exercise: `ch02-sphere`.
    pub id: &'static str,
    /// Its chapter's folder: `02-hits`.
    pub chapter: &'static str,
    /// See [`Values::tolerance`].
    pub tolerance: f64,
    /// Draws an input and calls the exercise on it; `None` rejects the
    /// draw (an input too close to an edge case, where two correct
    /// solutions may rightly differ in rounding: the tests check those).
    pub case: fn(&mut Rng) -> Option<Case>,
}

/// Every exercise this build can probe, in the chapters' order.
pub fn all() -> Vec<Probe> {
    let mut all = Vec::new();
    #[cfg(feature = "ch01")]
    all.extend(ch01::probes());
    #[cfg(feature = "ch02")]
    all.extend(ch02::probes());
    #[cfg(feature = "ch03")]
    all.extend(ch03::probes());
    #[cfg(feature = "ch04")]
    all.extend(ch04::probes());
    #[cfg(feature = "ch05")]
    all.extend(ch05::probes());
    #[cfg(feature = "ch06")]
    all.extend(ch06::probes());
    #[cfg(feature = "ch07")]
    all.extend(ch07::probes());
    all
}

/// The exercise's values on [`CASES`] inputs drawn from `seed`.
pub fn run(probe: &Probe, seed: u64) -> Values {
    let mut rng = crate::draw::rng_for(seed, probe.id);
    let mut cases = Vec::new();
    while cases.len() < CASES {
        if let Some(case) = (probe.case)(&mut rng) {
            cases.push(case);
        }
    }
    Values {
        id: probe.id.to_owned(),
        tolerance: probe.tolerance,
        cases,
    }
}
