//! Eight lanes where the CPU has them: a leaf's two packets of triangles
//! through the watertight test together, in one AVX2 test of eight lanes
//! instead of two of four.
//!
//! Most leaves hold two packets of four triangles (teapot-6 304 of 392
//! leaves, tetra-6 all 512), so this takes most leaves in one test. The
//! lanes do [`Triangles::intersect`]'s and [`Triangles::t_range`]'s
//! operations in the same order, with the same comparisons (ordered `<`,
//! `>`, `==`, unordered `!=`, as SSE's), so each lane's answer is the
//! four-lane test's to the last bit, and the hits offered are the same.
//!
//! Chosen at run time with `std::arch` (`is_x86_feature_detected!` and
//! `#[target_feature(enable = "avx2")]`) rather than a crate: one feature
//! and one function, and the standard library's check is cached.
//! `RAYBOOK_NO_AVX2=1` forces the four-lane path on a CPU that has AVX2
//! (CI checks that both give the same bytes).

use std::arch::x86_64::{
    __m256, _CMP_EQ_OQ, _CMP_GT_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ, _mm256_add_ps, _mm256_and_ps,
    _mm256_andnot_ps, _mm256_cmp_ps, _mm256_div_ps, _mm256_max_ps, _mm256_movemask_ps,
    _mm256_mul_ps, _mm256_or_ps, _mm256_set_m128, _mm256_set1_ps, _mm256_sub_ps,
};

use glam::Vec4;

use super::{Packet, Shapes, Triangles, Weights, lanes};
use crate::tracer::intersect_triangle;
use crate::wide::closest::Offer;
use crate::wide::primitive::PreparedRay;

/// Is the eight-lane leaf test to be used? AVX2 on this CPU, and the
/// variable `RAYBOOK_NO_AVX2` unset.
pub fn available() -> bool {
    std::env::var_os("RAYBOOK_NO_AVX2").is_none() && std::is_x86_feature_detected!("avx2")
}

/// A leaf of two packets of triangles: `a`'s lanes are 0 to 3 of the
/// eight, `b`'s 4 to 7.
pub struct TwoOfTriangles<'p> {
    a: (&'p Packet, &'p Triangles),
    b: (&'p Packet, &'p Triangles),
}

/// The leaf's two packets of triangles, if it is two packets of triangles.
#[inline(always)]
pub fn two_of_triangles(packets: &[Packet]) -> Option<TwoOfTriangles<'_>> {
    match packets {
        [a, b] => match (&a.shapes, &b.shapes) {
            (Shapes::Triangles(ta), Shapes::Triangles(tb)) => Some(TwoOfTriangles {
                a: (a, ta),
                b: (b, tb),
            }),
            _ => None,
        },
        _ => None,
    }
}

/// [`Packet::offer_hits`] for a leaf of two packets of triangles, tested
/// at once. The limit is asked again before each offer, as there.
#[target_feature(enable = "avx2")]
#[inline]
pub fn offer_hits_of_two(
    TwoOfTriangles { a, b }: TwoOfTriangles,
    ray: &mut PreparedRay,
    t_min: f32,
    closest: &mut impl Offer,
) {
    let used = a.0.used | b.0.used << 4;
    // Lane `lane` of the eight: its packet, triangles and lane of four.
    let one = |lane: usize| {
        let ((packet, triangles), at) = if lane < 4 { (a, lane) } else { (b, lane - 4) };
        (packet, triangles, at)
    };
    let found = intersect(a.1, b.1, ray);
    let through = found.hit & used;
    if through != 0 {
        let range = found.t_range();
        let maybe = range.may_lie_within(t_min, closest.limit()) & through;
        let outside = through & !maybe;
        debug_assert!(
            a.1.rightly_outside(outside & 0xf, ray.ray, t_min, closest.limit())
                && b.1
                    .rightly_outside(outside >> 4, ray.ray, t_min, closest.limit())
        );
        for lane in lanes(maybe) {
            let (packet, triangles, at) = one(lane);
            let t = triangles.t(at, ray.ray);
            if t.is_finite() && t > t_min && t < closest.limit() {
                closest.offer((t, found.weights(lane)), packet.object[at]);
            }
        }
    }
    for lane in lanes(found.on_edge & used) {
        let (packet, triangles, at) = one(lane);
        if let Some((t, alpha, beta)) =
            intersect_triangle(triangles.get(at), ray.ray, t_min, closest.limit())
        {
            closest.offer((t, Weights::new(alpha, beta, 1.0)), packet.object[at]);
        }
    }
}

/// [`Packet::blocks`] for a leaf of two packets of triangles, tested at
/// once: does one of their shadow-casting triangles meet the ray in
/// (t_min, t_max)?
#[target_feature(enable = "avx2")]
#[inline]
pub fn blocks_of_two(
    TwoOfTriangles { a, b }: TwoOfTriangles,
    ray: &mut PreparedRay,
    t_min: f32,
    t_max: f32,
) -> bool {
    let casting = (a.0.used & a.0.shadows) | (b.0.used & b.0.shadows) << 4;
    if casting == 0 {
        return false;
    }
    let one = |lane: usize| {
        if lane < 4 {
            (a.1, lane)
        } else {
            (b.1, lane - 4)
        }
    };
    let found = intersect(a.1, b.1, ray);
    let through = found.hit & casting;
    if through != 0 {
        let range = found.t_range();
        let surely = range.surely_within(t_min, t_max) & through;
        let maybe = range.may_lie_within(t_min, t_max) & through;
        debug_assert!(
            a.1.rightly_within(surely & 0xf, ray.ray, t_min, t_max)
                && b.1.rightly_within(surely >> 4, ray.ray, t_min, t_max)
        );
        let outside = through & !maybe;
        debug_assert!(
            a.1.rightly_outside(outside & 0xf, ray.ray, t_min, t_max)
                && b.1.rightly_outside(outside >> 4, ray.ray, t_min, t_max)
        );
        let within = |t: f32| t.is_finite() && t > t_min && t < t_max;
        let t = |lane: usize| {
            let (triangles, at) = one(lane);
            triangles.t(at, ray.ray)
        };
        if surely != 0 || lanes(maybe).any(|lane| within(t(lane))) {
            return true;
        }
    }
    lanes(found.on_edge & casting).any(|lane| {
        let (triangles, at) = one(lane);
        intersect_triangle(triangles.get(at), ray.ray, t_min, t_max).is_some()
    })
}

/// What the eight-lane test found: as the four-lane `Found`, with what
/// its t's bounds need.
struct Found8 {
    hit: u32,
    on_edge: u32,
    x: [__m256; 3],
    y: [__m256; 3],
    /// Each corner's p\[kz\] (the corner less r0, along the ray's main
    /// axis), and the shear's sz in all lanes.
    along: [__m256; 3],
    depth: __m256,
    u: __m256,
    v: __m256,
    w: __m256,
    determinant: __m256,
}

/// The four-lane `TRange`, eight lanes.
struct TRange8 {
    low: __m256,
    high: __m256,
}

impl TRange8 {
    /// [`TRange::may_lie_within`](super::TRange::may_lie_within), eight
    /// lanes.
    #[target_feature(enable = "avx2")]
    #[inline]
    fn may_lie_within(&self, t_min: f32, t_max: f32) -> u32 {
        let below = _mm256_cmp_ps::<_CMP_LT_OQ>(self.high, _mm256_set1_ps(t_min));
        let beyond = _mm256_cmp_ps::<_CMP_GT_OQ>(self.low, _mm256_set1_ps(t_max));
        !bits(_mm256_or_ps(below, beyond)) & 0xff
    }

    /// [`TRange::surely_within`](super::TRange::surely_within), eight
    /// lanes.
    #[target_feature(enable = "avx2")]
    #[inline]
    fn surely_within(&self, t_min: f32, t_max: f32) -> u32 {
        let above = _mm256_cmp_ps::<_CMP_GT_OQ>(self.low, _mm256_set1_ps(t_min));
        let below = _mm256_cmp_ps::<_CMP_LT_OQ>(self.high, _mm256_set1_ps(t_max));
        bits(_mm256_and_ps(above, below))
    }
}

impl Found8 {
    fn weights(&self, lane: usize) -> Weights {
        let lane_of = |v: __m256| lanes8(v)[lane];
        Weights::new(lane_of(self.v), lane_of(self.w), lane_of(self.determinant))
    }

    /// [`Triangles::t_range`], eight lanes: the same sums and products in
    /// the same order. Worked out only where the ray passes through a
    /// triangle, as there (its two divisions are most of its time).
    #[target_feature(enable = "avx2")]
    #[inline]
    fn t_range(&self) -> TRange8 {
        const fn gamma(n: f32) -> f32 {
            let u = f32::EPSILON / 2.0;
            n * u / (1.0 - n * u)
        }
        let (add, sub, mul, max, splat) = (
            _mm256_add_ps,
            _mm256_sub_ps,
            _mm256_mul_ps,
            _mm256_max_ps,
            _mm256_set1_ps,
        );
        // Shear::depth4.
        let [z0, z1, z2] = self.along.map(|p| mul(self.depth, p));
        let [a0, a1, a2] = self.along.map(|p| abs(p));
        let largest = |[a, b, c]: [__m256; 3]| max(max(abs(a), abs(b)), abs(c));
        let (max_x, max_y, max_z) = (largest(self.x), largest(self.y), largest([z0, z1, z2]));
        let (u, v, w, determinant) = (self.u, self.v, self.w, self.determinant);
        let max_e = largest([u, v, w]);
        let max_pz = max(max(a0, a1), a2);
        let delta_x = mul(splat(gamma(5.0)), add(max_x, max_pz));
        let delta_y = mul(splat(gamma(5.0)), add(max_y, max_pz));
        let delta_z = mul(splat(gamma(3.0)), max_z);
        let products = add(
            add(
                mul(mul(splat(gamma(2.0)), max_x), max_y),
                mul(delta_y, max_x),
            ),
            mul(delta_x, max_y),
        );
        let delta_e = mul(splat(2.0), products);
        let sum = add(
            add(
                mul(mul(splat(gamma(3.0)), max_e), max_z),
                mul(delta_e, max_z),
            ),
            mul(delta_z, max_e),
        );
        let delta_t = _mm256_div_ps(mul(splat(3.0), sum), abs(determinant));
        let t = _mm256_div_ps(add(add(mul(u, z0), mul(v, z1)), mul(w, z2)), determinant);
        let bound = add(mul(splat(2.0), delta_t), mul(splat(gamma(4.0)), abs(t)));
        TRange8 {
            low: sub(t, bound),
            high: add(t, bound),
        }
    }
}

/// The eight f32 of `v`, lane 0 first.
fn lanes8(v: __m256) -> [f32; 8] {
    // SAFETY: 32 bytes either way, and every bit pattern is an f32.
    unsafe { std::mem::transmute::<__m256, [f32; 8]>(v) }
}

/// Bit i set where lane i of the comparison `mask` is true.
#[target_feature(enable = "avx2")]
#[inline]
fn bits(mask: __m256) -> u32 {
    _mm256_movemask_ps(mask) as u32
}

/// |v| in each lane: its sign bit cleared, as glam's `Vec4::abs`.
#[target_feature(enable = "avx2")]
#[inline]
fn abs(v: __m256) -> __m256 {
    _mm256_andnot_ps(_mm256_set1_ps(-0.0), v)
}

/// [`Triangles::intersect`] for `a` (lanes 0 to 3) and `b` (lanes 4 to
/// 7): the same operations, lane for lane.
#[target_feature(enable = "avx2")]
#[inline]
fn intersect(a: &Triangles, b: &Triangles, ray: &mut PreparedRay) -> Found8 {
    let shear = ray.shear();
    let [kx, ky, kz] = shear.axes;
    let [sx, sy] = shear.scale.map(|s| _mm256_set1_ps(s));
    let origin = ray.origin.map(|o| _mm256_set1_ps(o.x));
    let join = |low: Vec4, high: Vec4| _mm256_set_m128(high.into(), low.into());
    let corner = |c: usize| [0, 1, 2].map(|axis| join(a.corners[c][axis], b.corners[c][axis]));
    let (sub, mul) = (_mm256_sub_ps, _mm256_mul_ps);
    // Shear::project4, and p[kz] for the bounds on t.
    let project = |corner: [__m256; 3]| {
        let p = [0, 1, 2].map(|axis| sub(corner[axis], origin[axis]));
        let (x, y) = (sub(p[kx], mul(sx, p[kz])), sub(p[ky], mul(sy, p[kz])));
        (x, y, p[kz])
    };
    let [(x0, y0, p0), (x1, y1, p1), (x2, y2, p2)] = [0, 1, 2].map(|c| project(corner(c)));
    let u = sub(mul(x2, y1), mul(y2, x1));
    let v = sub(mul(x0, y2), mul(y0, x2));
    let w = sub(mul(x1, y0), mul(y1, x0));
    let zero = _mm256_set1_ps(0.0);
    let or3 = |a, b, c| _mm256_or_ps(_mm256_or_ps(a, b), c);
    let eq = |x| _mm256_cmp_ps::<_CMP_EQ_OQ>(x, zero);
    let lt = |x| _mm256_cmp_ps::<_CMP_LT_OQ>(x, zero);
    let gt = |x| _mm256_cmp_ps::<_CMP_GT_OQ>(x, zero);
    let on_edge = or3(eq(u), eq(v), eq(w));
    let negative = or3(lt(u), lt(v), lt(w));
    let positive = or3(gt(u), gt(v), gt(w));
    let determinant = _mm256_add_ps(_mm256_add_ps(u, v), w);
    let nonzero = _mm256_cmp_ps::<_CMP_NEQ_UQ>(determinant, zero);
    let inside = _mm256_andnot_ps(_mm256_and_ps(negative, positive), nonzero);
    Found8 {
        hit: bits(inside) & !bits(on_edge) & 0xff,
        on_edge: bits(on_edge),
        x: [x0, x1, x2],
        y: [y0, y1, y2],
        along: [p0, p1, p2],
        depth: _mm256_set1_ps(shear.depth),
        u,
        v,
        w,
        determinant,
    }
}
