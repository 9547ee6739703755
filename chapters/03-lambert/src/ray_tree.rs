//! Chapter 3's ray tree (`--pixel X,Y`): the closest hit and what each light
//! adds there by the chapter's `arrival` and `lambert` (no shadow rays yet:
//! every light is free). Later chapters pass [`light_nodes`] the shadow
//! rays they traced and the highlight they add.

pub use ch02_hits::ray_tree::{hit_node, primary_ray};

use crate::toolkit::{Color, Scene};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::primary_node;
use crate::workbench::ray_tree::{Arriving, LightNode, RayNode, ShadowNode, Terms, TracerInfo};
use crate::{Arrival, Incoming, Surface, arrival, closest_hit, lambert, trace};

/// What each light of the scene does at `surface`, in the scene's order,
/// with the `highlight` and the `shadow` ray that later chapters add.
pub fn light_nodes(
    scene: &Scene,
    surface: &Surface,
    highlight: &dyn Fn(&Incoming) -> Option<Color>,
    shadow: &dyn Fn(&Incoming) -> Option<ShadowNode>,
) -> Vec<LightNode> {
    let light_node = |(index, light)| {
        let node = LightNode::new(index, light);
        match arrival(light, surface.hit.point) {
            Arrival::Ambient(ambient) => node.ambient(surface.material.color * ambient),
            Arrival::Dark => node,
            Arrival::Incoming(l) => {
                let light = Arriving::new(l.direction, l.distance, l.casts_shadows);
                let terms = || Terms::new(lambert(surface, &l), highlight(&l));
                node.arriving(surface.normal, light, terms, || shadow(&l))
            }
        }
    };
    scene.lights.iter().enumerate().map(light_node).collect()
}

/// Chapter 3's tree: the primary ray, its closest hit, each light's
/// Lambert term, and the colour the chapter's `trace` returns.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let color = trace(scene, &ray);
    let hit = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY);
    let mut node = primary_node(&ray, hit.map(|hit| hit_node(scene, &hit, &ray)), color);
    if let Some(hit) = hit {
        let surface = Surface::new(scene, hit, &ray);
        node.lights = light_nodes(scene, &surface, &|_| None, &|_| None);
        node.local = Some(color.to_array());
    }
    (TracerInfo::LIGHTS, node)
}
