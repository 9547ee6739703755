//! Ray–cone intersection: a bonus primitive beyond the lecture's three, for
//! the SPD scenes (`rings` and `tree` are built of cylinders and cones).
//!
//! The cone runs along its axis from `base` (radius r_b) to `apex` (radius
//! r_a), both radii ≥ 0: a cylinder when they are equal, a pointed cone when
//! one is 0, and no end caps. The ray is r(t) = r0 + t·rd, as for the
//! sphere; a, b, c are this quadratic's coefficients.

use crate::Ray;
use crate::toolkit::{DVec3, Vec3};

/// The cone's axis in f64: the base, the unit vector w from base to apex,
/// the height h, and the slope k = (r_a − r_b)/h (how much the radius grows
/// per unit along the axis).
struct Axis {
    base: DVec3,
    w: DVec3,
    height: f64,
    base_radius: f64,
    slope: f64,
}

impl Axis {
    fn new(base: Vec3, base_radius: f32, apex: Vec3, apex_radius: f32) -> Axis {
        let (base, axis) = (base.as_dvec3(), apex.as_dvec3() - base.as_dvec3());
        let height = axis.length();
        let (base_radius, apex_radius) = (f64::from(base_radius), f64::from(apex_radius));
        Axis {
            base,
            w: axis / height,
            height,
            base_radius,
            slope: (apex_radius - base_radius) / height,
        }
    }

    /// r(s) = r_b + k·s, the radius at s along the axis.
    fn radius(&self, s: f64) -> f64 {
        self.base_radius + self.slope * s
    }
}

/// The nearest distance in (t_min, t_max) at which the ray hits the cone's
/// side between its two end circles.
///
/// A point x has s = (x − base)·w along the axis and lies on the cone when
/// 0 ≤ s ≤ h and its distance from the axis is the radius there:
///
/// |x − base − s·w|² = r(s)²,   r(s) = r_b + k·s,   k = (r_a − r_b)/h.
///
/// Split every vector v into its part along the axis, v·w, and its part
/// across it, v⊥ = v − (v·w)·w. Put in x = r(t) and write f = r0 − base:
/// across the axis the point is f⊥ + t·rd⊥, along it s(t) = f·w + t·(rd·w),
/// so the radius there is r(s(t)) = ρ + t·m with ρ = r(f·w) (the radius
/// level with the ray's origin) and m = k·(rd·w). Squaring both sides:
///
/// |f⊥ + t·rd⊥|² = (ρ + t·m)²
/// a·t² + b·t + c = 0   with   a = rd⊥·rd⊥ − m²,  b = 2 (f⊥·rd⊥ − ρ·m),  c = f⊥·f⊥ − ρ².
///
/// It is solved as [`sphere_roots`](crate::sphere_roots) does, in f64:
/// q = −(b + sign(b)·√Δ)/2 with Δ = b² − 4ac, roots c/q and q/a. Of the
/// roots in (t_min, t_max), the nearer one whose s(t) lies in [0, h] is the
/// hit (the other one may be beyond an open end, or on the mirror cone past
/// a pointed apex, where r(s) < 0: both have s outside [0, h]).
///
/// A ray parallel to a cylinder's axis has rd⊥ = 0 and m = 0, so a = b = 0:
/// it never crosses the side. Nearly parallel, a → 0 and the stable form
/// keeps the near root c/q exact while q/a runs off to infinity (the line
/// meets the side very far away). Roots that are not finite are dropped, so
/// no NaN comes out.
pub fn intersect_cone(
    base: Vec3,
    base_radius: f32,
    apex: Vec3,
    apex_radius: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    let axis = Axis::new(base, base_radius, apex, apex_radius);
    let (f, rd) = (ray.origin.as_dvec3() - axis.base, ray.direction.as_dvec3());
    let (f_w, rd_w) = (f.dot(axis.w), rd.dot(axis.w));
    let (f_across, rd_across) = (f - f_w * axis.w, rd - rd_w * axis.w);
    let (rho, m) = (axis.radius(f_w), axis.slope * rd_w);
    let a = rd_across.dot(rd_across) - m * m;
    let b = 2.0 * (f_across.dot(rd_across) - rho * m);
    let c = f_across.dot(f_across) - rho * rho;
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return None;
    }
    let q = -(b + discriminant.sqrt().copysign(b)) / 2.0;
    let (t0, t1) = (c / q, q / a);
    let within = |t: f64| {
        let s = f_w + t * rd_w;
        t.is_finite() && t as f32 > t_min && (t as f32) < t_max && (0.0..=axis.height).contains(&s)
    };
    [t0.min(t1), t0.max(t1)]
        .into_iter()
        .find(|&t| within(t))
        .map(|t| t as f32)
}

/// The point of the cone hit at distance t, put back onto the surface, and
/// the cone's outward unit normal there.
///
/// The point r0 + t·rd has s = (x − base)·w along the axis and the unit
/// direction d̂ from the axis towards it; the point of the surface there is
/// base + s·w + r(s)·d̂ (as [`sphere_point`](crate::sphere_point) projects
/// onto the sphere). Along the surface, one step of h up the axis moves
/// r_a − r_b outwards: the side's direction is h·w + (r_a − r_b)·d̂. The
/// normal is d̂ tilted back along the axis,
///
/// n = normalize(d̂ + (r_b − r_a)/h · w),
///
/// perpendicular to that direction (the dot product is
/// h(r_b − r_a)/h + (r_a − r_b) = 0) and to the circle's w × d̂; for a
/// cylinder n = d̂. Computed in f64, so the f32 point is off the surface by
/// its own rounding only.
pub fn cone_point(
    base: Vec3,
    base_radius: f32,
    apex: Vec3,
    apex_radius: f32,
    ray: &Ray,
    t: f32,
) -> (Vec3, Vec3) {
    let axis = Axis::new(base, base_radius, apex, apex_radius);
    let v = ray.origin.as_dvec3() + f64::from(t) * ray.direction.as_dvec3() - axis.base;
    let s = v.dot(axis.w);
    // On the axis (only at a pointed apex) any direction across it will do.
    let across = (v - s * axis.w)
        .try_normalize()
        .unwrap_or_else(|| axis.w.any_orthonormal_vector());
    let s = s.clamp(0.0, axis.height);
    let point = axis.base + s * axis.w + axis.radius(s) * across;
    let normal = (across - axis.slope * axis.w).normalize();
    (point.as_vec3().into(), normal.as_vec3().into())
}
