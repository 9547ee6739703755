//! What the study renders: the grid of settings (maximum depth × weight
//! threshold × sampling), the effects added a chapter at a time, and the
//! one reference that every row is measured against.

use raybook::toolkit::scene::{Effect, Effects};
use raybook::tracer::Termination;

/// How the rays of a pixel are placed: two different estimators, so two
/// different rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sampling {
    /// One ray through the pixel's centre, as a render without `--seed`
    /// casts it: deterministic, so it has no variance, only bias (the
    /// centre's colour is not the pixel's mean colour at an edge).
    Centre,
    /// N rays, one at a random point of each cell of a √N × √N grid
    /// (chapter 1's jittered sampling, with `--seed`): an unbiased estimate
    /// of the pixel's mean colour, whose variance falls as N grows.
    Jittered(u32),
}

impl Sampling {
    /// Rays per pixel.
    pub fn samples(self) -> u32 {
        match self {
            Sampling::Centre => 1,
            Sampling::Jittered(n) => n,
        }
    }

    /// Whether renders with different seeds differ.
    pub fn is_random(self) -> bool {
        matches!(self, Sampling::Jittered(_))
    }

    /// As the tables write it: "centre" or "4 jittered".
    pub fn name(self) -> String {
        match self {
            Sampling::Centre => "centre".to_owned(),
            Sampling::Jittered(n) => format!("{n} jittered"),
        }
    }
}

/// Which tracer renders: the complete one (`raybook render`'s, with its
/// BVH), or chapter 7's own, which tests every object for every ray and
/// needs only chapters 1 to 7 solved: the one a student's handout can run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Tracer {
    #[default]
    Complete,
    #[value(name = "chapter7")]
    Chapter7,
}

/// One setting of the tracer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setting {
    /// The criteria that end a path (chapter 7).
    pub termination: Termination,
    /// The rays per pixel and where they go.
    pub sampling: Sampling,
    /// The effects simulated (of those the scene calls for).
    pub effects: Effects,
    /// The tracer that renders it.
    pub tracer: Tracer,
}

impl Setting {
    /// The setting's name in a table: depth, threshold, sampling, and the
    /// effects when some are missing.
    pub fn name(&self) -> String {
        let Termination {
            max_depth,
            min_weight,
        } = self.termination;
        let mut name = format!(
            "depth {max_depth}, threshold {min_weight}, {}",
            self.sampling.name()
        );
        if self.effects != Effects::ALL {
            name = format!("{name}, only {}", self.effects);
        }
        name
    }
}

/// The most accurate setting, which the reference renders: depth 64, far
/// beyond any row's, no threshold, and `samples` jittered rays.
pub fn reference_setting(samples: u32) -> Setting {
    Setting {
        termination: Termination {
            max_depth: 64,
            min_weight: 0.0,
        },
        sampling: Sampling::Jittered(samples),
        effects: Effects::ALL,
        tracer: Tracer::Complete,
    }
}

/// What one study renders.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// The picture's size in pixels.
    pub width: u32,
    /// The picture's height in pixels.
    pub height: u32,
    /// The maximum depths of the grid.
    pub depths: Vec<u32>,
    /// The weight thresholds of the grid.
    pub thresholds: Vec<f32>,
    /// The samplings of the grid.
    pub samplings: Vec<Sampling>,
    /// Renders of each row; each random row gets a seed per render.
    pub seeds: u32,
    /// The first of the rows' seeds: they are first_seed, first_seed + 1, …
    pub first_seed: u64,
    /// Rays per pixel of each of the reference's two independent renders:
    /// 16 times the grid's largest count.
    pub reference_samples: u32,
    /// The criteria the effects rows use: the scene's own.
    pub scene_default: Termination,
    /// The tracer every render uses.
    pub tracer: Tracer,
}

/// Seeds per row of the quick look and of the full study: enough that the
/// bias² of the grid's rows with the most rays per pixel, where the
/// termination's bias is judged, has 2 SE below the room between the floor
/// and its limit (3 × the floor). Measured: the page states the SEs each
/// run got, and how many seeds each row that cannot tell would need.
pub const QUICK_SEEDS: u32 = 8;
pub const FULL_SEEDS: u32 = 6;

/// The factor by which the reference has more rays per pixel than any row.
pub const REFERENCE_FACTOR: u32 = 16;

impl Plan {
    /// The full study (`quick = false`) or the quick look, sized for a
    /// 2-core machine: the quick look in about a minute with its reference
    /// cached, the full study in well under an hour with none (the
    /// performance page gives the times measured).
    pub fn new(quick: bool, scene_default: Termination) -> Plan {
        let (width, height) = if quick { (128, 96) } else { (256, 192) };
        let depths = if quick {
            vec![1, 2, 6, 16]
        } else {
            vec![1, 2, 3, 4, 6, 8, 16]
        };
        let thresholds = if quick {
            vec![0.01, 0.001, 0.0]
        } else {
            vec![0.1, 0.01, 0.001, 0.0001, 0.0]
        };
        let largest = if quick { 16 } else { 64 };
        let mut samplings = vec![Sampling::Centre];
        samplings.extend(
            (0..)
                .map(|k| 4u32.pow(k))
                .take_while(|&n| n <= largest)
                .map(Sampling::Jittered),
        );
        Plan {
            width,
            height,
            depths,
            thresholds,
            samplings,
            seeds: if quick { QUICK_SEEDS } else { FULL_SEEDS },
            first_seed: 1,
            reference_samples: REFERENCE_FACTOR * largest,
            scene_default,
            tracer: Tracer::Complete,
        }
    }

    /// Every setting of the grid depth × threshold × sampling, every effect
    /// on: depths outermost, samplings innermost.
    pub fn grid(&self) -> Vec<Setting> {
        let mut grid = Vec::new();
        for &max_depth in &self.depths {
            for &min_weight in &self.thresholds {
                for &sampling in &self.samplings {
                    grid.push(Setting {
                        termination: Termination {
                            max_depth,
                            min_weight,
                        },
                        sampling,
                        effects: Effects::ALL,
                        tracer: self.tracer,
                    });
                }
            }
        }
        grid
    }

    /// The effects added a chapter at a time, at the scene's own criteria
    /// and one centre ray: what a student's binary renders. The last, every
    /// effect, is also a row of the grid when the scene's criteria are in it.
    pub fn effect_steps(&self) -> Vec<(&'static str, Setting)> {
        EFFECT_STEPS
            .into_iter()
            .map(|(name, effects)| {
                let setting = Setting {
                    termination: self.scene_default,
                    sampling: Sampling::Centre,
                    effects: Effects::of(effects),
                    tracer: self.tracer,
                };
                (name, setting)
            })
            .collect()
    }

    /// Every setting the study renders, each once: the grid, then the
    /// effect steps that are not in it.
    pub fn settings(&self) -> Vec<Setting> {
        let mut settings = self.grid();
        for (_, step) in self.effect_steps() {
            if !settings.contains(&step) {
                settings.push(step);
            }
        }
        settings
    }

    /// The grid's most accurate termination: its largest depth, its
    /// smallest threshold.
    pub fn most_accurate(&self) -> Termination {
        Termination {
            max_depth: self.depths.iter().copied().max().unwrap_or(0),
            min_weight: self
                .thresholds
                .iter()
                .copied()
                .fold(f32::INFINITY, f32::min),
        }
    }

    /// The grid setting nearest the scene's own criteria, with one centre
    /// ray: what the chapter binaries render by default. Every knob is
    /// turned from here in the report's first table.
    pub fn base(&self) -> Setting {
        let Termination {
            max_depth,
            min_weight,
        } = self.scene_default;
        let depth = nearest(&self.depths, |&d| {
            (f64::from(d) - f64::from(max_depth)).abs()
        });
        let threshold = nearest(&self.thresholds, |&w| {
            ((f64::from(w) + 1e-6).ln() - (f64::from(min_weight) + 1e-6).ln()).abs()
        });
        Setting {
            termination: Termination {
                max_depth: depth,
                min_weight: threshold,
            },
            sampling: Sampling::Centre,
            effects: Effects::ALL,
            tracer: self.tracer,
        }
    }

    /// The rows whose error maps are written: the base, the base with the
    /// grid's smallest depth, largest threshold, and second-largest number
    /// of jittered rays, and the grid's most accurate row.
    pub fn mapped(&self) -> Vec<Setting> {
        let base = self.base();
        let mut settings = vec![base];
        let mut shallow = base;
        shallow.termination.max_depth = self.depths.iter().copied().min().unwrap_or(0);
        let mut lenient = base;
        lenient.termination.min_weight = self.thresholds.iter().copied().fold(0.0, f32::max);
        let jittered: Vec<Sampling> = self
            .samplings
            .iter()
            .copied()
            .filter(|s| s.is_random())
            .collect();
        settings.extend([shallow, lenient]);
        if let Some(&sampling) = jittered.iter().rev().nth(1) {
            settings.push(Setting { sampling, ..base });
        }
        if let Some(&sampling) = jittered.last() {
            settings.push(Setting {
                termination: self.most_accurate(),
                sampling,
                ..base
            });
        }
        settings.dedup();
        settings
    }
    /// The reference's setting.
    pub fn reference(&self) -> Setting {
        Setting {
            tracer: self.tracer,
            ..reference_setting(self.reference_samples)
        }
    }
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

/// The value of `values` with the smallest `distance`.
fn nearest<T: Copy>(values: &[T], distance: impl Fn(&T) -> f64) -> T {
    *values
        .iter()
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))
        .expect("the grid has values")
}
