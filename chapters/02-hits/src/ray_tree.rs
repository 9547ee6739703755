//! Chapter 2's ray tree (`--pixel X,Y`): the primary ray and its closest
//! hit, with both roots of the quadratic when the hit is on a sphere.

pub use ch01_rays::ray_tree::primary_ray;

use crate::toolkit::Scene;
use crate::toolkit::scene::Shape;
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::primary_node;
use crate::workbench::ray_tree::{HitFacts, HitNode, RayNode, TracerInfo};
use crate::{Hit, Method, Ray, View, closest_hit_by, intersect_lecture, shade, sphere_roots};

/// The tree's node of the chapter's `hit`, with the roots of the chapter's
/// own sphere quadratic when it is on a sphere.
pub fn hit_node(scene: &Scene, hit: &Hit, ray: &Ray) -> HitNode {
    let roots = match scene.objects[hit.object].shape {
        Shape::Sphere { center, radius } => sphere_roots(center, radius, ray),
        _ => None,
    };
    let normals = (hit.normal, hit.shading_normal);
    let facts = HitFacts::new(hit.object, hit.t, hit.point, normals, roots);
    HitNode::new(scene, facts, ray.direction)
}

/// Chapter 2's tree: the primary ray, its closest hit (as `shade` finds
/// it, by the lecture's methods) and the colour the chosen view shows there.
pub fn explain(scene: &Scene, view: View, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let hit = closest_hit_by(intersect_lecture, &scene.objects, &ray, 0.0, f32::INFINITY);
    let hit = hit.map(|hit| hit_node(scene, &hit, &ray));
    let color = shade(scene, view, Method::Lecture, &ray);
    (TracerInfo::HITS, primary_node(&ray, hit, color))
}
