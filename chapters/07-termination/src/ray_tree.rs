//! Chapter 7's ray tree (`--pixel X,Y`): chapter 6's tree, with paths ended
//! by the three termination criteria (no hit, maximum depth, weight
//! threshold); each ended path says which one ended it.

pub use ch06_refraction::ray_tree::{explain_split, explain_with};

use crate::toolkit::Scene;
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{RayNode, TracerInfo};
use crate::{Termination, Tracer, World};

/// What the complete tracer does, with these criteria.
pub fn tracer_info(termination: Termination) -> TracerInfo {
    TracerInfo {
        hits: true,
        lights: true,
        shadow_rays: true,
        max_depth: Some(termination.max_depth),
        min_weight: Some(termination.min_weight),
    }
}

/// The tree of the pixel's ray as the complete tracer traces it against
/// `world` (the scene's objects here; chapter 8 passes its BVH).
pub fn explain_against(
    scene: &Scene,
    world: &(impl World + ?Sized),
    termination: Termination,
    pixel: Pixel,
) -> (TracerInfo, RayNode) {
    let tracer = Tracer { termination };
    let info = tracer_info(termination);
    explain_with(&tracer, scene, world, pixel, info, explain_split)
}

/// Chapter 7's tree, with the given criteria.
pub fn explain(scene: &Scene, termination: Termination, pixel: Pixel) -> (TracerInfo, RayNode) {
    explain_against(scene, &scene.objects[..], termination, pixel)
}
