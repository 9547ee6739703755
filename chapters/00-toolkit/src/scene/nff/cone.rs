//! NFF cones and cylinders (`c`) as smooth triangles.
//!
//! raybook's lecture has three primitives, sphere, plane and triangle, so a
//! cone becomes a band of triangles around its axis that shade with the
//! exact normals of the cone at their corners ([`Shape::SmoothTriangle`]):
//! the shading is as smooth as a true cone's, and only the silhouette is a
//! polygon.

use std::f32::consts::TAU;

use glam::Vec3;

use crate::scene::Shape;

/// Corners around the axis. The widest cone of the SPD scenes, the trunk of
/// `tree`, is 37 pixels in radius at 1024×1024; with 32 corners its outline
/// comes within r·(1 − cos(π/32)) = 0.005·r, a fifth of a pixel, of the
/// circle. More would only slow the render (rings and tree have 4000 cones each).
pub const SEGMENTS: usize = 32;

/// One end of a cone: the centre of its circle and its radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct End {
    pub center: Vec3,
    pub radius: f32,
}

/// The side of the cone from `base` to `apex` (no end caps), as triangles
/// counter-clockwise seen from outside, or from inside if `inside`.
///
/// With w the unit axis from base to apex (height h), u and v unit vectors
/// perpendicular to it and each other, and the direction
/// d(θ) = u cos θ + v sin θ, the corner at angle θᵢ = 2πi / [`SEGMENTS`] is
/// base.center + r_base d(θᵢ) on the base's circle and apex.center + r_apex
/// d(θᵢ) on the apex's. Each of the segments between θᵢ and θᵢ₊₁ is a quad
/// of two triangles, or one where an end has radius 0 (a pointed cone).
///
/// The outward normal at angle θ is d(θ) tilted along the axis,
/// n = normalize(d(θ) + (r_base − r_apex)/h · w): it is perpendicular to the
/// side's direction h·w + (r_apex − r_base)·d(θ) (their dot product is
/// h(r_apex − r_base) + (r_base − r_apex)h = 0), and is d(θ) itself for a
/// cylinder. The point of a pointed cone has no normal of its own; its
/// triangle takes the normal at the middle of its segment, θᵢ + π/N.
pub(super) fn tessellate(base: End, apex: End, inside: bool) -> Vec<Shape> {
    let axis = apex.center - base.center;
    let height = axis.length();
    let w = axis / height;
    let u = w.any_orthonormal_vector();
    let v = w.cross(u); // (u, v, w) right-handed, so θ turns counter-clockwise about w
    let tilt = (base.radius - apex.radius) / height * w;
    let direction = |theta: f32| u * theta.cos() + v * theta.sin();
    let normal = |theta: f32| (direction(theta) + tilt).normalize();
    let corner = |end: End, theta: f32| end.center + end.radius * direction(theta);
    let mut triangles = Vec::with_capacity(2 * SEGMENTS);
    for i in 0..SEGMENTS {
        let [t0, t1] = [i, i + 1].map(|i| TAU * i as f32 / SEGMENTS as f32);
        let middle = (t0 + t1) / 2.0;
        if base.radius > 0.0 {
            let at_apex = if apex.radius > 0.0 { t1 } else { middle };
            triangles.push(smooth(
                [corner(base, t0), corner(base, t1), corner(apex, t1)],
                [normal(t0), normal(t1), normal(at_apex)],
                inside,
            ));
        }
        if apex.radius > 0.0 {
            let at_base = if base.radius > 0.0 { t0 } else { middle };
            triangles.push(smooth(
                [corner(base, t0), corner(apex, t1), corner(apex, t0)],
                [normal(at_base), normal(t1), normal(t0)],
                inside,
            ));
        }
    }
    triangles
}

/// A smooth triangle, turned to face the other way if `inside`: the corners
/// in reverse order (so the geometric normal flips too) and the normals negated.
fn smooth(vertices: [Vec3; 3], normals: [Vec3; 3], inside: bool) -> Shape {
    match inside {
        false => Shape::SmoothTriangle { vertices, normals },
        true => {
            let [a, b, c] = vertices;
            let [na, nb, nc] = normals;
            Shape::SmoothTriangle {
                vertices: [a, c, b],
                normals: [-na, -nc, -nb],
            }
        }
    }
}
