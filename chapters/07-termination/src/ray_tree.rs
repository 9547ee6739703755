//! Chapter 7's ray tree (`--pixel X,Y`): chapter 6's tree, with paths ended
//! by the three termination criteria (no hit, maximum depth, weight
//! threshold); each ended path says which one ended it.

pub use ch06_refraction::ray_tree::{Lesson, explain_split, explain_with};

use crate::toolkit::Scene;
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{RayNode, TracerInfo};
use crate::{Termination, Tracer, World};

/// Chapter 7's tree with its rays asked of `world` (chapter 8 passes its BVH).
pub fn explain_against(
    scene: &Scene,
    world: &(impl World + ?Sized),
    termination: Termination,
    pixel: Pixel,
) -> (TracerInfo, RayNode) {
    let tracer = Tracer { termination };
    let lesson = Lesson {
        scene,
        tracer: &tracer,
        world,
        split: explain_split,
    };
    let info = TracerInfo::recursive(termination.max_depth, Some(termination.min_weight));
    (info, explain_with(&lesson, pixel))
}

/// Chapter 7's tree, its rays asked of the scene's objects one by one.
pub fn explain(scene: &Scene, termination: Termination, pixel: Pixel) -> (TracerInfo, RayNode) {
    explain_against(scene, &scene.objects[..], termination, pixel)
}
