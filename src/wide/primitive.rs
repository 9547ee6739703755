//! What the wide BVH keeps of each object, and the ray prepared once for the
//! many tests it will meet.

use std::cell::OnceCell;

use glam::{Mat3A, Vec3A};

use crate::toolkit::Vec3;
use crate::toolkit::scene::Shape;
use crate::tracer::{Ray, intersect_cone, intersect_sphere};

/// An object's geometry as intersection needs it: a sphere, a triangle's
/// corners (a smooth triangle's normals matter only once the hit is chosen,
/// and are read from the scene then), or a cone's ends (whether it is inside
/// out matters only for the normal).
#[derive(Debug, Clone, Copy)]
pub enum Geometry {
    Sphere {
        center: Vec3,
        radius: f32,
    },
    Triangle {
        vertices: [Vec3; 3],
    },
    Cone {
        base: Vec3,
        base_radius: f32,
        apex: Vec3,
        apex_radius: f32,
    },
}

/// A bounded object, stored in the order of the tree's leaves: 48 bytes.
#[derive(Debug, Clone, Copy)]
pub struct Primitive {
    pub geometry: Geometry,
    /// Index in the scene's objects.
    pub object: u32,
    /// Does it block shadow rays?
    pub shadows: bool,
}

// The size the docs and the README's table of bytes per object give.
const _: () = assert!(std::mem::size_of::<Primitive>() == 48);

impl Primitive {
    /// The primitive of a bounded shape; `None` for a plane.
    pub fn of(shape: &Shape, object: usize, shadows: bool) -> Option<Primitive> {
        let geometry = match *shape {
            Shape::Sphere { center, radius } => Geometry::Sphere { center, radius },
            Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
                Geometry::Triangle { vertices }
            }
            Shape::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
                ..
            } => Geometry::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
            },
            Shape::Plane { .. } => return None,
        };
        let object = u32::try_from(object).expect("fewer than 2³² objects");
        Some(Primitive {
            geometry,
            object,
            shadows,
        })
    }

    /// Where the ray meets it in (t_min, t_max): chapter 2's `intersect`, to
    /// the last bit, with the triangle test's per-ray work done once; with
    /// a triangle's barycentric weights, which chapter 2 works out again.
    #[inline(always)]
    pub fn intersect(&self, ray: &PreparedRay, t_min: f32, t_max: f32) -> Option<(f32, Weights)> {
        match self.geometry {
            Geometry::Sphere { center, radius } => {
                let t = intersect_sphere_quickly(center, radius, &ray.ray, t_min, t_max)?;
                Some((t, Weights::NONE))
            }
            Geometry::Triangle { vertices } => ray.shear().intersect(vertices, t_min, t_max),
            Geometry::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
            } => {
                let t =
                    intersect_cone(base, base_radius, apex, apex_radius, &ray.ray, t_min, t_max)?;
                Some((t, Weights::NONE))
            }
        }
    }
}

/// A ray with what every triangle test would otherwise recompute: the
/// shear of the watertight test (the box tests' part is
/// [`Slabs`](super::node::Slabs)).
#[derive(Debug, Clone)]
pub struct PreparedRay {
    pub ray: Ray,
    /// Worked out at the first triangle the ray meets: a ray that meets
    /// only spheres never needs it.
    shear: OnceCell<Shear>,
}

impl PreparedRay {
    #[inline]
    pub fn new(ray: &Ray) -> PreparedRay {
        PreparedRay {
            ray: *ray,
            shear: OnceCell::new(),
        }
    }

    /// The triangle test's transform for this ray.
    #[inline]
    pub fn shear(&self) -> &Shear {
        self.shear.get_or_init(|| Shear::new(&self.ray))
    }
}

/// The watertight triangle test's transform of space (chapter 2's
/// `intersect_triangle`, after Woop, Benthin and Wald, JCGT 2013): the ray
/// becomes the +z axis from the origin. Chapter 2 works it out for every
/// triangle; it depends on the ray only, so here it is worked out once.
///
/// Chapter 2 picks coordinates kx, ky, kz of p − r0 and computes
/// x = p[kx] − sx·p[kz], y = p[ky] − sy·p[kz], z = sz·p[kz]. Here each is a
/// dot product with a row that holds 1, −sx (or −sy, or sz) and zeros: the
/// same products and sums, since adding a zero term changes no bit (but a
/// zero's sign, which no test here looks at), and no coordinate is picked
/// by index, which costs a branch each time.
#[derive(Debug, Clone, Copy)]
pub struct Shear {
    origin: Vec3A,
    /// The rows e_kx − sx·e_kz, e_ky − sy·e_kz and sz·e_kz (e_i the unit
    /// vectors), so that x, y, z = rows · (p − r0).
    rows: Mat3A,
}

impl Shear {
    fn new(ray: &Ray) -> Shear {
        let d = ray.direction.to_array();
        let kz = ray.direction.abs().max_position();
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        // Built as arrays: indexing a Vec3 is a branch per index.
        let (mut x, mut y, mut z) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        (x[kx], x[kz]) = (1.0, -(d[kx] / d[kz]));
        (y[ky], y[kz]) = (1.0, -(d[ky] / d[kz]));
        z[kz] = 1.0 / d[kz];
        let rows = Mat3A::from_cols_array_2d(&[x, y, z]).transpose();
        Shear {
            origin: ray.origin.into(),
            rows,
        }
    }

    /// A corner in the ray's space: x, y across the ray, z along it. The
    /// matrix product sums each row's three products left to right, as a
    /// dot product does, in four lanes at once.
    #[inline]
    fn project(&self, p: Vec3) -> (f32, f32, f32) {
        let p = self.rows * (Vec3A::from(p) - self.origin);
        (p.x, p.y, p.z)
    }

    /// Chapter 2's `intersect_triangle`, the same operations in the same
    /// order, so the same t to the last bit. The barycentric weights are
    /// kept as fractions, divided only for the one hit that is chosen.
    #[inline]
    pub fn intersect(
        &self,
        [p0, p1, p2]: [Vec3; 3],
        t_min: f32,
        t_max: f32,
    ) -> Option<(f32, Weights)> {
        let (x0, y0, z0) = self.project(p0);
        let (x1, y1, z1) = self.project(p1);
        let (x2, y2, z2) = self.project(p2);
        let mut u = x2 * y1 - y2 * x1;
        let mut v = x0 * y2 - y0 * x2;
        let mut w = x1 * y0 - y1 * x0;
        if u == 0.0 || v == 0.0 || w == 0.0 {
            // On an edge in f32: decide in f64, as chapter 2 does.
            u = edge_f64(x2, y2, x1, y1);
            v = edge_f64(x0, y0, x2, y2);
            w = edge_f64(x1, y1, x0, y0);
        }
        let outside = (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0);
        let determinant = u + v + w;
        if outside || determinant == 0.0 {
            return None;
        }
        let t = (u * z0 + v * z1 + w * z2) / determinant;
        let weights = Weights { v, w, determinant };
        (t.is_finite() && t > t_min && t < t_max).then_some((t, weights))
    }
}

/// A triangle hit's barycentric weights (α, β) = (v/det, w/det), as chapter
/// 2's `intersect_triangle` computes them, before the division.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weights {
    v: f32,
    w: f32,
    determinant: f32,
}

impl Weights {
    /// For shapes that have none: (0, 0).
    pub const NONE: Weights = Weights {
        v: 0.0,
        w: 0.0,
        determinant: 1.0,
    };

    /// (α, β).
    pub fn alpha_beta(&self) -> (f32, f32) {
        (self.v / self.determinant, self.w / self.determinant)
    }
}

fn edge_f64(px: f32, py: f32, qx: f32, qy: f32) -> f32 {
    (px as f64 * qy as f64 - py as f64 * qx as f64) as f32
}

/// Chapter 2's `intersect_sphere`, to the last bit, after a test in f32
/// that rules out most rays that miss: those that pass the centre farther
/// than r, by a margin that covers every rounding.
///
/// With f = r0 − c and rd of length 1 (up to rounding), the ray passes the
/// centre at distance |h|, h = f − (f·rd)·rd. Computed in f32, h is off by
/// a few units in the last place of |f| (f32::EPSILON·|f| each); 64 of them
/// is a wide margin. So if |h| > r + 64·ε·|f|, the exact |h| exceeds r too,
/// and so does chapter 2's (in f64, far more exact): its discriminant
/// 4a(r² − h·h) is negative, and it answers None as this does.
#[inline]
fn intersect_sphere_quickly(
    center: Vec3,
    radius: f32,
    ray: &Ray,
    t_min: f32,
    t_max: f32,
) -> Option<f32> {
    let f = ray.origin - center;
    let h = f - f.dot(ray.direction) * ray.direction;
    let margin = radius + 64.0 * f32::EPSILON * f.abs().max_element();
    if h.length_squared() > margin * margin {
        return None;
    }
    intersect_sphere(center, radius, ray, t_min, t_max)
}
