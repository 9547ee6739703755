//! What the wide BVH keeps of each object, and the ray prepared once for the
//! many tests it will meet.

use glam::Vec4;

use crate::toolkit::Vec3;
use crate::toolkit::scene::Shape;
use crate::tracer::Ray;

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

/// A bounded object, in the order of the tree's leaves, before its leaf is
/// packed (`packet.rs`): 80 bytes, held only while building.
#[derive(Debug, Clone, Copy)]
pub struct Primitive {
    pub geometry: Geometry,
    /// Index in the scene's objects.
    pub object: u32,
    /// Does it block shadow rays?
    pub shadows: bool,
}

// The size the docs and the table of bytes per object in book/appendix/performance.md give.
const _: () = assert!(std::mem::size_of::<Primitive>() == 80);

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
}

/// A ray with what every triangle test would otherwise recompute: the
/// shear of the watertight test (the box tests' part is
/// [`Slabs`](super::node::Slabs)), and its coordinates in four lanes.
///
/// The shear is worked out when the first triangle is tested, not for a ray
/// that meets none: a sphere's test and most shadow rays need none.
#[derive(Debug, Clone)]
pub struct PreparedRay<'r> {
    pub ray: &'r Ray,
    /// r0's and rd's coordinates, each in all four lanes.
    pub origin: [Vec4; 3],
    pub direction: [Vec4; 3],
    /// The triangle test's transform, once worked out.
    shear: Option<Shear>,
}

impl<'r> PreparedRay<'r> {
    #[inline]
    pub fn new(ray: &'r Ray) -> PreparedRay<'r> {
        PreparedRay {
            ray,
            origin: ray.origin.to_array().map(Vec4::splat),
            direction: ray.direction.to_array().map(Vec4::splat),
            shear: None,
        }
    }

    /// The triangle test's transform for this ray, worked out on first use.
    #[inline]
    pub fn shear(&mut self) -> Shear {
        *self.shear.get_or_insert_with(|| Shear::new(self.ray))
    }
}

/// The watertight triangle test's transform of space (chapter 2's
/// `intersect_triangle`, after Woop, Benthin and Wald, JCGT 2013): the ray
/// becomes the +z axis from the origin. Chapter 2 works it out for every
/// triangle; it depends on the ray only, so here it is worked out once.
#[derive(Debug, Clone, Copy)]
pub struct Shear {
    /// The axes kx, ky, kz: z the one along which the ray travels fastest,
    /// x and y the others, in the order that keeps a triangle's winding.
    axes: [usize; 3],
    /// sx = rd\[kx\] / rd\[kz\], sy = rd\[ky\] / rd\[kz\].
    scale: [f32; 2],
    /// sz = 1 / rd\[kz\]: a corner's z in the ray's space is its distance
    /// along the ray (for the f32 estimate of t only).
    depth: f32,
}

impl Shear {
    fn new(ray: &Ray) -> Shear {
        let d = ray.direction.to_array(); // indexing a Vec3 is a branch per index
        let kz = ray.direction.abs().max_position();
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        Shear {
            axes: [kx, ky, kz],
            scale: [d[kx] / d[kz], d[ky] / d[kz]],
            depth: 1.0 / d[kz],
        }
    }

    /// Four corners' z in the ray's space, z = sz·p\[kz\] with p the corner
    /// less r0, and |p\[kz\]|, each in four lanes (for
    /// `Triangles::t_range`).
    #[inline(always)]
    pub fn depth4(&self, origin: &[Vec4; 3], corner: &[Vec4; 3]) -> (Vec4, Vec4) {
        let kz = self.axes[2];
        let p = corner[kz] - origin[kz];
        (Vec4::splat(self.depth) * p, p.abs())
    }

    /// Four corners in the ray's space, x and y (the test needs no z: t
    /// comes from the plane), each in four lanes, given r0's coordinates in
    /// four lanes: as chapter 2 computes one, with p the corner less r0,
    ///
    /// ```text
    /// x = p[kx] − sx·p[kz],  y = p[ky] − sy·p[kz]
    /// ```
    #[inline(always)]
    pub fn project4(&self, origin: &[Vec4; 3], corner: &[Vec4; 3]) -> (Vec4, Vec4) {
        let p = [
            corner[0] - origin[0],
            corner[1] - origin[1],
            corner[2] - origin[2],
        ];
        let [kx, ky, kz] = self.axes;
        let [sx, sy] = self.scale;
        (
            p[kx] - Vec4::splat(sx) * p[kz],
            p[ky] - Vec4::splat(sy) * p[kz],
        )
    }
}

/// A triangle hit's barycentric weights (α, β) = (v/det, w/det), as chapter
/// 2's `intersect_triangle` computes them, before the division (or after
/// it, with det = 1, where chapter 2's test itself answered).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weights {
    v: f32,
    w: f32,
    determinant: f32,
}

impl Weights {
    pub fn new(v: f32, w: f32, determinant: f32) -> Weights {
        Weights { v, w, determinant }
    }

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
