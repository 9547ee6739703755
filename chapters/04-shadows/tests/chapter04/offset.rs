//! The offset's margin: on thousands of hits, computed again in f64, the
//! shadow ray's origin lies beyond the true surface, on the light's side.

use ch04_shadows::toolkit::Vec3;
use ch04_shadows::toolkit::scene::{Object, Shape};
use ch04_shadows::{Hit, Ray, closest_hit, offset_origin};

/// A point or vector in f64, to measure what f32 computed.
#[derive(Debug, Clone, Copy, PartialEq)]
struct DVec3 {
    x: f64,
    y: f64,
    z: f64,
}

impl DVec3 {
    const fn new(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3 { x, y, z }
    }
    fn of(v: Vec3) -> DVec3 {
        DVec3::new(v.x.into(), v.y.into(), v.z.into())
    }
    fn dot(self, o: DVec3) -> f64 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    fn cross(self, o: DVec3) -> DVec3 {
        DVec3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    fn normalize(self) -> DVec3 {
        self * (1.0 / self.length())
    }
}

impl std::ops::Add for DVec3 {
    type Output = DVec3;
    fn add(self, o: DVec3) -> DVec3 {
        DVec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl std::ops::Sub for DVec3 {
    type Output = DVec3;
    fn sub(self, o: DVec3) -> DVec3 {
        DVec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl std::ops::Mul<f64> for DVec3 {
    type Output = DVec3;
    fn mul(self, k: f64) -> DVec3 {
        DVec3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl std::ops::Mul<DVec3> for f64 {
    type Output = DVec3;
    fn mul(self, v: DVec3) -> DVec3 {
        v * self
    }
}

impl std::ops::Div<f64> for DVec3 {
    type Output = DVec3;
    fn div(self, k: f64) -> DVec3 {
        self * (1.0 / k)
    }
}

/// A small deterministic generator (xorshift64*): the same hits every run.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [−1, 1).
    fn signed(&mut self) -> f64 {
        2.0 * self.next() - 1.0
    }

    fn unit(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(self.signed(), self.signed(), self.signed());
            if v.dot(v) > 0.01 && v.dot(v) <= 1.0 {
                return v.normalize();
            }
        }
    }
}

fn f32s(v: DVec3) -> Vec3 {
    Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

/// Signed distance of `p` from the shape's true surface, in f64, positive on
/// the side its geometric normal (as chapter 2 defines it) points to.
fn signed_distance(shape: &Shape, p: Vec3) -> f64 {
    let p = DVec3::of(p);
    match *shape {
        Shape::Sphere { center, radius } => (p - DVec3::of(center)).length() - f64::from(radius),
        Shape::Plane { normal, offset } => {
            let n = DVec3::of(normal);
            (n.dot(p) + f64::from(offset)) / n.length()
        }
        Shape::Triangle {
            vertices: [a, b, c],
        }
        | Shape::SmoothTriangle {
            vertices: [a, b, c],
            ..
        } => {
            let (a, b, c) = (DVec3::of(a), DVec3::of(b), DVec3::of(c));
            let n = (b - a).cross(c - a).normalize();
            n.dot(p - a)
        }
        Shape::Cone {
            base,
            base_radius,
            apex,
            apex_radius,
            inside_out,
        } => {
            // In the plane through the axis and p: p is s along the axis and
            // ρ across it; the side is the line ρ = r(s) = r_b + k·s, which
            // p lies (ρ − r(s))·cos α from, where tan α = k.
            let (base, axis) = (DVec3::of(base), DVec3::of(apex - base));
            let (h, k) = (axis.length(), f64::from(apex_radius - base_radius));
            let (w, k) = (axis / h, k / h);
            let s = (p - base).dot(w);
            let rho = ((p - base) - s * w).length();
            let outside = (rho - f64::from(base_radius) - k * s) / (1.0 + k * k).sqrt();
            if inside_out { -outside } else { outside }
        }
    }
}

/// Shapes at the scale `scale` around `center`, and a ray at each.
fn cases(random: &mut Random, count: usize) -> Vec<(Shape, Ray)> {
    let mut out = Vec::new();
    for i in 0..count {
        let scale = [1.0, 100.0, 1e4][i % 3];
        let center = scale * DVec3::new(random.signed(), random.signed(), random.signed());
        let eye = center + scale * 0.5 * random.unit();
        let shape = match (i / 3) % 4 {
            0 => {
                let normal = random.unit();
                let offset = -normal.dot(center);
                Shape::Plane {
                    normal: f32s(normal).normalize(),
                    offset: offset as f32,
                }
            }
            1 => Shape::Sphere {
                center: f32s(center),
                radius: (0.01 * scale * (1.0 + 9.0 * random.next())) as f32,
            },
            2 => {
                // Long and thin as the SPD rings' cylinders, or pointed.
                let size = 0.1 * scale;
                let base = center + size * random.unit();
                let apex = base + 3.0 * size * random.unit();
                let radius = (0.1 * size * (1.0 + random.next())) as f32;
                Shape::Cone {
                    base: f32s(base),
                    base_radius: radius,
                    apex: f32s(apex),
                    apex_radius: [radius, 0.0, 0.5 * radius][i % 3],
                    inside_out: i % 2 == 0,
                }
            }
            _ => {
                // Some of them slivers: one corner almost on the opposite edge.
                let size = 0.1 * scale;
                let a = center + size * random.unit();
                let b = center + size * random.unit();
                let thin = if i % 2 == 0 { 1e-3 } else { 1.0 };
                let c = (a + b) / 2.0 + thin * size * random.unit();
                Shape::Triangle {
                    vertices: [f32s(a), f32s(b), f32s(c)],
                }
            }
        };
        // Aim at a point near the shape, so that most rays hit it.
        let target = match shape {
            Shape::Triangle {
                vertices: [a, b, c],
            } => {
                let (u, v) = (random.next(), random.next());
                let (u, v) = if u + v > 1.0 {
                    (1.0 - u, 1.0 - v)
                } else {
                    (u, v)
                };
                DVec3::of(a) + u * DVec3::of(b - a) + v * DVec3::of(c - a)
            }
            Shape::Sphere { radius, .. } => center + 0.9 * f64::from(radius) * random.unit(),
            Shape::Cone {
                base,
                base_radius,
                apex,
                ..
            } => {
                let (base, axis) = (DVec3::of(base), DVec3::of(apex - base));
                let across = axis.cross(random.unit()).normalize();
                base + random.next() * axis + 0.5 * f64::from(base_radius) * across
            }
            _ => center + 0.3 * scale * random.unit(),
        };
        let eye32 = f32s(eye);
        out.push((shape, Ray::new(eye32, (f32s(target) - eye32).normalize())));
    }
    out
}

/// Many hits on planes, spheres, cones and triangles (slivers among them),
/// near the origin and up to 10⁴ from it.
fn hits() -> Vec<(Shape, Hit)> {
    let mut random = Random(0x9e37_79b9_7f4a_7c15);
    cases(&mut random, 6000)
        .into_iter()
        .filter_map(|(shape, ray)| {
            let object = [Object {
                shape,
                material: 0,
                shadows: true,
            }];
            let hit = closest_hit(&object, &ray, 0.0, f32::INFINITY)?;
            Some((shape, hit))
        })
        .collect()
}

#[test]
fn the_hit_points_lie_well_within_their_error_bound() {
    let hits = hits();
    assert!(hits.len() > 3000, "only {} hits", hits.len());
    let worst = hits
        .iter()
        .map(|(shape, hit)| signed_distance(shape, hit.point).abs() / f64::from(hit.error))
        .fold(0.0, f64::max);
    println!(
        "{} hits, worst distance off the surface: {worst} × error",
        hits.len()
    );
    assert!(
        worst < 0.25,
        "a hit point lies {worst} × hit.error off its surface"
    );
}

#[test]
fn the_offset_origin_clears_the_true_surface_by_half_the_error_bound() {
    let hits = hits();
    let mut random = Random(7);
    let mut least = f64::INFINITY;
    for (shape, hit) in &hits {
        for _ in 0..2 {
            // A direction to either side, from grazing to straight out.
            let out = f32s(random.unit());
            let along = out.dot(hit.normal);
            if along.abs() < 1e-3 {
                continue;
            }
            let side = f64::from(along.signum());
            let origin = offset_origin(hit, out);
            let cleared = side * signed_distance(shape, origin) / f64::from(hit.error);
            least = least.min(cleared);
            assert!(
                cleared >= 0.5,
                "the origin {origin} lies {cleared} × hit.error beyond the true surface \
                 of {shape:?} on the side of {out} (at least 0.5 is needed: the hit \
                 points lie up to 0.25 × error off it, on either side)"
            );
        }
    }
    println!("least clearance: {least} × error");
}
