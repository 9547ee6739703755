#![doc = include_str!("../README.md")]

pub mod ray_tree;

pub use ch06_refraction::{
    Camera, Glass, Hit, Mirrors, Path, Ray, Secondary, SecondaryKind, ShadowStart, Surface,
    Whitted, World, closest_hit, glass_secondary_rays, lambert, offset_origin, reflect, refract,
    render, render_whitted, scene_files, schlick, shade, toolkit, trace, workbench,
};

use toolkit::{Color, Image, Scene, Stats};

/// The lecture's three termination criteria. A path ends when
/// 1. its ray hits nothing: the background is all there is to see;
/// 2. it would bounce more than `max_depth` times; or
/// 3. its weight, the product of the weights along it, is below
///    `min_weight` ([`below_threshold`], which says what "below" means for
///    three channels): whatever it finds counts too little in the pixel.
///
/// The weight bounds a path's share of the pixel *relative to the colour
/// it would bring back*. Colours are not clamped until the pixel is
/// written, and a brightly lit surface can be far above 1, so a path below
/// the threshold can still change the pixel by more than `min_weight`
/// (`scenes/floodlit.toml`). The threshold bounds the error only where the
/// colours are at most 1.
///
/// The first criterion needs no decision (see [`trace`]); the other two are
/// here, and each path they end is counted in the statistics.
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

/// Is a path's `weight` below the threshold `min_weight`? The weight
/// criterion, derived in the README, section *The two decisions*.
///
/// * `weight` is the product of the weights along the path, per channel,
///   each channel ≥ 0. `min_weight` is the scene's threshold, ≥ 0.
/// * `true` when what the path could still bring back is too little to be
///   worth following, `false` while it may still matter. A weight has three
///   channels: which test of them says that (each of them, one of them, or
///   their mean) is the README's question, and a weight of
///   (0.5, 0.0001, 0.0001), half of the red the path finds, is the case to
///   think of.
/// * A weight exactly at `min_weight` is not below it; with
///   `min_weight` = 0 no weight is below it.
pub fn below_threshold(weight: Color, min_weight: f32) -> bool {
    // EXERCISE(ch07-below-threshold): whether the path's weight is too small, in the README's sense, to be worth following
    crate::workbench::exercise::solution_begins("ch07-below-threshold");
    weight.max_element() < min_weight
    // END EXERCISE
}

/// The complete tracer: chapter 6's rays, ended by explicit criteria.
#[derive(Debug, Clone, Copy)]
pub struct Tracer {
    pub termination: Termination,
}

impl Whitted for Tracer {
    /// Chapter 6's: the mirror ray, and at glass the refracted ray.
    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        glass_secondary_rays(surface, incoming)
    }

    /// May a ray be traced? The lecture's last two criteria, derived in the
    /// README, section *The two decisions*.
    ///
    /// * `depth` is the ray's depth (1 for the first bounce, as in chapter
    ///   5) and `weight` the weight of its whole path, up to and including
    ///   its own.
    /// * `false` if the path has had its `max_depth` bounces already
    ///   (`max_depth = 1` follows exactly one bounce, 0 none) or if its
    ///   weight is below the threshold `min_weight` ([`below_threshold`]);
    ///   else `true`.
    /// * Each `false` ends a path and is counted once, by the criterion that
    ///   ended it: `stats.ended_max_depth` or `stats.ended_threshold`; the
    ///   depth is asked first. A `true` counts nothing here (the caller
    ///   counts the rays it traces).
    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool {
        // EXERCISE(ch07-may-trace): a ray may go on unless its path has had its max_depth bounces or its weight is below the threshold; count each path ended by the criterion that ended it (the depth first)
        crate::workbench::exercise::solution_begins("ch07-may-trace");
        if depth > self.termination.max_depth {
            stats.ended_max_depth += 1;
            false
        } else if below_threshold(weight, self.termination.min_weight) {
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
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
