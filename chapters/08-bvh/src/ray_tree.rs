//! Chapter 8's ray tree (`--pixel X,Y`): chapter 7's, with every closest
//! hit and shadow ray asked of the BVH. The tree is the same as chapter 7's
//! for the same scene: the hierarchy changes how fast the answers come,
//! never what they are.

use ch07_termination::ray_tree::explain_against;

use crate::toolkit::Scene;
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{RayNode, TracerInfo};
use crate::{Bvh, Termination};

/// Chapter 8's tree: the complete tracer against a BVH of the scene.
pub fn explain(scene: &Scene, termination: Termination, pixel: Pixel) -> (TracerInfo, RayNode) {
    let bvh = Bvh::build(&scene.objects);
    explain_against(scene, &bvh, termination, pixel)
}
