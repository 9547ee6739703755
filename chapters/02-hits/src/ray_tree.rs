//! Chapter 2's ray tree (`--pixel X,Y`): the primary ray and its closest
//! hit, with both roots of the quadratic when the hit is on a sphere.

pub use ch01_rays::ray_tree::{primary_ray, ray_node, rgb};

use crate::toolkit::scene::Shape;
use crate::toolkit::{Scene, Vec3};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{End, HitNode, RayKind, RayNode, Side, TracerInfo, shape_name};
use crate::{Hit, Ray, View, closest_hit, shade, sphere_roots};

/// What the tree says of a hit: the object, t, the point, the normal (as
/// the shape defines it, and turned to face the ray), the side it faced,
/// and for a sphere the quadratic's two roots (nearest first).
pub fn hit_node(scene: &Scene, hit: &Hit, ray: &Ray) -> HitNode {
    let object = &scene.objects[hit.object];
    let back = hit.normal.dot(ray.direction) > 0.0;
    let facing: Vec3 = if back {
        -hit.shading_normal
    } else {
        hit.shading_normal
    };
    let roots = match object.shape {
        Shape::Sphere { center, radius } => sphere_roots(center, radius, ray).map(|(a, b)| [a, b]),
        _ => None,
    };
    HitNode {
        object: hit.object,
        shape: shape_name(&object.shape).into(),
        material: scene.material(object).name.clone(),
        t: hit.t,
        point: rgb(hit.point),
        normal: rgb(hit.normal),
        facing_normal: rgb(facing),
        side: if back { Side::Back } else { Side::Front },
        roots,
    }
}

/// What this chapter's tracer does.
pub const TRACER: TracerInfo = TracerInfo {
    hits: true,
    lights: false,
    shadow_rays: false,
    max_depth: None,
    min_weight: None,
};

/// Chapter 2's tree: the primary ray, its closest hit (as `shade` finds
/// it) and the colour the chosen view shows there.
pub fn explain(scene: &Scene, view: View, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let mut node = ray_node(RayKind::Primary, 0, &ray);
    match closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY) {
        None => node.end = Some(End::NoHit),
        Some(hit) => node.hit = Some(hit_node(scene, &hit, &ray)),
    }
    node.color = Some(rgb(shade(scene, view, &ray)));
    (TRACER, node)
}
