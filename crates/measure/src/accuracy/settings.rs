//! The accuracy knobs, and the settings each sweep renders.

use raybook::toolkit::scene::{Effect, Effects};
use raybook::tracer::Termination;

/// The accuracy knobs of the tracer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Knob {
    /// How many bounces a path may take (chapter 7's maximum depth).
    Depth,
    /// The weight below which a path ends (chapter 7's threshold).
    Threshold,
    /// Rays per pixel, for anti-aliasing.
    Samples,
    /// The effects simulated, added a chapter at a time.
    Effects,
}

impl Knob {
    /// Every knob, in the order the tools report them.
    pub const ALL: [Knob; 4] = [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects];

    /// The knob's name, as the table and the plot show it.
    pub fn name(self) -> &'static str {
        match self {
            Knob::Depth => "max depth",
            Knob::Threshold => "weight threshold",
            Knob::Samples => "samples per pixel",
            Knob::Effects => "effects",
        }
    }
}

/// One setting of the tracer.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The knob this setting turns.
    pub knob: Knob,
    /// The knob's value, as shown in the table.
    pub value: String,
    /// The criteria that end a path.
    pub termination: Termination,
    /// Rays per pixel.
    pub samples: u32,
    /// The effects simulated (of those the scene calls for).
    pub effects: Effects,
}

/// The most accurate setting: every bounce, no threshold, every effect.
fn best(samples: u32) -> Setting {
    Setting {
        knob: Knob::Depth,
        value: String::new(),
        termination: Termination {
            max_depth: 12,
            min_weight: 0.0,
        },
        samples,
        effects: Effects::ALL,
    }
}

/// The settings of one sweep, most accurate last (it is the reference):
/// `knob` turned, everything else at its most accurate. `quick` sweeps
/// fewer values.
pub fn settings(knob: Knob, quick: bool) -> Vec<Setting> {
    let turned = |value: String, change: &dyn Fn(&mut Setting)| {
        let mut setting = Setting {
            knob,
            value,
            ..best(1)
        };
        change(&mut setting);
        setting
    };
    match knob {
        Knob::Depth => depths(quick)
            .into_iter()
            .map(|d| turned(d.to_string(), &|s| s.termination.max_depth = d))
            .collect(),
        Knob::Threshold => [0.1f32, 1e-2, 1e-3, 1e-4, 0.0]
            .into_iter()
            .map(|w| turned(w.to_string(), &|s| s.termination.min_weight = w))
            .collect(),
        Knob::Samples => sample_counts(quick)
            .iter()
            .map(|&n| turned(n.to_string(), &|s| s.samples = n))
            .collect(),
        Knob::Effects => EFFECT_STEPS
            .into_iter()
            .map(|(name, effects)| turned(name.to_owned(), &|s| s.effects = Effects::of(effects)))
            .collect(),
    }
}

/// The maximum depths swept: every one from 0 to 12, or some when quick.
fn depths(quick: bool) -> Vec<u32> {
    if quick {
        vec![0, 1, 2, 3, 4, 6, 8, 12]
    } else {
        (0..=12).collect()
    }
}

/// The samples per pixel swept.
fn sample_counts(quick: bool) -> &'static [u32] {
    if quick { &[1, 4, 16] } else { &[1, 4, 16, 64] }
}

/// The effects swept: a chapter's at a time, with their names.
const EFFECT_STEPS: [(&str, &[Effect]); 4] = {
    use Effect::*;
    [
        ("lambert", &[Lambert, Spot]),
        ("+ shadows", &[Lambert, Spot, Shadows]),
        ("+ reflection", &[Lambert, Spot, Shadows, Reflection]),
        (
            "+ refraction",
            &[Lambert, Spot, Shadows, Reflection, Refraction],
        ),
    ]
};

/// Every knob's sweep, in the order of [`Knob::ALL`].
pub fn all_settings(quick: bool) -> Vec<Setting> {
    Knob::ALL
        .into_iter()
        .flat_map(|knob| settings(knob, quick))
        .collect()
}
