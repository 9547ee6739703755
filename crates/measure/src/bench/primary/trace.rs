//! The primary rays of a scene, the world they are traced against, and
//! tracing them to their closest hits on one thread or on a pool's threads.

use rayon::prelude::*;

use raybook::toolkit::Scene;
use raybook::tracer::{Camera, Ray, World};

/// The world primary rays are traced against: the complete tracer's
/// ([`raybook::world`]), the one `raybook render` uses.
pub fn primary_world(scene: &Scene) -> impl World + '_ {
    raybook::world(scene)
}

/// The primary rays of `scene` at its image size, row by row from the top
/// left: one per pixel, through the pixel's centre, as the renderer makes
/// them with one sample per pixel ([`Camera::primary_ray`]).
pub fn primary_rays(scene: &Scene) -> Vec<Ray> {
    let (width, height) = (scene.image.width, scene.image.height);
    let camera = Camera::new(&scene.camera, width, height);
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| camera.primary_ray(x, y))
        .collect()
}

/// The distance to the closest hit of each ray, +∞ where it hits nothing:
/// `closest_hit` for t in [0, ∞), as the tracer asks for a primary ray.
pub fn hit_distances(world: &(impl World + ?Sized), rays: &[Ray]) -> Vec<f32> {
    let mut t = vec![0.0; rays.len()];
    trace_serial(world, rays, &mut t);
    t
}

fn closest_t(world: &(impl World + ?Sized), ray: &Ray) -> f32 {
    world
        .closest_hit(ray, 0.0, f32::INFINITY)
        .map_or(f32::INFINITY, |hit| hit.t)
}

/// On this thread, one ray after the other.
pub(super) fn trace_serial(world: &(impl World + ?Sized), rays: &[Ray], t: &mut [f32]) {
    for (ray, t) in rays.iter().zip(t) {
        *t = closest_t(world, ray);
    }
}

/// On the current rayon pool's threads.
pub(super) fn trace_parallel(world: &(impl World + ?Sized), rays: &[Ray], t: &mut [f32]) {
    rays.par_iter()
        .zip(t.par_iter_mut())
        .for_each(|(ray, t)| *t = closest_t(world, ray));
}
