#![doc = include_str!("../README.md")]

mod coincident;
mod cone;
mod plane;
mod sphere;
mod stable;
mod triangle;

pub mod ray_tree;

pub use ch01_rays::{Camera, Ray, render, scene_files, toolkit, workbench};
pub use coincident::{coincidence_window, coincident_range, first_coincident};
pub use cone::{cone_point, intersect_cone};
pub use plane::{intersect_plane, plane_point};
pub use sphere::{intersect_sphere, nearest_root, sphere_point, sphere_roots_abc};
pub use stable::{Quadratic, sphere_roots};
pub use triangle::{
    barycentrics, intersect_triangle, smooth_normal, triangle_by_plane, triangle_hit_point,
    triangle_normal, triangle_plane_t, triangle_point,
};

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
    /// it: outward for a sphere, n for a plane, along (p₁ − p₀) × (p₂ − p₀)
    /// for a triangle (p₀, p₁, p₂), away from the axis for a cone (towards
    /// it if the cone is inside out). It may face away from the ray; shading
    /// decides what to do.
    /// Rays leaving the surface are offset along it.
    pub normal: Vec3,
    /// The unit normal that shading uses: the geometric `normal` for every
    /// shape but a [`Shape::SmoothTriangle`], whose corner normals are
    /// interpolated (see [`smooth_normal`]), on the same side as `normal`.
    pub shading_normal: Vec3,
    /// How far the computed `point` may lie off the true surface: a bound on
    /// its rounding error, which grows with the size of the coordinates
    /// involved (chapter 4 starts rays leaving the surface this far off it).
    pub error: f32,
    /// Index of the object in the scene.
    pub object: usize,
}

/// The distance in (t_min, t_max) at which the ray first hits a shape.
pub fn intersect(shape: &Shape, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
    match *shape {
        Shape::Sphere { center, radius } => intersect_sphere(center, radius, ray, t_min, t_max),
        Shape::Plane { normal, offset } => intersect_plane(normal, offset, ray, t_min, t_max),
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            intersect_triangle(vertices, ray, t_min, t_max).map(|(t, _, _)| t)
        }
        Shape::Cone {
            base,
            base_radius,
            apex,
            apex_radius,
            ..
        } => intersect_cone(base, base_radius, apex, apex_radius, ray, t_min, t_max),
    }
}

/// Where the ray meets `shape`, as [`intersect`] says, but by the lecture's
/// methods as written on paper: a sphere by its quadratic in a, b, c
/// ([`sphere_roots_abc`]), a triangle by its plane and then α and β
/// ([`triangle_by_plane`]). This chapter draws its pictures with them, so
/// that your own code draws them; the README's *When the numbers get hard*
/// and *Shared edges* show where they fail, and why the later chapters use
/// the robust forms.
pub fn intersect_lecture(shape: &Shape, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
    match *shape {
        Shape::Sphere { center, radius } => {
            nearest_root(sphere_roots_abc(center, radius, ray)?, t_min, t_max)
        }
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            triangle_by_plane(vertices, ray, t_min, t_max).map(|(t, _, _)| t)
        }
        _ => intersect(shape, ray, t_min, t_max),
    }
}

/// The hit record of `ray` meeting `shape` at distance t.
pub fn hit_at(shape: &Shape, ray: &Ray, t: f32, object: usize) -> Hit {
    let weights = match *shape {
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            barycentrics(vertices, ray)
        }
        Shape::Sphere { .. } | Shape::Plane { .. } | Shape::Cone { .. } => (0.0, 0.0),
    };
    hit_with_weights(shape, ray, t, weights, object)
}

/// [`hit_at`] for a caller that knows a triangle's barycentric weights
/// (α, β) of the hit already (they are ignored for other shapes).
pub fn hit_with_weights(
    shape: &Shape,
    ray: &Ray,
    t: f32,
    weights: (f32, f32),
    object: usize,
) -> Hit {
    // Each point lies on its surface up to rounding (projected onto a sphere
    // or plane; a triangle's is the ray's point r(t) with t worked out again
    // in f64, see triangle_hit_point), which bounds its error by a few units
    // in the last place (f32::EPSILON relative) of the largest coordinate
    // involved: the point's. A cone's point is worked out in f64 and is
    // off by its rounding to f32 only, as a sphere's is.
    let (point, normal, shading_normal, error) = match *shape {
        Shape::Sphere { center, radius } => {
            let point = sphere_point(center, radius, ray, t);
            let normal = (point - center) / radius;
            let error = 4.0 * f32::EPSILON * (largest(point) + radius);
            (point, normal, normal, error)
        }
        Shape::Plane { normal, offset } => {
            let point = plane_point(normal, offset, ray, t);
            (point, normal, normal, 8.0 * f32::EPSILON * largest(point))
        }
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            let normal = triangle_normal(vertices);
            let (point, error) = triangle_hit_point(vertices, weights, ray);
            let shading_normal = match *shape {
                Shape::SmoothTriangle { normals, .. } => smooth_normal(normals, weights, normal),
                _ => normal,
            };
            (point, normal, shading_normal, error)
        }
        Shape::Cone {
            base,
            base_radius,
            apex,
            apex_radius,
            inside_out,
        } => {
            let (point, outward) = cone_point(base, base_radius, apex, apex_radius, ray, t);
            let normal = if inside_out { -outward } else { outward };
            let error = 4.0 * f32::EPSILON * (largest(point) + base_radius.max(apex_radius));
            (point, normal, normal, error)
        }
    };
    Hit {
        t,
        point,
        normal,
        shading_normal,
        error,
        object,
    }
}

/// The largest magnitude of a point's coordinates, |p|∞.
fn largest(p: Vec3) -> f32 {
    p.abs().max_element()
}

/// The hit of the object that the ray meets first, by the tracer's robust
/// tests ([`intersect`]): [`closest_hit_by`] with them, and of surfaces
/// that lie within their error bounds of that hit, the one listed first
/// ([`first_coincident`], README, section *Coincident surfaces*). Every
/// chapter after this one traces with it.
pub fn closest_hit(objects: &[Object], ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
    let nearest = closest_hit_by(intersect, objects, ray, t_min, t_max)?;
    Some(first_coincident(objects, ray, (t_min, t_max), nearest))
}

/// The hit of the object that the ray meets first: the smallest t, over
/// all of `objects`, strictly between `t_min` and `t_max`. Derived in the
/// README, section *The closest hit*.
///
/// * `intersect(shape, ray, t_min, t_max)` says where the ray meets a
///   shape (the nearest t in the range, or `None`): this chapter's picture
///   passes the lecture's methods ([`intersect_lecture`]), every later
///   chapter the robust ones ([`intersect`]). The `Hit` returned is the
///   one [`hit_at`] fills in, with `object` the index of the object in
///   `objects`.
/// * The nearest object wins wherever it is in the list; for two objects
///   hit at exactly the same t, the first in the list.
/// * `None` if the ray meets no object in (t_min, t_max), or `objects` is
///   empty.
pub fn closest_hit_by(
    intersect: impl Fn(&Shape, &Ray, f32, f32) -> Option<f32>,
    objects: &[Object],
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<Hit> {
    // EXERCISE(ch02-closest): the hit of the object met nearest along the ray within (t_min, t_max), as a Hit, or None if the ray meets none
    crate::workbench::exercise::solution_begins("ch02-closest");
    let mut closest: Option<(f32, usize)> = None;
    for (index, object) in objects.iter().enumerate() {
        let bound = closest.map_or(t_max, |(t, _)| t);
        if let Some(t) = intersect(&object.shape, ray, t_min, bound) {
            closest = Some((t, index));
        }
    }
    closest.map(|(t, index)| hit_at(&objects[index].shape, ray, t, index))
    // END EXERCISE
}

/// Which tests find the hits of the chapter-2 picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Method {
    /// The lecture's methods, your own: [`intersect_lecture`].
    #[default]
    Lecture,
    /// The robust forms the later chapters trace with: [`intersect`], and
    /// the rule for coincident surfaces ([`closest_hit`]).
    Robust,
}

impl Method {
    /// Where `ray` meets `shape` in (t_min, t_max), by this method.
    pub fn intersect(self, shape: &Shape, ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
        match self {
            Method::Lecture => intersect_lecture(shape, ray, t_min, t_max),
            Method::Robust => intersect(shape, ray, t_min, t_max),
        }
    }

    /// Both roots of `ray`'s line meeting the sphere, nearest first, as
    /// this method computes them: your [`sphere_roots_abc`] for the
    /// lecture's, [`sphere_roots`] for the robust. The ray tree shows these,
    /// the roots of the code that drew the pixel.
    pub fn sphere_roots(self, center: Vec3, radius: f32, ray: &Ray) -> Option<(f32, f32)> {
        match self {
            Method::Lecture => sphere_roots_abc(center, radius, ray),
            Method::Robust => sphere_roots(center, radius, ray),
        }
    }
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

/// The colour seen along a primary ray in the chosen view, its closest hit
/// found by `method`.
pub fn shade(scene: &Scene, view: View, method: Method, ray: &Ray) -> Color {
    let hit = match method {
        Method::Lecture => {
            closest_hit_by(intersect_lecture, &scene.objects, ray, 0.0, f32::INFINITY)
        }
        Method::Robust => closest_hit(&scene.objects, ray, 0.0, f32::INFINITY),
    };
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
pub fn render_hits(
    scene: &Scene,
    view: View,
    method: Method,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    render(scene, |ray, _| shade(scene, view, method, ray), on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
