//! Chapter 1's ray tree (`--pixel X,Y`): the pixel's primary ray, which
//! meets nothing in this chapter's empty world and sees the sky.

use crate::toolkit::{Scene, Vec3};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::{TreeRay, primary_node};
use crate::workbench::ray_tree::{RayNode, TracerInfo};
use crate::{Camera, Ray, sky};

impl TreeRay for Ray {
    fn origin(&self) -> Vec3 {
        self.origin
    }

    fn direction(&self) -> Vec3 {
        self.direction
    }
}

/// The ray the tree follows: the scene camera's primary ray through the
/// pixel's centre (one ray, whatever the scene's samples).
pub fn primary_ray(scene: &Scene, pixel: Pixel) -> Ray {
    let camera = Camera::new(&scene.camera, scene.image.width, scene.image.height);
    camera.primary_ray(pixel.x, pixel.y)
}

/// Chapter 1's tree: the primary ray and the sky colour it sees.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    (TracerInfo::default(), primary_node(&ray, None, sky(&ray)))
}
