//! Chapter 6's ray tree (`--pixel X,Y`): chapter 5's tree, and at each
//! transparent surface how the light splits: entering or leaving, the two
//! indices and η, total internal reflection, Schlick's Fresnel term and the
//! weights of the mirror and refracted rays.

pub use ch05_reflection::ray_tree::{Lesson, explain_with};

use crate::toolkit::{Color, Scene};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{RayNode, RefractionNode, TracerInfo};
use crate::{Glass, Mirrors, Ray, Surface, split};

/// How the chapter's own [`split`] shares the light of `incoming` at
/// `surface` between the mirror ray and the refracted ray: its indices,
/// its Fresnel term and its weights, as it returned them; `None` for an
/// opaque material, which the chapter does not split. Only the geometry
/// comes from the hit: the side the ray meets (entering if it meets the
/// outside) and cos θ₁ = −n·d with the facing normal.
pub fn explain_split(surface: &Surface, incoming: &Ray) -> Option<RefractionNode> {
    let material = surface.material;
    if material.transparency == 0.0 {
        return None;
    }
    let shares = split(surface, incoming);
    let (n1, n2) = shares.indices;
    let eta = n1 / n2;
    let cos_theta1 = -surface.normal.dot(incoming.direction);
    Some(RefractionNode {
        entering: incoming.direction.dot(surface.hit.normal) < 0.0,
        n1,
        n2,
        eta,
        cos_theta1,
        sin2_theta2: eta * eta * (1.0 - cos_theta1 * cos_theta1),
        total_internal_reflection: shares.refracted.is_none(),
        fresnel: shares.fresnel,
        transparency: material.transparency,
        reflectance: material.reflectance.to_array(),
        reflected_weight: shares.reflected.to_array(),
        refracted_weight: shares.refracted.map(|(w, _): (Color, _)| w.to_array()),
    })
}

/// Chapter 6's tree: chapter 5's, with the split at glass.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let mirrors = Mirrors {
        max_depth: scene.trace.max_depth,
    };
    let (tracer, world) = (&Glass { mirrors }, &scene.objects[..]);
    let split = explain_split;
    let lesson = Lesson {
        scene,
        tracer,
        world,
        split,
    };
    let info = TracerInfo::recursive(mirrors.max_depth, None);
    (info, explain_with(&lesson, pixel))
}
