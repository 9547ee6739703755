//! Chapter 2's ray tree (`--pixel X,Y`): the primary ray and its closest
//! hit, with both roots of the sphere's quadratic when the hit is on a
//! sphere, as the code that drew the pixel returned them.

pub use ch01_rays::ray_tree::primary_ray;

use crate::toolkit::Scene;
use crate::toolkit::scene::Shape;
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::primary_node;
use crate::workbench::ray_tree::{HitFacts, HitNode, RayNode, TracerInfo};
use crate::{Hit, Method, Ray, View, closest_hit_by, shade};

/// The tree's node of the chapter's `hit`, found by the robust forms (the
/// tracer's from chapter 3 on), with [`sphere_roots`](crate::sphere_roots)'
/// roots when it is on a sphere.
pub fn hit_node(scene: &Scene, hit: &Hit, ray: &Ray) -> HitNode {
    hit_node_by(Method::Robust, scene, hit, ray)
}

/// The tree's node of `hit`, found by `method`, with the roots that
/// `method`'s own sphere quadratic returned when it is on a sphere: the
/// student's `sphere_roots_abc` for the lecture's methods. (Roots from
/// another solver would not be the ones that drew the pixel: they differ
/// on a far sphere, and miss where the student's rounding hit.)
pub fn hit_node_by(method: Method, scene: &Scene, hit: &Hit, ray: &Ray) -> HitNode {
    let roots = match scene.objects[hit.object].shape {
        Shape::Sphere { center, radius } => method.sphere_roots(center, radius, ray),
        _ => None,
    };
    let normals = (hit.normal, hit.shading_normal);
    let facts = HitFacts::new(hit.object, hit.t, hit.point, normals, roots);
    HitNode::new(scene, facts, ray.direction)
}

/// Chapter 2's tree: the primary ray, its closest hit (as `shade` finds
/// it, by `method`: the lecture's, your own, unless `--method robust`)
/// and the colour the chosen view shows there.
pub fn explain(scene: &Scene, view: View, method: Method, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let intersect =
        |shape: &Shape, ray: &Ray, t_min, t_max| method.intersect(shape, ray, t_min, t_max);
    let hit = closest_hit_by(intersect, &scene.objects, &ray, 0.0, f32::INFINITY);
    let hit = hit.map(|hit| hit_node_by(method, scene, &hit, &ray));
    let color = shade(scene, view, method, &ray);
    (TracerInfo::HITS, primary_node(&ray, hit, color))
}
