//! Axis-aligned bounding boxes and the slab test.

use crate::toolkit::Vec3;
use crate::toolkit::scene::Shape;

/// An axis-aligned box: the points x with min ≤ x ≤ max in every coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

/// 1 + 2γ₃, with γₙ = n·u / (1 − n·u) and u = 2⁻²⁴ the unit roundoff of
/// f32: the factor that makes the slab test's far distance an upper bound
/// of the exact one despite rounding (Ize, "Robust BVH Ray Traversal",
/// JCGT 2013; pbrt-v4's `Bounds3::IntersectP`).
const ROBUST_FAR: f32 = 1.0 + 2.0 * (3.0 * f32::EPSILON / 2.0) / (1.0 - 3.0 * f32::EPSILON / 2.0);

impl Aabb {
    /// The empty box: the union with it changes nothing.
    pub const EMPTY: Aabb = Aabb {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    /// The smallest box holding both.
    pub fn union(self, other: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The smallest box holding this one and the point p.
    pub fn grow(self, p: Vec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The centre of the box.
    pub fn center(&self) -> Vec3 {
        (self.min + self.max) / 2.0
    }

    /// Half the surface area, dx·dy + dy·dz + dz·dx: proportional to the
    /// chance that a random ray crossing the parent box also crosses this one.
    pub fn half_area(&self) -> f32 {
        let d = (self.max - self.min).max(Vec3::ZERO);
        d.x * d.y + d.y * d.z + d.z * d.x
    }

    /// The box a little larger on every side: by 2⁻²⁰ of its coordinates'
    /// magnitude and of its size, so that a primitive's own rounding (a
    /// sphere's c ± r, a hit exactly on a triangle's edge) never puts a hit
    /// outside its box.
    pub fn padded(self) -> Aabb {
        let scale =
            self.min.abs().max(self.max.abs()).max_element() + (self.max - self.min).max_element();
        let pad = Vec3::splat(scale * (1.0 / 1_048_576.0) + f32::MIN_POSITIVE);
        Aabb {
            min: self.min - pad,
            max: self.max + pad,
        }
    }

    /// The slab test: where the ray r0 + t·rd enters the box, if it meets it
    /// for some t in [t_min, t_max]. `inverse` is 1/rd per coordinate.
    ///
    /// Each pair of parallel faces (a slab) is crossed between
    /// t = (min − r0)/rd and t = (max − r0)/rd, in either order. The ray is
    /// in the box where it is in all three slabs: from the largest entry to
    /// the smallest exit. It meets the box when that interval is not empty.
    /// A ray parallel to a slab has 1/rd = ±∞ and gets the interval
    /// (−∞, ∞) when it runs strictly inside the slab, an empty one when
    /// strictly outside. On a face's plane 0·∞ is NaN, and the comparisons
    /// make that a miss on a min face, a hit on a max face: harmless, since
    /// boxes are `padded` beyond their objects (the chapter's text, *The
    /// slab test*).
    pub fn entry(&self, origin: Vec3, inverse: Vec3, t_min: f32, t_max: f32) -> Option<f32> {
        let t0 = (self.min - origin) * inverse;
        let t1 = (self.max - origin) * inverse;
        let near = t0.min(t1).max_element().max(t_min);
        let far = (t0.max(t1).min_element() * ROBUST_FAR).min(t_max);
        (near <= far).then_some(near)
    }
}

/// The box around a shape, slightly padded; `None` for a plane, which is
/// unbounded.
pub fn bounds(shape: &Shape) -> Option<Aabb> {
    let exact = match *shape {
        Shape::Sphere { center, radius } => Aabb {
            min: center - Vec3::splat(radius),
            max: center + Vec3::splat(radius),
        },
        Shape::Plane { .. } => return None,
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            vertices.iter().fold(Aabb::EMPTY, |b, &v| b.grow(v))
        }
        Shape::Cone {
            base,
            base_radius,
            apex,
            apex_radius,
            ..
        } => {
            let axis = apex - base;
            disk(base, axis, base_radius).union(disk(apex, axis, apex_radius))
        }
    };
    Some(exact.padded())
}

/// The box around a disk of centre c, radius r and axis along `axis`
/// (an end of a cone; the cone's side lies between its end disks, so the
/// box of both bounds it).
///
/// With w the unit axis, the disk's points are c + r·u for unit vectors u
/// perpendicular to w. Along coordinate i they reach farthest where u leans
/// most along e_i: u is e_i's part across w, e_i − w_i·w, normalised, whose
/// i-th coordinate is 1 − w_i² over its length √(1 − w_i²). So the extent
/// is r·√(1 − w_i²): 0 along the axis of a disk facing e_i, r across it.
/// 1 − w_i² is computed as (w_j² + w_k²), the other two coordinates, which
/// does not cancel for an axis close to e_i as 1 − w_i² does in f32.
fn disk(center: Vec3, axis: Vec3, radius: f32) -> Aabb {
    let w = axis / axis.length();
    let sq = w * w;
    let across = Vec3::new(sq.y + sq.z, sq.z + sq.x, sq.x + sq.y);
    let extent = radius * across.sqrt();
    Aabb {
        min: center - extent,
        max: center + extent,
    }
}
