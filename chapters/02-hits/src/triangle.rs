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
///
/// The paper's t, the edge functions' mean of the corners' z, is off by
/// rounding that follows the corners' distance from the ray's origin, not
/// the hit's: for a floor whose corners are 10⁶ away it is off by about
/// 0.1, and a shadow ray leaving the floor upwards finds the floor again
/// just ahead (the README, section *A floor as large as the world*). So
/// once the ray is known to pass through the triangle, t is worked out from
/// the triangle's plane in f64 ([`triangle_plane_t`]): exact to its
/// rounding to f32. As a bonus, two triangles in one plane get one t.
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
    let (sx, sy) = (d[kx] / d[kz], d[ky] / d[kz]);
    let project = |p: Vec3| {
        let p = p - ray.origin;
        (p[kx] - sx * p[kz], p[ky] - sy * p[kz])
    };
    let (x0, y0) = project(p0);
    let (x1, y1) = project(p1);
    let (x2, y2) = project(p2);
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
    let t = triangle_plane_t([p0, p1, p2], ray) as f32;
    let inside = t.is_finite() && t > t_min && t < t_max;
    inside.then(|| (t, v / determinant, w / determinant))
}

/// The distance t at which the ray meets the plane of the triangle
/// (p₀, p₁, p₂), worked out in f64: t = N·(p₀ − r0) / N·rd, with
/// N = e₁ × e₂ (not a number, or infinite, for a ray in or along the plane).
///
/// In f64 every product of two f32 inputs is exact, so N, p₀ − r0 and the
/// quotient are exact to about 10⁻¹⁶ of their size, and t to far below its
/// rounding to f32 unless the corners are some 10⁶ times farther from the
/// ray's origin than t (the bound of [`triangle_hit_point`] says by how much).
pub fn triangle_plane_t([p0, p1, p2]: [Vec3; 3], ray: &Ray) -> f64 {
    let [p0, p1, p2] = [p0, p1, p2].map(|p| p.as_dvec3());
    let origin = ray.origin.as_dvec3();
    let n = (p1 - p0).cross(p2 - p0);
    n.dot(p0 - origin) / n.dot(ray.direction.as_dvec3())
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

/// The point where `ray` meets the plane of the triangle (p₀, p₁, p₂), and
/// e, a bound on how far it lies off that plane: as accurate as the ray
/// allows, plus a term that grows with the corners' distance a million
/// times slower than the corners' own rounding.
///
/// Two ways to get the point, each with its bound:
/// * the barycentric mean [`triangle_point`] of the corners: off the plane
///   by a few units in the last place of the *corners'* coordinates, 8ε·|p|∞
///   with p the largest corner (pbrt, 4th ed., section 6.8.5, "Bounding
///   Intersection Point Error", bounds it so). A floor whose corners are 10⁶
///   away from the point seen gets a point up to 0.95 off the floor, and a
///   shadow ray offset as far.
/// * the ray's own r(t) = r0 + t·rd, with t from the plane in f64
///   ([`triangle_plane_t`]), which is exact to about 10⁻¹⁶ of its size, so the
///   point is off the plane by its rounding to f32, under ε·|r(t)|∞ (the
///   bound says 4ε·|r(t)|∞, as a sphere's does, so that chapter 4's offset
///   clears it with room), plus 64·ε₆₄·(|p₀ − r0|∞ + |r0|∞ + |t|) for the
///   f64 steps: its error follows the point, not the corners. The same section of pbrt re-projects a
///   computed point onto a sphere's surface for the same reason; Wächter and
///   Binder ("A Fast and Robust Method for Avoiding Self-Intersection", Ray
///   Tracing Gems, chapter 6, 2019) prefer the barycentric point to r(t)
///   only because r(t) from an f32 t carries t's error, which grows with
///   the distance travelled. Worked out again in f64, it does not.
///
/// The one with the smaller bound is returned (nearly always r(t); the
/// barycentric point for a ray in the triangle's plane, which has no t).
/// The README, section *A floor as large as the world*, shows the
/// difference on a picture.
pub fn triangle_hit_point(vertices: [Vec3; 3], weights: (f32, f32), ray: &Ray) -> (Vec3, f32) {
    let barycentric = triangle_point(vertices, weights);
    let largest = |p: Vec3| p.abs().max_element();
    let corners = vertices.iter().fold(0.0f32, |m, &v| m.max(largest(v)));
    let by_corners = (
        barycentric,
        8.0 * f32::EPSILON * corners.max(largest(barycentric)),
    );
    let t = triangle_plane_t(vertices, ray);
    if !t.is_finite() {
        return by_corners;
    }
    let (origin, direction) = (ray.origin.as_dvec3(), ray.direction.as_dvec3());
    let point = Vec3::from((origin + t * direction).as_vec3());
    let to_corner = (vertices[0].as_dvec3() - origin).abs().max_element();
    let f64_steps = to_corner + origin.abs().max_element() + t.abs();
    let error = 4.0 * f32::EPSILON * largest(point) + (64.0 * f64::EPSILON * f64_steps) as f32;
    if error < by_corners.1 {
        (point, error)
    } else {
        by_corners
    }
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
