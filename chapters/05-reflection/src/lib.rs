#![doc = include_str!("../README.md")]

mod mirror;

pub mod ray_tree;

pub use ch04_shadows::{
    Camera, Hit, Incoming, Ray, ShadowStart, Surface, World, any_hit, closest_hit, lambert,
    offset_origin, render, scene_files, shade, toolkit, workbench,
};
pub use mirror::{highlight, mirror_ray, reflect};

use toolkit::{Color, Image, Scene, Stats};

/// Which kind of secondary ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SecondaryKind {
    Reflection,
    Refraction,
}

/// A ray that leaves a hit, with the weight its colour gets in the hit's colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Secondary {
    pub ray: Ray,
    pub weight: Color,
    pub kind: SecondaryKind,
}

impl Secondary {
    /// Counts this ray in the statistics, by its kind.
    pub fn count(&self, stats: &mut Stats) {
        match self.kind {
            SecondaryKind::Reflection => stats.reflection += 1,
            SecondaryKind::Refraction => stats.refraction += 1,
        }
    }
}

/// What a recursive (Whitted) tracer decides at each hit. This chapter
/// answers each question with the mirror; chapter 6 brings a refracted ray,
/// chapter 7 explicit termination criteria, without changing [`trace`].
pub trait Whitted: Sync {
    /// The light that reaches the eye from the surface straight from the
    /// lights: chapter 4's shadowed Lambert shading plus the highlight.
    fn local(
        &self,
        scene: &Scene,
        world: &(impl World + ?Sized),
        surface: &Surface,
        stats: &mut Stats,
    ) -> Color {
        shade(
            scene,
            world,
            surface,
            ShadowStart::Offset,
            stats,
            |incoming| lambert(surface, incoming) + highlight(surface, incoming),
        )
    }

    /// The rays that leave the surface (at most two: a mirror ray and a
    /// refracted one).
    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2];

    /// May a ray be traced at `depth` (1 for the first bounce) on a path
    /// whose weights multiply to `weight`?
    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool;
}

/// This chapter's tracer: mirrors, with recursion ended at a fixed depth.
#[derive(Debug, Clone, Copy)]
pub struct Mirrors {
    /// The scene's `max_depth`: the number of bounces followed. The primary
    /// ray has depth 0 and the first mirror ray depth 1, so `max_depth = 1`
    /// follows exactly one bounce and `max_depth = 0` none.
    pub max_depth: u32,
}

impl Whitted for Mirrors {
    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        [
            mirror_ray(surface, incoming, surface.material.reflectance),
            None,
        ]
    }

    fn may_trace(&self, depth: u32, _: Color, stats: &mut Stats) -> bool {
        let within = depth <= self.max_depth;
        if !within {
            stats.ended_max_depth += 1;
        }
        within
    }
}

/// Where a ray is on its path: how many bounces from the eye (0 for a
/// primary ray, 1 for a ray leaving its first hit), and the product of the
/// weights along the path up to and including its own.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Path {
    pub depth: u32,
    pub weight: Color,
}

impl Path {
    /// A primary ray: depth 0, weight 1.
    pub const START: Path = Path {
        depth: 0,
        weight: Color::ONE,
    };
}

/// The colour seen along `ray`, traced against `world`, by a ray at `path`
/// (its depth and weight).
///
/// The background if the ray hits nothing: the path ends there (the first
/// of chapter 7's criteria, counted in `stats.ended_no_hit`). Otherwise the
/// hit's local light, plus the light its secondary rays bring back
/// ([`follow_secondary_rays`], which calls `trace` again: the recursion).
pub fn trace(
    tracer: &impl Whitted,
    scene: &Scene,
    world: &(impl World + ?Sized),
    ray: &Ray,
    path: Path,
    stats: &mut Stats,
) -> Color {
    // EXERCISE(ch05-trace): the background if the ray hits nothing (a path ended by no hit); else the hit's local light plus the light that its secondary rays bring back along this path
    crate::workbench::exercise::solution_begins("ch05-trace");
    let Some(hit) = world.closest_hit(ray, 0.0, f32::INFINITY) else {
        stats.ended_no_hit += 1;
        return scene.image.background;
    };
    let surface = Surface::new(scene, hit, ray);
    let local = tracer.local(scene, world, &surface, stats);
    let secondary = tracer.secondary_rays(&surface, ray);
    if secondary == [None, None] {
        return local; // a matte, opaque surface: its local light is all there is
    }
    local + follow_secondary_rays(tracer, scene, world, secondary, path, stats)
    // END EXERCISE
}

/// The light that reaches a surface along its secondary rays, for a hit
/// reached by a ray at `path`.
///
/// Each secondary ray is one bounce deeper than the ray that made the hit,
/// and its path's weight is the product of the weights along the way:
/// path.weight × secondary.weight. If the tracer lets a ray at that depth
/// and weight go on (`may_trace`), it is counted and traced (by calling
/// [`trace`] again), and the colour it sees counts with the ray's own weight:
///
/// ```text
/// colour = Σ over the rays traced  secondary.weight × trace(secondary.ray, depth + 1)
/// ```
///
/// (Only the ray's own weight multiplies what it sees: the weights before
/// it multiply the result on the way back up the recursion.)
pub fn follow_secondary_rays(
    tracer: &impl Whitted,
    scene: &Scene,
    world: &(impl World + ?Sized),
    secondary_rays: [Option<Secondary>; 2],
    path: Path,
    stats: &mut Stats,
) -> Color {
    // EXERCISE(ch05-recursion): the sum, over the secondary rays that the tracer lets go on one bounce deeper (with the path's weight times the ray's own), of the ray's weight times the colour seen along it; count each ray traced
    crate::workbench::exercise::solution_begins("ch05-recursion");
    let mut color = Color::ZERO;
    for secondary in secondary_rays.into_iter().flatten() {
        let next = Path {
            depth: path.depth + 1,
            weight: path.weight * secondary.weight,
        };
        if tracer.may_trace(next.depth, next.weight, stats) {
            secondary.count(stats);
            let seen = trace(tracer, scene, world, &secondary.ray, next, stats);
            color += secondary.weight * seen;
        }
    }
    color
    // END EXERCISE
}

/// Renders a scene with a Whitted tracer against `world` (the scene's
/// objects, or a faster structure over them): each primary ray starts a path.
pub fn render_whitted(
    tracer: &impl Whitted,
    scene: &Scene,
    world: &(impl World + ?Sized),
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    render(
        scene,
        |ray, stats| trace(tracer, scene, world, ray, Path::START, stats),
        on_row,
    )
}

/// Chapter 5's picture.
pub fn render_mirrors(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    let tracer = Mirrors {
        max_depth: scene.trace.max_depth,
    };
    render_whitted(&tracer, scene, &scene.objects[..], on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
