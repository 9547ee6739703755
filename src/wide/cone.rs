//! Four cones in a packet, lane by lane, and the f32 test that rules out
//! most rays that miss them before chapter 2's test in f64.
//!
//! Chapter 2's `intersect_cone` works out the cone's axis (a square root and
//! four divisions) and solves its quadratic (a square root and two more
//! divisions), all in f64, for every ray that enters the cone's box. In the
//! SPD's rings, the cylinders are thin and lie across their boxes: most of
//! those rays pass the cylinder by. In rings-7's render at 512², chapter
//! 2's test ran 7.84 million times, one in nine a hit, before
//! [`Cones::might_hit`] ruled rays out, and 2.98 million times after
//! (book/appendix/performance.md, "Cones four at a time").

use glam::{BVec4A, Vec4};

use super::primitive::{Geometry, PreparedRay, Primitive};
use crate::toolkit::Vec3;

/// Up to four cones: their ends and the ends' radii, and for the f32 test,
/// a slack that grows with how steep each cone is.
#[derive(Debug, Clone, Copy)]
pub struct Cones {
    base: [Vec4; 3],
    apex: [Vec4; 3],
    base_radius: Vec4,
    apex_radius: Vec4,
    /// 2⁻¹⁴·(1 + R/h), with R the larger radius and h the height (rounded
    /// up): see [`Cones::might_hit`].
    slack: Vec4,
}

/// A cone's ends and their radii, as chapter 2's `intersect_cone` takes
/// them: (base, base radius, apex, apex radius).
pub type Ends = (Vec3, f32, Vec3, f32);

impl Cones {
    /// The packet of up to four cones. A lane left empty holds a cone of no
    /// radius at the origin (the packet's `used` mask leaves it out).
    pub fn of(cones: &[&Primitive]) -> Cones {
        let mut packet = Cones {
            base: [Vec4::ZERO; 3],
            apex: [Vec4::ZERO; 3],
            base_radius: Vec4::ZERO,
            apex_radius: Vec4::ZERO,
            slack: Vec4::ZERO,
        };
        for (lane, p) in cones.iter().enumerate() {
            let Geometry::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
            } = p.geometry
            else {
                unreachable!("only cones are packed as cones")
            };
            for axis in 0..3 {
                packet.base[axis][lane] = base[axis];
                packet.apex[axis][lane] = apex[axis];
            }
            packet.base_radius[lane] = base_radius;
            packet.apex_radius[lane] = apex_radius;
            packet.slack[lane] = slack(base, apex, base_radius.max(apex_radius));
        }
        packet
    }

    /// Lane `lane`'s cone, for chapter 2's test.
    pub fn get(&self, lane: usize) -> Ends {
        // Lanes are read from arrays: indexing a Vec4 is a jump table.
        let point = |p: &[Vec4; 3]| Vec3::from_array(p.map(|axis| axis.to_array()[lane]));
        let radius = |r: Vec4| r.to_array()[lane];
        (
            point(&self.base),
            radius(self.base_radius),
            point(&self.apex),
            radius(self.apex_radius),
        )
    }

    /// Lanes whose cone the ray may meet: all but those whose axis's line
    /// the ray's line passes farther from than the cone's larger radius R,
    /// by a margin that covers every rounding, in f32 here and in f64 in
    /// chapter 2. (The side lies within R of its axis, so a ray that passes
    /// the axis's line farther away meets no point of it.)
    ///
    /// With f = r0 − base, a = apex − base and n = rd × a, the two lines are
    /// d = |f·n| / |n| apart. The test, without a division:
    ///
    /// ```text
    /// miss  when  |f·n| > (R + σ)·|n| + σ·D·A,    σ = 2⁻¹⁴(1 + R/h)(F + A + R)
    /// ```
    ///
    /// with F, A, D the largest |coordinate| of f, a and rd, and h = |a|.
    /// Why σ is enough (u = ε/2 is f32's unit roundoff, γₙ = nu/(1 − nu)):
    /// - in f32, f·n is off by at most γ₇·6·F·D·A (each of its six products
    ///   goes through seven roundings: f, a, rd·a, the cross product's
    ///   difference, f·n and two sums), and |n| by at most γ₃·2√3·D·A plus
    ///   3u of itself: together below 22ε(F + R)·D·A ≤ σ·D·A/16; the
    ///   test's own roundings take less than 8u of its right side;
    /// - chapter 2 finds a hit where its f64 quadratic a·t² + b·t + c,
    ///   rounded, is 0: the exact one is then within about 2⁷ f64 roundings
    ///   of its terms' sizes (each below 36S²), so below 2⁻⁴⁰S², with
    ///   S = 2(F + A + R)(1 + R/h) a bound on |f|, on h, on the radius level
    ///   with r0 and on the distance along the ray to a point of the side.
    ///   On a line that passes d > R + δ from the axis, the exact quadratic
    ///   (distance² from the axis less the cone's radius² there) is at
    ///   least δ²: chapter 2 can find a hit only if δ² < 2⁻⁴⁰S², that is
    ///   δ < 2⁻²⁰S = σ/32.
    ///
    /// So where the test says "miss", the exact d exceeds R + σ/2 and chapter
    /// 2 finds no hit. A ray parallel to the axis (n = 0) is never ruled
    /// out, nor is a lane where anything is not a number (a cone of no
    /// height has a slack that is infinite or not a number). The tests in
    /// `cone/tests.rs` check this against chapter 2 over many rays, grazing
    /// ones among them (with σ = 0, they find a ray it would wrongly rule
    /// out).
    #[inline(always)]
    pub fn might_hit(&self, ray: &PreparedRay) -> BVec4A {
        let f = [0, 1, 2].map(|i| ray.origin[i] - self.base[i]);
        let a = [0, 1, 2].map(|i| self.apex[i] - self.base[i]);
        let [dx, dy, dz] = ray.direction;
        let n = [
            dy * a[2] - dz * a[1],
            dz * a[0] - dx * a[2],
            dx * a[1] - dy * a[0],
        ];
        let across = f[0] * n[0] + f[1] * n[1] + f[2] * n[2];
        let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let largest = |v: [Vec4; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
        let (far, long) = (largest(f), largest(a));
        let radius = self.base_radius.max(self.apex_radius);
        let sigma = self.slack * (far + long + radius);
        let reach = Vec4::splat(ray.ray.direction.abs().max_element());
        let bound = (radius + sigma) * length + sigma * reach * long;
        !across.abs().cmpgt(bound)
    }
}

/// 2⁻¹⁴(1 + R/h), rounded up: [`Cones::might_hit`]'s slack per unit of
/// F + A + R. Infinite or not a number for a cone of no height, which is
/// then never ruled out.
fn slack(base: Vec3, apex: Vec3, radius: f32) -> f32 {
    let height = (apex.as_dvec3() - base.as_dvec3()).length();
    let steep = 1.0 + f64::from(radius) / height;
    ((steep / f64::from(1u32 << 14)) as f32).next_up()
}

#[cfg(test)]
mod tests;
