//! A small scene's shadow rays that leave a triangle: its own packet's test
//! is skipped where no triangle of the packet can be ahead of the ray.
//!
//! A shadow ray starts a hair off the surface it leaves (chapter 4's
//! offset, a few ε of the point's size), while the box around a small
//! scene's packet of triangles is padded a little more (chapter 8's 2⁻²⁰ of
//! its size). So the box never rules out the packet the ray leaves, and
//! its whole four-lane test ran only to find the plane behind the ray: in
//! tinyraytracer's scene, most shadow rays leave the board, a rectangle of
//! two triangles. Here one sign test per triangle, chapter 2's own
//! numbers, answers that first.

use arrayvec::ArrayVec;

use crate::toolkit::scene::{Object, Shape};
use crate::toolkit::{DVec3, Vec3};
use crate::tracer::Ray;

/// The planes of a packet's triangles, as chapter 2's `triangle_plane_t`
/// works them out: a corner p₀ and the normal N = (p₁ − p₀) × (p₂ − p₀),
/// in f64.
#[derive(Debug, Clone)]
pub struct Planes {
    lanes: ArrayVec<(DVec3, DVec3), 4>,
}

impl Planes {
    /// The planes of the triangles `objects` (indices in the scene's
    /// `scene` objects); `None` if one of them is not a triangle.
    pub fn of(scene: &[Object], objects: impl Iterator<Item = u32>) -> Option<Planes> {
        let mut lanes = ArrayVec::new();
        for object in objects {
            let corners = match scene[object as usize].shape {
                Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => vertices,
                _ => return None,
            };
            lanes.push(plane(corners));
        }
        Some(Planes { lanes })
    }

    /// Is every triangle's plane at or behind the ray's origin, so that
    /// chapter 2's test finds no hit beyond `t_min` ≥ 0 in any of them?
    ///
    /// Chapter 2's t is (N·(p₀ − r0)) / (N·rd) in f64, rounded to f32, and
    /// a hit needs t > t_min ≥ 0, so t > 0: a numerator and a denominator
    /// both nonzero and of one sign (rounding keeps a quotient's sign, and
    /// a NaN or an infinite t is no hit either). Both are worked out here
    /// with chapter 2's own operations, so they are its numbers to the
    /// last bit; where their signs differ, or one is 0 or NaN, the
    /// triangle answers "no hit", whatever its edges say.
    #[inline(always)]
    pub fn all_behind(&self, ray: &Ray, t_min: f32) -> bool {
        if t_min.is_nan() || t_min < 0.0 {
            return false; // the sign test holds for t_min ≥ 0 only
        }
        let (origin, direction) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
        self.lanes.iter().all(|&(corner, normal)| {
            let (distance, speed) = (normal.dot(corner - origin), normal.dot(direction));
            let ahead = (distance > 0.0 && speed > 0.0) || (distance < 0.0 && speed < 0.0);
            !ahead
        })
    }
}

/// A triangle's p₀ and N, as chapter 2's `triangle_plane_t` computes them.
fn plane([p0, p1, p2]: [Vec3; 3]) -> (DVec3, DVec3) {
    let [p0, p1, p2] = [p0, p1, p2].map(|p| p.as_dvec3());
    (p0, (p1 - p0).cross(p2 - p0))
}
