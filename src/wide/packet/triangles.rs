//! Four triangles in a packet, lane by lane: chapter 2's watertight test
//! in four lanes, and the bounds on t that its own f32 numbers give.

use glam::Vec4;

use super::super::primitive::{Geometry, PreparedRay, Primitive, Weights};
use super::lanes;
use crate::toolkit::Vec3;
use crate::tracer::{Ray, triangle_plane_t};

/// Four triangles: each corner's x, y, z.
#[derive(Debug, Clone, Copy)]
pub(super) struct Triangles {
    corners: [[Vec4; 3]; 3],
}

/// What the four-lane triangle test found.
pub(super) struct Found {
    /// Bit i: the ray passes through lane i's triangle (not on an edge).
    pub(super) hit: u32,
    /// Bit i: lane i is on an edge in f32, to be decided in f64.
    pub(super) on_edge: u32,
    /// The corners' x and y in the ray's space.
    x: [Vec4; 3],
    y: [Vec4; 3],
    /// The edge functions and their sum.
    u: Vec4,
    v: Vec4,
    w: Vec4,
    determinant: Vec4,
}

/// Bounds on each lane's t, as chapter 2 finds it, from the watertight
/// test's own f32 t (`Triangles::t_range`): the exact t lies in [low, high].
pub(super) struct TRange {
    low: Vec4,
    high: Vec4,
}

impl TRange {
    /// Lanes whose t may lie in (t_min, t_max): all but those surely at or
    /// below t_min or at or above t_max (and a lane whose bounds are not
    /// numbers may).
    #[inline(always)]
    pub(super) fn may_lie_within(&self, t_min: f32, t_max: f32) -> u32 {
        let below = self.high.cmplt(Vec4::splat(t_min));
        let beyond = self.low.cmpgt(Vec4::splat(t_max));
        !(below | beyond).bitmask() & 0b1111
    }

    /// Lanes whose t surely lies in (t_min, t_max).
    #[inline(always)]
    pub(super) fn surely_within(&self, t_min: f32, t_max: f32) -> u32 {
        (self.low.cmpgt(Vec4::splat(t_min)) & self.high.cmplt(Vec4::splat(t_max))).bitmask()
    }
}

impl Found {
    pub(super) fn weights(&self, lane: usize) -> Weights {
        let lane_of = |v: Vec4| v.to_array()[lane];
        Weights::new(lane_of(self.v), lane_of(self.w), lane_of(self.determinant))
    }
}

impl Triangles {
    pub(super) fn of(triangles: &[&Primitive]) -> Triangles {
        let mut packet = Triangles {
            corners: [[Vec4::ZERO; 3]; 3],
        };
        for (lane, p) in triangles.iter().enumerate() {
            let Geometry::Triangle { vertices } = p.geometry else {
                unreachable!("only triangles are packed as triangles")
            };
            for (corner, vertex) in vertices.iter().enumerate() {
                for axis in 0..3 {
                    packet.corners[corner][axis][lane] = vertex[axis];
                }
            }
        }
        packet
    }

    pub(super) fn get(&self, lane: usize) -> [Vec3; 3] {
        self.corners
            .map(|c| Vec3::from_array(c.map(|axis| axis.to_array()[lane])))
    }

    /// Lane `lane`'s t, as chapter 2's `intersect_triangle` finds it.
    pub(super) fn t(&self, lane: usize, ray: &Ray) -> f32 {
        triangle_plane_t(self.get(lane), ray) as f32
    }

    /// Chapter 2's watertight test (`intersect_triangle`) in four lanes, up
    /// to its t ([`Triangles::t`]): the same products and sums, the same
    /// edge functions and determinant.
    #[inline(always)]
    pub(super) fn intersect(&self, ray: &mut PreparedRay) -> Found {
        let shear = ray.shear();
        let [p0, p1, p2] = &self.corners;
        let (x0, y0) = shear.project4(&ray.origin, p0);
        let (x1, y1) = shear.project4(&ray.origin, p1);
        let (x2, y2) = shear.project4(&ray.origin, p2);
        let u = x2 * y1 - y2 * x1;
        let v = x0 * y2 - y0 * x2;
        let w = x1 * y0 - y1 * x0;
        let zero = Vec4::ZERO;
        let on_edge = u.cmpeq(zero) | v.cmpeq(zero) | w.cmpeq(zero);
        let negative = u.cmplt(zero) | v.cmplt(zero) | w.cmplt(zero);
        let positive = u.cmpgt(zero) | v.cmpgt(zero) | w.cmpgt(zero);
        let determinant = u + v + w;
        let inside = !(negative & positive) & determinant.cmpne(zero);
        Found {
            hit: (inside & !on_edge).bitmask(),
            on_edge: on_edge.bitmask(),
            x: [x0, x1, x2],
            y: [y0, y1, y2],
            u,
            v,
            w,
            determinant,
        }
    }

    /// Bounds on each lane's t, for the lanes the ray passes through: the
    /// watertight test's own t in f32, t = (u·z₀ + v·z₁ + w·z₂) / (u + v + w)
    /// with zᵢ the corners' distances along the ray, plus or minus a bound
    /// on its rounding error. Chapter 2's t (`triangle_plane_t`, in f64) is
    /// exact to its rounding to f32, so it lies within the bounds too.
    ///
    /// The bound is pbrt-v4's (Pharr, Jakob and Humphreys, section 6.8.7,
    /// "Avoiding Intersections behind Ray Origins", its part on triangles), with γₙ = nu/(1 − nu), u = ε/2:
    /// the corners' z are off by δz = γ₃·max|zᵢ|, their x and y by
    /// δx = γ₅(max|xᵢ| + max|p\[kz\]|) (and δy alike), the edge functions by
    /// δe = 2(γ₂·max|xᵢ|·max|yᵢ| + δy·max|xᵢ| + δx·max|yᵢ|), so t by
    ///
    /// ```text
    /// δt = 3(γ₃·max|eᵢ|·max|zᵢ| + δe·max|zᵢ| + δz·max|eᵢ|) / |u + v + w|
    /// ```
    ///
    /// Taken twice, plus γ₄|t| for the division and the sum below it: a
    /// lane's f64 t is needed only where these bounds leave it in doubt.
    #[inline(always)]
    pub(super) fn t_range(&self, ray: &mut PreparedRay, found: &Found) -> TRange {
        const fn gamma(n: f32) -> f32 {
            let u = f32::EPSILON / 2.0;
            n * u / (1.0 - n * u)
        }
        let shear = ray.shear();
        let [(z0, a0), (z1, a1), (z2, a2)] = self
            .corners
            .each_ref()
            .map(|c| shear.depth4(&ray.origin, c));
        let largest = |[a, b, c]: [Vec4; 3]| a.abs().max(b.abs()).max(c.abs());
        let (max_x, max_y, max_z) = (largest(found.x), largest(found.y), largest([z0, z1, z2]));
        let max_e = largest([found.u, found.v, found.w]);
        let max_pz = a0.max(a1).max(a2);
        let delta_x = gamma(5.0) * (max_x + max_pz);
        let delta_y = gamma(5.0) * (max_y + max_pz);
        let delta_z = gamma(3.0) * max_z;
        let delta_e = 2.0 * (gamma(2.0) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let sum = gamma(3.0) * max_e * max_z + delta_e * max_z + delta_z * max_e;
        let delta_t = 3.0 * sum / found.determinant.abs();
        let t = (found.u * z0 + found.v * z1 + found.w * z2) / found.determinant;
        let bound = 2.0 * delta_t + gamma(4.0) * t.abs();
        TRange {
            low: t - bound,
            high: t + bound,
        }
    }

    /// For the debug assertions: chapter 2's t of each lane in `mask` lies
    /// outside (t_min, t_max), as the bounds said.
    pub(super) fn rightly_outside(&self, mask: u32, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        lanes(mask).all(|lane| {
            let t = self.t(lane, ray);
            !(t.is_finite() && t > t_min && t < t_max)
        })
    }

    /// For the debug assertions: chapter 2's t of each lane in `mask` lies
    /// in (t_min, t_max), as the bounds said.
    pub(super) fn rightly_within(&self, mask: u32, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        lanes(mask).all(|lane| {
            let t = self.t(lane, ray);
            t.is_finite() && t > t_min && t < t_max
        })
    }
}
