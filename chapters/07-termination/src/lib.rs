#![doc = include_str!("../README.md")]

pub use ch06_refraction::{
    Camera, Glass, Hit, Kind, Mirrors, Path, Ray, Secondary, Surface, Whitted, World, closest_hit,
    offset_origin, reflect, refract, render, render_whitted, schlick, toolkit, trace,
};

use ch06_refraction::{Origin, lambert, shade};
use toolkit::scene::Effect;
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

/// The complete tracer for a scene that calls for neither reflection nor
/// refraction: each hit gets chapter 4's shadowed Lambert shading, and no
/// secondary ray ever leaves it.
///
/// It is the same [`trace`] as [`Tracer`]'s, and makes the same picture. But
/// its answers are fixed before rendering, so the compiler builds a `trace`
/// without the recursion, the highlight and the secondary rays: machinery
/// the scene does not call for costs nothing (`cargo bench --bench effects`).
#[derive(Debug, Clone, Copy)]
pub struct Direct;

impl Whitted for Direct {
    /// Lambert shading where shadow rays are free: no material is shiny
    /// under a point or spot light, so there is no highlight to add.
    fn local(
        &self,
        scene: &Scene,
        world: &(impl World + ?Sized),
        surface: &Surface,
        stats: &mut Stats,
    ) -> Color {
        shade(scene, world, surface, Origin::Offset, stats, |incoming| {
            lambert(surface, incoming)
        })
    }

    /// None: no material reflects or transmits.
    fn secondary_rays(&self, _: &Surface, _: &Ray) -> [Option<Secondary>; 2] {
        [None, None]
    }

    /// Never asked: there are no secondary rays.
    fn may_trace(&self, _: u32, _: Color, _: &mut Stats) -> bool {
        false
    }
}

/// Renders `scene` against `world` with the complete tracer, chosen once,
/// before rendering, by the effects the scene calls for: [`Direct`] if it
/// calls for neither reflection nor refraction, else [`Tracer`] with the
/// given criteria. Both give the same picture and the same statistics.
pub fn render_complete(
    scene: &Scene,
    world: &(impl World + ?Sized),
    termination: Termination,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    let effects = scene.calls_for();
    if effects.contains(Effect::Reflection) || effects.contains(Effect::Refraction) {
        render_whitted(&Tracer { termination }, scene, world, on_row)
    } else {
        render_whitted(&Direct, scene, world, on_row)
    }
}

/// Chapter 7's picture, with the given criteria.
pub fn render_terminated(
    scene: &Scene,
    termination: Termination,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    render_complete(scene, &scene.objects[..], termination, on_row)
}

/// This chapter, for the command line.
pub const CHAPTER: toolkit::cli::Chapter = toolkit::cli::Chapter {
    folder: "07-termination",
    title: "termination criteria",
    default_scene_path: "chapters/07-termination/scenes/default.toml",
    default_scene: include_str!("../scenes/default.toml"),
    effects: ch06_refraction::CHAPTER.effects,
};
