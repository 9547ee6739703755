#![doc = include_str!("../README.md")]

pub use ch06_refraction::{
    Camera, Glass, Hit, Mirrors, Path, Ray, Secondary, SecondaryKind, ShadowStart, Surface,
    Whitted, World, closest_hit, lambert, offset_origin, reflect, refract, render, render_whitted,
    schlick, shade, toolkit, trace,
};

use toolkit::{Color, Image, Scene, Stats};

/// The lecture's three termination criteria. A path ends when
/// 1. its ray hits nothing: the background is all there is to see;
/// 2. it has bounced `max_depth` times; or
/// 3. its weight, the product of the weights along it, falls below
///    `min_weight` (in every channel): whatever it found could change the
///    pixel by less than that.
///
/// The first needs no decision (see [`trace`]); the other two are here, and
/// each path they end is counted in the statistics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Termination {
    pub max_depth: u32,
    pub min_weight: f32,
}

impl Termination {
    /// The criteria of a scene's `[trace]` table.
    pub fn of(scene: &Scene) -> Termination {
        Termination {
            max_depth: scene.trace.max_depth,
            min_weight: scene.trace.min_weight,
        }
    }
}

/// The complete tracer: chapter 6's rays, ended by explicit criteria.
#[derive(Debug, Clone, Copy)]
pub struct Tracer {
    pub termination: Termination,
}

impl Whitted for Tracer {
    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        let glass = Glass {
            mirrors: Mirrors {
                max_depth: self.termination.max_depth,
            },
        };
        glass.secondary_rays(surface, incoming)
    }

    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool {
        // EXERCISE(ch07-may-trace): false (and count stats.ended_max_depth) beyond max_depth; false (and count stats.ended_threshold) if every channel of weight < min_weight; else true
        if depth > self.termination.max_depth {
            stats.ended_max_depth += 1;
            false
        } else if weight.max_element() < self.termination.min_weight {
            stats.ended_threshold += 1;
            false
        } else {
            true
        }
        // END EXERCISE
    }
}

/// Chapter 7's picture, with the given criteria.
pub fn render_terminated(
    scene: &Scene,
    termination: Termination,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    render_whitted(&Tracer { termination }, scene, &scene.objects[..], on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: toolkit::cli::Chapter = toolkit::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
