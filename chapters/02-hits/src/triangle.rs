//! Watertight ray–triangle intersection.

use crate::Ray;
use crate::toolkit::Vec3;

/// Where the ray hits the triangle (a, b, c), as t and the barycentric
/// coordinates (α, β) of the hit point p = a + α(b − a) + β(c − a).
///
/// The lecture's inside test is 0 ≤ α, 0 ≤ β, α + β ≤ 1. Written with the
/// three weights (1 − α − β, α, β) of the corners, all three must be ≥ 0. We
/// compute those weights as the signed areas U, V, W of the triangles that the
/// ray makes with each edge ("edge functions", divided by their sum at the
/// end), in a frame where the ray runs along the z axis (Woop, Benthin and
/// Wald, "Watertight Ray/Triangle Intersection", JCGT 2013).
///
/// Why not the usual Möller–Trumbore test? It computes each edge test from
/// different intermediate values, so for a ray exactly through the edge shared
/// by two triangles, rounding can put the point outside both: a hole. Here the
/// test of an edge depends only on that edge's two corners and the ray, so both
/// triangles compute the same number with opposite signs, and a point on the
/// edge (value 0) counts as inside both. When a value is exactly 0 in f32 we
/// recompute it in f64, as the paper does, to decide its sign correctly.
pub fn intersect_triangle(
    [a, b, c]: [Vec3; 3],
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    let d = ray.direction;
    // Let z be the axis along which the ray travels fastest; x and y follow
    // it cyclically, swapped if needed so the triangle keeps its winding.
    let kz = d.abs().max_position();
    let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
    if d[kz] < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    // Shear so that the ray becomes the z axis from the origin.
    let (sx, sy, sz) = (d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
    let project = |p: Vec3| {
        let p = p - ray.origin;
        (p[kx] - sx * p[kz], p[ky] - sy * p[kz], sz * p[kz])
    };
    let (ax, ay, az) = project(a);
    let (bx, by, bz) = project(b);
    let (cx, cy, cz) = project(c);
    // Edge functions: twice the signed area seen from the ray.
    let mut u = edge(cx, cy, bx, by);
    let mut v = edge(ax, ay, cx, cy);
    let mut w = edge(bx, by, ax, ay);
    if u == 0.0 || v == 0.0 || w == 0.0 {
        u = edge_f64(cx, cy, bx, by);
        v = edge_f64(ax, ay, cx, cy);
        w = edge_f64(bx, by, ax, ay);
    }
    // Inside when all three have the same sign (either winding: two-sided).
    let outside = (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0);
    let determinant = u + v + w;
    if outside || determinant == 0.0 {
        return None; // a miss, or a ray in the triangle's plane
    }
    let t = (u * az + v * bz + w * cz) / determinant;
    let inside = t.is_finite() && t > t_min && t < t_max;
    inside.then(|| (t, v / determinant, w / determinant))
}

/// px·qy − py·qx, the edge function of the edge from p to q at the origin.
fn edge(px: f32, py: f32, qx: f32, qy: f32) -> f32 {
    px * qy - py * qx
}

/// The same in f64, for values too close to zero to trust their f32 sign.
fn edge_f64(px: f32, py: f32, qx: f32, qy: f32) -> f32 {
    (px as f64 * qy as f64 - py as f64 * qx as f64) as f32
}

/// The triangle's unit normal (b − a) × (c − a): counter-clockwise corners,
/// seen from the front, turn around it.
pub fn triangle_normal([a, b, c]: [Vec3; 3]) -> Vec3 {
    (b - a).cross(c - a).normalize()
}

/// The barycentric coordinates (α, β) of the point where the ray meets the
/// plane of the triangle (b − a, c − a), as the watertight test computes
/// them; (0, 0) if the ray runs in the triangle's plane.
pub fn barycentrics(vertices: [Vec3; 3], ray: &Ray) -> (f32, f32) {
    intersect_triangle(vertices, ray, f32::NEG_INFINITY, f32::INFINITY)
        .map_or((0.0, 0.0), |(_, alpha, beta)| (alpha, beta))
}

/// The point of the triangle with barycentric coordinates (α, β):
/// (1 − α − β)·a + α·b + β·c.
///
/// Why not r0 + t·rd? That point carries the rounding error of t, which
/// grows with the distance travelled, in every direction, off the plane too.
/// A weighted mean of the corners is off the triangle's plane by at most a
/// few units in the last place of the corners' coordinates, however thin the
/// triangle (pbrt computes its hit points the same way), and chapter 4
/// relies on that bound.
pub fn triangle_point([a, b, c]: [Vec3; 3], (alpha, beta): (f32, f32)) -> Vec3 {
    (1.0 - alpha - beta) * a + alpha * b + beta * c
}

/// The shading normal of a smooth triangle at barycentric coordinates
/// (α, β): the corner normals blended with the same weights,
/// (1 − α − β)·n_a + α·n_b + β·n_c, made unit length, and turned to the side
/// of the geometric normal so that front and back stay where the flat
/// triangle has them.
pub fn smooth_normal(normals: [Vec3; 3], (alpha, beta): (f32, f32), geometric: Vec3) -> Vec3 {
    let [na, nb, nc] = normals;
    let blend = (1.0 - alpha - beta) * na + alpha * nb + beta * nc;
    let n = blend.normalize_or(geometric);
    if n.dot(geometric) < 0.0 { -n } else { n }
}
