//! Ray–triangle intersection: the lecture's method (the plane, then the
//! barycentric coordinates), and the watertight test, which the tracer uses.
//!
//! Letters as in the README: the corners are p₀, p₁, p₂, the edges from p₀
//! are e₁ = p₁ − p₀ and e₂ = p₂ − p₀, and a point of the triangle's plane is
//! x = p₀ + α·e₁ + β·e₂.

use crate::Ray;
use crate::intersect_plane;
use crate::toolkit::Vec3;

/// Where the ray hits the triangle (p₀, p₁, p₂): `Some((t, α, β))`, with t
/// the distance along the ray and (α, β) the barycentric coordinates of the
/// hit point. The lecture's method in two steps, the triangle's plane and
/// then α and β, derived in the README, section *The lecture's method: the
/// plane, then α and β*.
///
/// * The edges from p₀ are e₁ = p₁ − p₀ and e₂ = p₂ − p₀, and (α, β) are the
///   hit point x's coordinates along them: x = p₀ + α·e₁ + β·e₂. So α is
///   p₁'s weight, β is p₂'s, and 1 − α − β is p₀'s.
/// * t obeys the plane's rules ([`intersect_plane`]): finite and strictly
///   between `t_min` and `t_max`, and `None` for a ray parallel to the
///   triangle's plane, in it or beside it.
/// * The point counts when it is inside the triangle or on its border:
///   0 ≤ α, 0 ≤ β and α + β ≤ 1, equalities included, so points exactly on
///   an edge or a corner are hits. Otherwise `None`.
/// * Both sides count: a ray that meets the triangle from its back is a hit
///   as much as one that meets it from its front.
///
/// Right on paper; but two triangles that share an edge decide a ray through
/// it with different numbers, and rounding can make both say "outside". The
/// tracer uses [`intersect_triangle`], which cannot.
pub fn triangle_by_plane(
    [p0, p1, p2]: [Vec3; 3],
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<(f32, f32, f32)> {
    // EXERCISE(ch02-triangle): the lecture's two steps: where the ray meets the plane through the three corners (in (t_min, t_max)), then the hit point's barycentric coordinates (α, β); a hit only if 0 ≤ α, 0 ≤ β and α + β ≤ 1
    crate::workbench::exercise::solution_begins("ch02-triangle");
    let (e1, e2) = (p1 - p0, p2 - p0);
    let area_normal = e1.cross(e2); // N
    let (n, twice_area) = (area_normal.normalize(), area_normal.length());
    let t = intersect_plane(n, -n.dot(p0), ray, t_min, t_max)?;
    let w = ray.at(t) - p0;
    let alpha = w.cross(e2).dot(n) / twice_area;
    let beta = e1.cross(w).dot(n) / twice_area;
    (alpha >= 0.0 && beta >= 0.0 && alpha + beta <= 1.0).then_some((t, alpha, beta))
    // END EXERCISE
}

/// Where the ray hits the triangle (p₀, p₁, p₂), as t and the barycentric
/// coordinates (α, β) of the hit point x = p₀ + α·e₁ + β·e₂: watertight.
///
/// The inside test is the lecture's 0 ≤ α, 0 ≤ β, α + β ≤ 1. Written with
/// the three weights (1 − α − β, α, β) of the corners, all three must be
/// ≥ 0. We compute those weights as the signed areas U, V, W of the triangles
/// that the ray makes with each edge ("edge functions", divided by their sum
/// at the end), in a frame where the ray runs along the z axis (Woop, Benthin
/// and Wald, "Watertight Ray/Triangle Intersection", JCGT 2013).
///
/// Why not [`triangle_by_plane`], or the usual Möller–Trumbore test? Each
/// computes the test of an edge from numbers that depend on the whole
/// triangle (its plane, its normal, one corner), so for a ray exactly
/// through the edge shared by two triangles, rounding can put the point
/// outside both: a hole. Here the test of an edge depends only on that
/// edge's two corners and the ray, so both triangles compute the same number
/// with opposite signs, and a point on the edge (value 0) counts as inside
/// both. When a value is exactly 0 in f32 we recompute it in f64, as the
/// paper does, to decide its sign correctly.
pub fn intersect_triangle(
    [p0, p1, p2]: [Vec3; 3],
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
    let (x0, y0, z0) = project(p0);
    let (x1, y1, z1) = project(p1);
    let (x2, y2, z2) = project(p2);
    // Edge functions: twice the signed area seen from the ray.
    let mut u = edge(x2, y2, x1, y1);
    let mut v = edge(x0, y0, x2, y2);
    let mut w = edge(x1, y1, x0, y0);
    if u == 0.0 || v == 0.0 || w == 0.0 {
        u = edge_f64(x2, y2, x1, y1);
        v = edge_f64(x0, y0, x2, y2);
        w = edge_f64(x1, y1, x0, y0);
    }
    // Inside when all three have the same sign (either winding: two-sided).
    let outside = (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0);
    let determinant = u + v + w;
    if outside || determinant == 0.0 {
        return None; // a miss, or a ray in the triangle's plane
    }
    let t = (u * z0 + v * z1 + w * z2) / determinant;
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

/// The triangle's unit normal along e₁ × e₂ = (p₁ − p₀) × (p₂ − p₀):
/// counter-clockwise corners, seen from the front, turn around it.
pub fn triangle_normal([p0, p1, p2]: [Vec3; 3]) -> Vec3 {
    (p1 - p0).cross(p2 - p0).normalize()
}

/// The barycentric coordinates (α, β) of the point where the ray meets the
/// plane of the triangle (p₀, p₁, p₂), as the watertight test computes
/// them; (0, 0) if the ray runs in the triangle's plane.
pub fn barycentrics(vertices: [Vec3; 3], ray: &Ray) -> (f32, f32) {
    intersect_triangle(vertices, ray, f32::NEG_INFINITY, f32::INFINITY)
        .map_or((0.0, 0.0), |(_, alpha, beta)| (alpha, beta))
}

/// The point of the triangle with barycentric coordinates (α, β):
/// (1 − α − β)·p₀ + α·p₁ + β·p₂.
///
/// Why not the ray's point r(t)? That point carries the rounding error of t,
/// which grows with the distance travelled, in every direction, off the
/// plane too.
/// A weighted mean of the corners is off the triangle's plane by at most a
/// few units in the last place of the corners' coordinates, however thin the
/// triangle (pbrt computes its hit points the same way), and chapter 4
/// relies on that bound.
pub fn triangle_point([p0, p1, p2]: [Vec3; 3], (alpha, beta): (f32, f32)) -> Vec3 {
    (1.0 - alpha - beta) * p0 + alpha * p1 + beta * p2
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
