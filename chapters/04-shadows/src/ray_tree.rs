//! Chapter 4's ray tree (`--pixel X,Y`): chapter 3's tree with the shadow
//! ray of each light, free or blocked by which object. The chapter's own
//! `shade` runs against a recorder standing in for its world.

pub use ch03_lambert::ray_tree::{hit_node, light_nodes, primary_ray};

use crate::toolkit::{Scene, Stats, scene::Object};
use crate::workbench::cli::Pixel;
use crate::workbench::ray_tree::record::{Log, Recorder, ShadowQuery, primary_node};
use crate::workbench::ray_tree::{RayNode, ShadowNode, TracerInfo};
use crate::{Hit, Incoming, Ray, ShadowStart, Surface, World, intersect, lambert, shade, trace};

/// The recorder answers as the world it stands in for, and writes it down.
impl<W: World + ?Sized, S: Copy + Send> World for Recorder<'_, W, Hit, S> {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        self.record_closest(self.inner.closest_hit(ray, t_min, t_max))
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        let blocked = self.inner.any_hit(ray, t_min, t_max);
        let (origin, direction) = (ray.origin, ray.direction);
        let query = ShadowQuery::new(origin, direction, (t_min, t_max), blocked);
        self.record_shadow(query)
    }
}

/// The shadow ray among `shadows` that went towards `incoming`'s light,
/// and the nearest shadow-casting object on it by the chapter's `intersect`.
pub fn shadow_towards(
    objects: &[Object],
    shadows: &[ShadowQuery],
    incoming: &Incoming,
) -> Option<ShadowNode> {
    let shadow = ShadowQuery::towards(shadows, incoming.direction)?;
    let (origin, direction) = (shadow.origin, shadow.direction);
    let ray = Ray { origin, direction };
    Some(shadow.node_among(objects, |shape, t0, t1| intersect(shape, &ray, t0, t1)))
}

/// Chapter 4's tree: the primary ray, its closest hit, and for each light
/// its shadow ray (as the chapter's `shade` traces them, started as
/// `origin` says) and what it adds.
pub fn explain(scene: &Scene, pixel: Pixel, origin: ShadowStart) -> (TracerInfo, RayNode) {
    let ray = primary_ray(scene, pixel);
    let color = trace(scene, &ray, origin, &mut Stats::default());
    let hit = scene.objects[..].closest_hit(&ray, 0.0, f32::INFINITY);
    let mut node = primary_node(&ray, hit.map(|hit| hit_node(scene, &hit, &ray)), color);
    let Some(hit) = hit else {
        return (TracerInfo::SHADOW_RAYS, node);
    };
    let surface = Surface::new(scene, hit, &ray);
    let log = Log::<Hit, ()>::default();
    let (world, stats) = (log.recorder(&scene.objects[..]), &mut Stats::default());
    let local = shade(scene, &world, &surface, origin, stats, |l| {
        lambert(&surface, l)
    });
    let shadows = log.into_shadow_rays();
    let shadow = |incoming: &Incoming| shadow_towards(&scene.objects, &shadows, incoming);
    node.lights = light_nodes(scene, &surface, &|_| None, &shadow);
    node.local = Some(local.to_array());
    (TracerInfo::SHADOW_RAYS, node)
}
