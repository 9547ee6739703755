//! Where things go: each ray as a segment of the plane, the objects the
//! rays meet, and the frame that maps the plane onto the picture.

use ch00_toolkit::{Scene, Vec3};

use super::geometry::{Outline, P2, Plane, Section, bounds, clip, outline, section, size};
use super::{LINE, MARGIN, MAX_DRAWING_HEIGHT, WIDTH};
use crate::ray_tree::{Fold, RayNode};

/// One ray as drawn: its segment in the plane and how it ends.
pub(super) struct Drawn<'a> {
    pub(super) ray: &'a RayNode,
    pub(super) a: P2,
    pub(super) b: P2,
    pub(super) shown: bool,
    /// It hits nothing: an arrow, drawn a fixed length.
    pub(super) escapes: bool,
}

/// Every ray of the tree as a segment, depth first; those `fold` folds
/// (with every ray after them) are not `shown`. A ray that hits nothing is
/// drawn `reach` long, one that was not traced a quarter of that.
pub(super) fn segments<'a>(
    ray: &'a RayNode,
    plane: &Plane,
    fold: &Fold,
    reach: f32,
) -> Vec<Drawn<'a>> {
    let mut all = Vec::new();
    walk(ray, plane, fold, reach, true, &mut all);
    all
}

fn walk<'a>(
    ray: &'a RayNode,
    plane: &Plane,
    f: &Fold,
    reach: f32,
    up: bool,
    all: &mut Vec<Drawn<'a>>,
) {
    let shown = up && !f.folds(ray);
    let origin = Vec3::from_array(ray.origin);
    let dir = Vec3::from_array(ray.direction);
    let end = match (&ray.hit, ray.traced) {
        (Some(hit), _) => Vec3::from_array(hit.point),
        (None, true) => origin + reach * dir,
        (None, false) => origin + 0.25 * reach * dir,
    };
    all.push(Drawn {
        ray,
        a: plane.project(origin),
        b: plane.project(end),
        shown,
        escapes: ray.hit.is_none() && ray.traced,
    });
    for next in &ray.secondary {
        walk(next, plane, f, reach, shown, all);
    }
}

/// How far a ray that hits nothing is drawn: 0.3 of the extent of the
/// hits, at least a tenth of the primary ray's way to its hit (1 if it
/// hits nothing).
pub(super) fn reach(primary: &RayNode, plane: &Plane) -> f32 {
    let mut points = Vec::new();
    hits(primary, plane, &mut points);
    let (lo, hi) = bounds(&points);
    let least = primary.hit.as_ref().map_or(1.0, |h| 0.1 * h.t);
    (0.3 * size(lo, hi)).max(least)
}

fn hits(ray: &RayNode, plane: &Plane, points: &mut Vec<P2>) {
    if let Some(hit) = &ray.hit {
        points.push(plane.project(Vec3::from_array(hit.point)));
    }
    ray.secondary.iter().for_each(|r| hits(r, plane, points));
}

/// From the plane's coordinates to the picture's pixels.
pub(super) struct Frame {
    pub(super) lo: P2,
    pub(super) hi: P2,
    pub(super) scale: f32,
    pub(super) left: f32,
    pub(super) top: f32,
    pub(super) height: f32,
    /// Is the eye in the picture? Not when it is far from what the rays
    /// do after the primary ray's hit: the primary ray then comes in from
    /// the left edge, so that the rest is drawn large.
    pub(super) eye_in: bool,
}

impl Frame {
    /// The frame that holds the shown rays and the circles no larger than
    /// them, with a margin.
    pub(super) fn fit(rays: &[Drawn], sections: &[Met]) -> Frame {
        let primary = &rays[0];
        let mut points: Vec<P2> = rays[1..]
            .iter()
            .filter(|d| d.shown)
            .flat_map(|d| [d.a, d.b])
            .chain([primary.b])
            .collect();
        let (lo, hi) = bounds(&points);
        let rest = size(lo, hi);
        let eye_in = rest < 1e-3 || primary.b[0] - primary.a[0] < 1.2 * rest;
        points.push(match eye_in {
            true => primary.a,
            false => [primary.b[0] - 0.4 * rest, primary.b[1]],
        });
        let largest = size(lo, hi).max(1e-3);
        for met in sections {
            if let Some(Section::Circle { center, radius }) = met.section
                && radius <= largest
            {
                points.push([center[0] - radius, center[1] - radius]);
                points.push([center[0] + radius, center[1] + radius]);
            }
        }
        let (lo, hi) = bounds(&points);
        let pad = 0.06 * size(lo, hi).max(1e-3);
        // At least a third as high as wide, so that a flat tree has room for its labels.
        let grow = ((hi[0] - lo[0]) / 3.0 - (hi[1] - lo[1])).max(0.0) / 2.0;
        let (lo, hi) = (
            [lo[0] - pad, lo[1] - pad - grow],
            [hi[0] + pad, hi[1] + pad + grow],
        );
        let width = WIDTH - 2.0 * MARGIN;
        let scale = (width / (hi[0] - lo[0])).min(MAX_DRAWING_HEIGHT / (hi[1] - lo[1]));
        let used = scale * (hi[0] - lo[0]);
        Frame {
            lo,
            hi,
            scale,
            left: MARGIN + (width - used) / 2.0,
            top: MARGIN + LINE,
            height: scale * (hi[1] - lo[1]),
            eye_in,
        }
    }

    /// The part of the segment from `a` to `b` (in pixels) inside the drawing.
    pub(super) fn visible(&self, a: P2, b: P2) -> Option<(P2, P2)> {
        clip(
            a,
            b,
            [MARGIN, self.top],
            [WIDTH - MARGIN, self.top + self.height],
        )
    }

    pub(super) fn px(&self, p: P2) -> P2 {
        [
            self.left + (p[0] - self.lo[0]) * self.scale,
            self.top + (self.hi[1] - p[1]) * self.scale,
        ]
    }
}

/// An object the rays meet, where the plane cuts it, and its outline
/// seen along the plane's normal where that tells more.
pub(super) struct Met {
    pub(super) object: usize,
    pub(super) name: String,
    pub(super) section: Option<Section>,
    pub(super) outline: Option<Outline>,
}

/// The objects the rays hit, in the order they are first met.
pub(super) fn objects_met(rays: &[Drawn], scene: &Scene, plane: &Plane) -> Vec<Met> {
    let mut met: Vec<Met> = Vec::new();
    for hit in rays.iter().filter_map(|d| d.ray.hit.as_ref()) {
        if met.iter().any(|m| m.object == hit.object) {
            continue;
        }
        let Some(shape) = scene.objects.get(hit.object).map(|o| &o.shape) else {
            continue;
        };
        let cut = section(plane, shape);
        met.push(Met {
            object: hit.object,
            name: format!("object {} ({}, {})", hit.object, hit.shape, hit.material),
            outline: outline(plane, shape, cut.as_ref()),
            section: cut,
        });
    }
    met
}
