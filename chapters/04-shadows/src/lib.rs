#![doc = include_str!("../README.md")]

mod offset;

pub mod ray_tree;

pub use ch03_lambert::{
    Camera, Hit, Incoming, Ray, Surface, closest_hit, direct_light, intersect, lambert, render,
    scene_files, toolkit, workbench,
};
pub use offset::offset_origin;

use toolkit::scene::Object;
use toolkit::{Color, Image, Scene, Stats};

/// Where shadow rays start.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ShadowStart {
    /// Just off the surface, by [`offset_origin`]: no acne.
    #[default]
    Offset,
    /// Exactly at the computed hit point: shows shadow acne (for the lesson).
    HitPoint,
}

/// The shadow ray from a surface towards one light, and the parameter
/// t_max at which it reaches that light. Derived in the README, section
/// *The shadow ray* (where it starts: section *Shadow acne*).
///
/// * `surface.hit` is the point p that the eye sees, with its geometric
///   normal and its error bound. `incoming.direction` is l, the unit vector
///   from p towards the light, and `incoming.distance` is r, the distance
///   from p to the light.
/// * The ray starts where `origin` says: `ShadowStart::Offset`, at
///   [`offset_origin`] for a ray leaving towards the light (just off the
///   surface, on the light's side); `ShadowStart::HitPoint`, at p itself
///   (the chapter's demonstration of acne).
/// * Its direction has length 1, so t measures distance along it, and it
///   goes from the surface towards the light.
/// * t_max is the t at which this ray arrives at the light's position. A
///   hit at 0 < t < t_max then stands between the surface and the light;
///   one at t ≥ t_max is beyond the light and blocks nothing. (Why it is
///   neither ∞ nor 1, and from which point it is measured, is the README's
///   question.)
pub fn shadow_ray(surface: &Surface, incoming: &Incoming, origin: ShadowStart) -> (Ray, f32) {
    // EXERCISE(ch04-shadow-ray): the ray from the surface towards the light, starting where `origin` says, and the t at which it reaches the light
    crate::workbench::exercise::solution_begins("ch04-shadow-ray");
    let point = surface.hit.point;
    let light = point + incoming.direction * incoming.distance;
    let start = match origin {
        ShadowStart::Offset => offset_origin(&surface.hit, incoming.direction),
        ShadowStart::HitPoint => point,
    };
    let ray = Ray {
        origin: start,
        direction: incoming.direction,
    };
    (ray, start.distance(light))
    // END EXERCISE
}

/// Does anything block a shadow ray? Derived in the README, section *The
/// shadow ray*.
///
/// * `true` if some object of `objects` whose `shadows` flag is set is hit
///   by `ray` at a t strictly between `t_min` and `t_max`, as chapter 2's
///   `intersect` decides for each shape; `false` otherwise, and for an
///   empty list.
/// * An object with `shadows = false` never blocks, wherever it is.
/// * Which blocker it is, and how near, does not matter: unlike
///   `closest_hit`, it returns at the first one found without testing the
///   objects after it.
pub fn any_hit(objects: &[Object], ray: &Ray, t_min: f32, t_max: f32) -> bool {
    // EXERCISE(ch04-any-hit): is some object that casts shadows hit for t in (t_min, t_max)? Stop at the first one found
    crate::workbench::exercise::solution_begins("ch04-any-hit");
    objects
        .iter()
        .filter(|object| object.shadows)
        .any(|object| intersect(&object.shape, ray, t_min, t_max).is_some())
    // END EXERCISE
}

/// What rays are traced against. The two questions a tracer asks of its
/// objects: the closest hit (chapter 2) and whether anything blocks a
/// shadow ray (this chapter). Chapters 2 to 7 ask them of every object in
/// turn; chapter 8 answers them faster with a bounding volume hierarchy.
pub trait World: Sync {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit>;
    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool;
}

/// The objects themselves, tested one by one.
impl World for [Object] {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        closest_hit(self, ray, t_min, t_max)
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        any_hit(self, ray, t_min, t_max)
    }
}

/// Does a light reach the surface, or does something stand between them?
/// Derived in the README, section *One shadow ray per light* (the shadow
/// ray itself: section *The shadow ray*).
///
/// * `incoming` is what the light sends to the point seen (chapter 3's
///   `arrival`): l, the distance to the light, and whether the light casts
///   shadows. `origin` says where the shadow ray starts (see
///   [`shadow_ray`]).
/// * A light that casts no shadows (`incoming.casts_shadows` is false) is
///   free: `true`, with no ray traced and nothing counted.
/// * Any other light costs exactly one shadow ray, the one [`shadow_ray`]
///   makes, counted once in `stats.shadow`, and asked of `world.any_hit`.
///   The light is free (`true`) if nothing stands between the shadow ray's
///   origin and the light, blocked (`false`) if something does. (Which
///   interval to ask about is the README's question.)
pub fn light_is_free(
    world: &(impl World + ?Sized),
    surface: &Surface,
    incoming: &Incoming,
    origin: ShadowStart,
    stats: &mut Stats,
) -> bool {
    // EXERCISE(ch04-light-is-free): a light that casts no shadows is free without a ray; otherwise one shadow ray (counted in stats.shadow) decides whether anything stands between the surface and the light
    crate::workbench::exercise::solution_begins("ch04-light-is-free");
    if !incoming.casts_shadows {
        return true;
    }
    stats.shadow += 1;
    let (ray, distance) = shadow_ray(surface, incoming, origin);
    !world.any_hit(&ray, 0.0, distance)
    // END EXERCISE
}

/// The light reaching the eye from a surface: chapter 3's `direct_light`,
/// with each light first asked for by a shadow ray. `reflect` says how much
/// of a free light comes back (here: [`lambert`]; chapter 5 adds a highlight).
pub fn shade(
    scene: &Scene,
    world: &(impl World + ?Sized),
    surface: &Surface,
    origin: ShadowStart,
    stats: &mut Stats,
    reflect: impl Fn(&Incoming) -> Color,
) -> Color {
    let visible = |surface: &Surface, incoming: &Incoming| {
        light_is_free(world, surface, incoming, origin, stats)
    };
    direct_light(scene, surface, visible, reflect)
}

/// The colour seen along a ray: the background, or the closest hit lit by
/// Lambert's law where its shadow rays are free.
pub fn trace(scene: &Scene, ray: &Ray, origin: ShadowStart, stats: &mut Stats) -> Color {
    match closest_hit(&scene.objects, ray, 0.0, f32::INFINITY) {
        None => scene.image.background,
        Some(hit) => {
            let surface = Surface::new(scene, hit, ray);
            shade(
                scene,
                &scene.objects[..],
                &surface,
                origin,
                stats,
                |incoming| lambert(&surface, incoming),
            )
        }
    }
}

/// Chapter 4's picture.
pub fn render_shadows(
    scene: &Scene,
    origin: ShadowStart,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    render(scene, |ray, stats| trace(scene, ray, origin, stats), on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
