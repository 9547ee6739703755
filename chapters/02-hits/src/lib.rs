#![doc = include_str!("../README.md")]

mod plane;
mod sphere;
mod triangle;

pub use ch01_rays::{Camera, Ray, render, toolkit};
pub use plane::intersect_plane;
pub use sphere::{intersect_sphere, sphere_point, sphere_roots};
pub use triangle::{intersect_triangle, triangle_normal};

use toolkit::scene::{Object, Shape};
use toolkit::{Color, Image, Scene, Stats, Vec3};

/// Where a ray hits a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Distance along the ray.
    pub t: f32,
    /// The point hit.
    pub point: Vec3,
    /// The surface's geometric unit normal at the point, as the shape defines
    /// it: outward for a sphere, n for a plane, (b − a) × (c − a) for a
    /// triangle. It may face away from the ray; shading decides what to do.
    pub normal: Vec3,
    /// Index of the object in the scene.
    pub object: usize,
}

/// The distance in (t_min, t_max) at which the ray first hits a shape.
pub fn intersect(shape: &Shape, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
    match *shape {
        Shape::Sphere { center, radius } => intersect_sphere(center, radius, ray, t_min, t_max),
        Shape::Plane { normal, offset } => intersect_plane(normal, offset, ray, t_min, t_max),
        Shape::Triangle { vertices } => {
            intersect_triangle(vertices, ray, t_min, t_max).map(|(t, _, _)| t)
        }
    }
}

/// The hit record of `ray` meeting `shape` at distance t.
pub fn hit_at(shape: &Shape, ray: &Ray, t: f32, object: usize) -> Hit {
    let (point, normal) = match *shape {
        Shape::Sphere { center, radius } => {
            let point = sphere_point(center, radius, ray, t);
            (point, (point - center) / radius)
        }
        Shape::Plane { normal, .. } => (ray.at(t), normal),
        Shape::Triangle { vertices } => (ray.at(t), triangle_normal(vertices)),
    };
    Hit {
        t,
        point,
        normal,
        object,
    }
}

/// The closest hit of a ray over all objects, for t in (t_min, t_max).
///
/// Each object is tested with the nearest hit so far as the upper bound, so
/// an object behind it is rejected without more work.
pub fn closest_hit(objects: &[Object], ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
    let mut closest: Option<(f32, usize)> = None;
    for (index, object) in objects.iter().enumerate() {
        let bound = closest.map_or(t_max, |(t, _)| t);
        if let Some(t) = intersect(&object.shape, ray, t_min, bound) {
            closest = Some((t, index));
        }
    }
    closest.map(|(t, index)| hit_at(&objects[index].shape, ray, t, index))
}

/// What the chapter-2 picture shows at each hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum View {
    /// Each object in its material's colour, no light at all.
    #[default]
    Flat,
    /// The unit normal n mapped to a colour: (n + 1) / 2.
    Normals,
    /// Distance: white near the eye, fading to black far away.
    Depth,
}

/// The colour seen along a primary ray in the chosen view.
pub fn shade(scene: &Scene, view: View, ray: &Ray) -> Color {
    let hit = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY);
    match (view, hit) {
        (View::Flat, Some(hit)) => scene.material(&scene.objects[hit.object]).color,
        (View::Normals, Some(hit)) => (hit.normal + Vec3::ONE) / 2.0,
        (View::Depth, Some(hit)) => {
            // Fade by e^(−t/s), with s the distance from the eye to what it looks at.
            let scale = scene.camera.eye.distance(scene.camera.look_at);
            Color::splat((-hit.t / scale).exp())
        }
        (View::Depth, None) => Color::ZERO, // infinitely far
        (_, None) => scene.image.background,
    }
}

/// Chapter 2's picture: every pixel's closest hit, shown in `view`.
pub fn render_hits(scene: &Scene, view: View, on_row: impl Fn() + Sync) -> (Image, Stats) {
    render(scene, |ray, _| shade(scene, view, ray), on_row)
}

/// This chapter, for the command line.
pub const CHAPTER: toolkit::cli::Chapter = toolkit::cli::Chapter {
    folder: "02-hits",
    title: "ray-plane, ray-sphere and ray-triangle intersection",
    default_scene_path: "chapters/02-hits/scenes/default.toml",
    default_scene: include_str!("../scenes/default.toml"),
};
