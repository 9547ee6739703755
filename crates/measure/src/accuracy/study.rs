//! A whole study: the plan, the reference and its floor, and every row
//! summed up; and the views of it that the report and the plots share.

use raybook::tracer::Termination;

use super::reference::Reference;
use super::settings::{Plan, Sampling, Setting};
use super::summary::{Floor, Summary};

/// What one run of `raybook accuracy` measured.
pub struct Study {
    pub plan: Plan,
    /// The reference's setting, cost and where it is cached (its picture
    /// too, for the error maps).
    pub reference: Reference,
    /// The reference's floor.
    pub floor: Floor,
    /// Every setting of the grid, summed up.
    pub grid: Vec<Summary>,
    /// The effects added a chapter at a time, named.
    pub effects: Vec<(&'static str, Summary)>,
    /// The threads every render ran on.
    pub threads: usize,
}

impl Study {
    /// The grid's most accurate termination ([`Plan::most_accurate`]).
    pub fn most_accurate(&self) -> Termination {
        self.plan.most_accurate()
    }

    /// The grid's setting nearest the scene's own ([`Plan::base`]).
    pub fn base(&self) -> Setting {
        self.plan.base()
    }

    /// The grid row of `setting`, if it is one.
    pub fn row(&self, setting: &Setting) -> Option<&Summary> {
        self.grid.iter().find(|r| r.setting == *setting)
    }

    /// The jittered rows of `termination`, fewest rays per pixel first.
    pub fn curve(&self, termination: Termination) -> Vec<&Summary> {
        let mut rows: Vec<&Summary> = self
            .grid
            .iter()
            .filter(|r| r.setting.termination == termination && r.setting.sampling.is_random())
            .collect();
        rows.sort_by_key(|r| r.setting.sampling.samples());
        rows
    }

    /// The centre-ray row of `termination`.
    pub fn centre(&self, termination: Termination) -> Option<&Summary> {
        self.grid.iter().find(|r| {
            r.setting.termination == termination && r.setting.sampling == Sampling::Centre
        })
    }

    /// The rows that turn one knob of [`Study::base`]: the depths, then
    /// the thresholds, then the samplings, each named by the knob's value.
    pub fn one_knob_rows(&self) -> Vec<(String, &Summary)> {
        let base = self.base();
        let mut rows = Vec::new();
        for &d in &self.plan.depths {
            let mut s = base;
            s.termination.max_depth = d;
            rows.extend(self.row(&s).map(|r| (format!("depth {d}"), r)));
        }
        for &w in &self.plan.thresholds {
            let mut s = base;
            s.termination.min_weight = w;
            rows.extend(self.row(&s).map(|r| (format!("threshold {w}"), r)));
        }
        for &sampling in &self.plan.samplings {
            let s = Setting { sampling, ..base };
            rows.extend(self.row(&s).map(|r| (sampling.name(), r)));
        }
        rows
    }
}
