#![doc = include_str!("../README.md")]

mod lights;

pub mod ray_tree;

pub use ch02_hits::{
    Camera, Hit, Ray, closest_hit, intersect, render, scene_files, toolkit, workbench,
};
pub use lights::{Arrival, Incoming, arrival, spot_factor};

use toolkit::scene::Material;
use toolkit::{Color, Image, Scene, Stats, Vec3};

/// A hit as shading sees it: where, which way the surface faces, what it is made of.
#[derive(Debug, Clone, Copy)]
pub struct Surface<'a> {
    pub hit: Hit,
    /// The unit shading normal turned to face the incoming ray. Every
    /// surface is two-sided: the back of a plane or triangle (and the inside
    /// of a sphere) is shaded like its front, seen from where the eye is.
    pub normal: Vec3,
    /// Unit vector from the point back along the ray (towards the eye).
    pub to_eye: Vec3,
    pub material: &'a Material,
}

impl<'a> Surface<'a> {
    /// The surface seen by `ray` at `hit`.
    ///
    /// Which side the ray sees is decided by the geometric normal (the
    /// surface's true orientation); the shading normal, on the same side as
    /// it, is turned with it. (For flat shapes the two are the same.)
    pub fn new(scene: &'a Scene, hit: Hit, ray: &Ray) -> Surface<'a> {
        let facing = if hit.normal.dot(ray.direction) > 0.0 {
            -hit.shading_normal
        } else {
            hit.shading_normal
        };
        Surface {
            hit,
            normal: facing,
            to_eye: -ray.direction,
            material: scene.material(&scene.objects[hit.object]),
        }
    }
}

/// Lambert's cosine law: the light that a matte (Lambertian) surface sends
/// towards the eye of what one point or spot light gives it, in the
/// workbook's units, a pixel value per channel. Derived in the README,
/// section *Lambert's cosine law*, with the workbook's convention for the
/// 1/π in *Why there is no 1/π*.
///
/// * `surface.material.color` is the albedo k_d, per channel, in [0, 1].
/// * `surface.normal` is the unit normal n, already turned to face the eye:
///   use it, not the hit's geometric normal.
/// * `incoming.direction` is l, the unit vector from the surface point
///   towards the light; θ is the angle between n and l.
/// * `incoming.irradiance` is I_L, per channel: what the light gives a
///   surface that faces it head on. The fall-off with distance and a spot's
///   cone are already in it: do not apply them again.
/// * Colours multiply channel by channel. The result is never negative: a
///   light behind the surface or in its plane (θ ≥ 90°) gives black.
pub fn lambert(surface: &Surface, incoming: &Incoming) -> Color {
    // EXERCISE(ch03-lambert): the cosine law: what a matte surface of this albedo sends back of the incoming light; nothing for light from behind
    crate::workbench::exercise::solution_begins("ch03-lambert");
    let cos_theta = surface.normal.dot(incoming.direction).max(0.0);
    surface.material.color * incoming.irradiance * cos_theta
    // END EXERCISE
}

/// The light that reaches the eye from `surface`: the sum, channel by
/// channel, of what each light of the scene adds, [`arrival`] saying what a
/// light sends to the surface's point. Derived in the README, section *The
/// light loop*.
///
/// * An ambient light ([`Arrival::Ambient`]) adds its ambient term, the
///   albedo's share of its colour: once for each ambient light of the
///   scene, however many other lights there are.
/// * A point or spot light whose light arrives ([`Arrival::Incoming`])
///   adds `reflect(incoming)`, but only if the light is strictly in front
///   of the surface, on the side that `surface.normal` (the normal facing
///   the eye) points to, not in its plane or behind it, and
///   `visible(surface, incoming)` says that nothing blocks it. A light
///   behind the surface adds nothing, whatever `reflect` would say.
/// * `visible` is not even asked about a light that could add nothing
///   (which lights those are, and in which order to ask, is the README's
///   question). Chapter 4's `visible` traces a shadow ray, so every
///   question costs a ray, and the tests count the questions.
///
/// Lights add: two lights make a point brighter than either alone, and the
/// sum may exceed 1 (no clamping here: the picture clamps it when it is
/// written).
///
/// This chapter passes [`always_visible`] and [`lambert`]; chapter 4 passes a
/// shadow ray, chapter 5 adds a highlight to `reflect`.
pub fn direct_light(
    scene: &Scene,
    surface: &Surface,
    mut visible: impl FnMut(&Surface, &Incoming) -> bool,
    reflect: impl Fn(&Incoming) -> Color,
) -> Color {
    // EXERCISE(ch03-light-loop): the sum over the scene's lights (see `arrival`): what each of arrival's three answers adds, with visible asked only about a light that could add something
    crate::workbench::exercise::solution_begins("ch03-light-loop");
    let mut color = Color::ZERO;
    for light in &scene.lights {
        match arrival(light, surface.hit.point) {
            Arrival::Ambient(ambient) => color += surface.material.color * ambient,
            Arrival::Incoming(incoming) => {
                if surface.normal.dot(incoming.direction) <= 0.0 {
                    continue; // behind the surface
                }
                let light = reflect(&incoming);
                if light != Color::ZERO && visible(surface, &incoming) {
                    color += light;
                }
            }
            Arrival::Dark => {}
        }
    }
    color
    // END EXERCISE
}

/// Chapter 3 has no shadows yet: every light is seen from everywhere.
pub fn always_visible(_: &Surface, _: &Incoming) -> bool {
    true
}

/// The colour seen along a ray: the background if it hits nothing, else the
/// Lambert-shaded closest hit.
pub fn trace(scene: &Scene, ray: &Ray) -> Color {
    match closest_hit(&scene.objects, ray, 0.0, f32::INFINITY) {
        None => scene.image.background,
        Some(hit) => {
            let surface = Surface::new(scene, hit, ray);
            direct_light(scene, &surface, always_visible, |incoming| {
                lambert(&surface, incoming)
            })
        }
    }
}

/// Chapter 3's picture.
pub fn render_lambert(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    render(scene, |ray, _| trace(scene, ray), on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
