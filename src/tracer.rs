//! The complete tracer: the most advanced chapter's, chosen once per scene
//! by the effects the scene calls for.
//!
//! Everything of chapter 7 (and the intersection routines of chapter 2 it is
//! built on) is re-exported here; what this module adds serves only the
//! complete tracer: a tracer without secondary rays for scenes that need
//! none ([`Direct`]), and the choice between the two ([`render_complete`]).

pub use ch02_hits::{
    Quadratic, closest_hit_by, coincident_range, first_coincident, hit_at, hit_with_weights,
    intersect, intersect_cone, intersect_plane, intersect_sphere, intersect_triangle, sphere_point,
    sphere_roots, triangle_normal, triangle_plane_t,
};
pub use ch07_termination::*;

use crate::toolkit::scene::Effect;
use crate::toolkit::{Color, Image, Scene, Stats};

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
        shade(
            scene,
            world,
            surface,
            ShadowStart::Offset,
            stats,
            |incoming| lambert(surface, incoming),
        )
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
