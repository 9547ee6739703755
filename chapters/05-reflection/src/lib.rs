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

/// The colour seen along `ray`, traced against `world` by the Whitted
/// `tracer`. Derived in the README, section *Recursion, not a loop*.
///
/// * `path` is the ray's own place on its path: its depth (0 for a primary
///   ray) and the weight of the whole path up to and including it
///   ([`Path`]). The ray has a unit direction, so t is a distance.
/// * The ray's hit is the closest one of `world` in front of its origin, at
///   any distance.
/// * No hit: the scene's background colour. The path ends there, and that
///   is counted once in `stats.ended_no_hit` (the first of chapter 7's
///   criteria).
/// * A hit: the colour of the [`Surface`] seen there (chapter 3's
///   `Surface::new`), by the README's rule for trace(ray, depth), which is
///   its question. Its parts are the tracer's answers for that surface and
///   this ray ([`Whitted::local`], [`Whitted::secondary_rays`]) and
///   [`follow_secondary_rays`], given this ray's `path` (it works out the
///   deeper paths).
/// * Nothing else is counted here: the rays traced are counted where they
///   are made.
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

/// The light that a hit's secondary rays bring back to it: the sum term
/// of trace(ray, depth) in the README, section *Recursion, not a loop*
/// (paragraphs **Depth**, **Weight** and **Counting**).
///
/// * `secondary_rays` are the rays that leave the hit (`None` entries are
///   no ray); `path` is the depth and path weight of the ray that made the
///   hit, not of the secondary rays.
/// * Each secondary ray has its own [`Path`]: one bounce deeper than
///   `path`, and the weight of its whole path as the README's **Weight**
///   defines it, channel by channel.
/// * The tracer decides, with [`Whitted::may_trace`] asked of that depth
///   and weight, whether the ray goes on. A ray it refuses is neither traced
///   nor counted here, and adds nothing (may_trace counts the path it
///   ends).
/// * A ray it lets go on is counted once by its kind
///   ([`Secondary::count`]) and traced with [`trace`] at its own path. What
///   it sees counts in the sum times a weight: which one, the ray's own or
///   its path's, is the README's question (*Recursion, not a loop*), and
///   the tests check the answer.
/// * Black if no ray goes on.
pub fn follow_secondary_rays(
    tracer: &impl Whitted,
    scene: &Scene,
    world: &(impl World + ?Sized),
    secondary_rays: [Option<Secondary>; 2],
    path: Path,
    stats: &mut Stats,
) -> Color {
    // EXERCISE(ch05-recursion): the sum, over the secondary rays that the tracer lets go on one bounce deeper (with the path's weight times the ray's own), of the colour seen along each times a weight (which weight is the README's question); count each ray traced
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
