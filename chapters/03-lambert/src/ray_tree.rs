//! Chapter 3's ray tree (`--pixel X,Y`): the closest hit and what each light
//! adds there by Lambert's law (no shadow rays yet: every light is free).
//!
//! [`light_nodes`] is shared by the later chapters: they pass the shadow
//! rays they traced and the highlight they add.

pub use ch02_hits::ray_tree::{hit_node, primary_ray, ray_node, rgb};

use crate::toolkit::{Color, Scene};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::{
    End, LightNode, LightStatus, RayKind, RayNode, ShadowNode, TracerInfo, light_kind,
};
use crate::{Arrival, Incoming, Surface, arrival, closest_hit, lambert, trace};

/// The highlight a chapter adds to a light's Lambert term (`None`: no highlights yet).
pub type HighlightTerm<'a> = &'a dyn Fn(&Incoming) -> Option<Color>;

/// The shadow ray a chapter traced towards a light, if it traced one.
pub type ShadowQuery<'a> = &'a mut dyn FnMut(&Incoming) -> Option<ShadowNode>;

/// What each light of the scene does at `surface`, in the scene's order,
/// decided as the lecture's light loop (`direct_light`) decides: ambient
/// light adds albedo × its colour; a light behind the surface (n·l ≤ 0) or
/// one that would add nothing is not asked about; any other adds its terms
/// unless the shadow ray `shadow` reports found it blocked.
pub fn light_nodes(
    scene: &Scene,
    surface: &Surface,
    highlight: HighlightTerm,
    shadow: ShadowQuery,
) -> Vec<LightNode> {
    (0..scene.lights.len())
        .map(|index| light_node(scene, index, surface, highlight, &mut *shadow))
        .collect()
}

/// One light at `surface`.
fn light_node(
    scene: &Scene,
    index: usize,
    surface: &Surface,
    highlight: HighlightTerm,
    shadow: ShadowQuery,
) -> LightNode {
    let light = &scene.lights[index];
    let mut node = LightNode {
        light: index,
        kind: light_kind(light).into(),
        status: LightStatus::Dark,
        direction: None,
        distance: None,
        n_dot_l: None,
        casts_shadows: None,
        shadow_ray: None,
        lambert: None,
        highlight: None,
        adds: [0.0; 3],
    };
    match arrival(light, surface.hit.point) {
        Arrival::Ambient(ambient) => {
            node.status = LightStatus::Ambient;
            node.adds = rgb(surface.material.color * ambient);
        }
        Arrival::Dark => {}
        Arrival::Incoming(incoming) => {
            incoming_light(&mut node, surface, &incoming, highlight, shadow)
        }
    }
    node
}

/// A point or spot light that reaches the point: n·l, its terms, and
/// whether the shadow ray (if any) lets it through.
fn incoming_light(
    node: &mut LightNode,
    surface: &Surface,
    incoming: &Incoming,
    highlight: HighlightTerm,
    shadow: ShadowQuery,
) {
    let n_dot_l = surface.normal.dot(incoming.direction);
    node.direction = Some(rgb(incoming.direction));
    node.distance = Some(incoming.distance);
    node.n_dot_l = Some(n_dot_l);
    node.casts_shadows = Some(incoming.casts_shadows);
    if n_dot_l <= 0.0 {
        node.status = LightStatus::Behind;
        return;
    }
    let diffuse = lambert(surface, incoming);
    let shine = highlight(incoming);
    node.lambert = Some(rgb(diffuse));
    node.highlight = shine.map(rgb);
    let total = diffuse + shine.unwrap_or(Color::ZERO);
    if total == Color::ZERO {
        node.status = LightStatus::AddsNothing;
        return;
    }
    node.shadow_ray = if incoming.casts_shadows {
        shadow(incoming)
    } else {
        None
    };
    let blocked = node.shadow_ray.as_ref().is_some_and(|s| s.blocked);
    node.status = if blocked {
        LightStatus::Blocked
    } else {
        LightStatus::Free
    };
    node.adds = if blocked { [0.0; 3] } else { rgb(total) };
}

/// What this chapter's tracer does.
pub const TRACER: TracerInfo = TracerInfo {
    hits: true,
    lights: true,
    shadow_rays: false,
    max_depth: None,
    min_weight: None,
};

/// Chapter 3's tree: the primary ray, its closest hit, each light's
/// Lambert term, and the colour the chapter's `trace` returns.
pub fn explain(scene: &Scene, pixel: Pixel) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let mut node = ray_node(RayKind::Primary, 0, &ray);
    let color = trace(scene, &ray);
    node.color = Some(rgb(color));
    let Some(hit) = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY) else {
        node.end = Some(End::NoHit);
        return (TRACER, node);
    };
    let surface = Surface::new(scene, hit, &ray);
    node.hit = Some(hit_node(scene, &hit, &ray));
    node.lights = light_nodes(scene, &surface, &|_| None, &mut |_| None);
    node.local = Some(rgb(color));
    (TRACER, node)
}
