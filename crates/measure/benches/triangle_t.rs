//! What a triangle's t from its plane in f64 costs (chapter 2's
//! `intersect_triangle`, since issue 36) against the watertight test's own
//! f32 t (Woop, Benthin and Wald's mean of the corners' z, as before), on
//! every primary ray against every triangle of a mesh: most tests miss and
//! pay nothing more; a ray that passes through a triangle pays an f64
//! cross product and two dot products.
//!
//! Run with `cargo bench --bench triangle_t`: the two tests timed in
//! alternation, round after round, the median of the per-round ratios.

use std::hint::black_box;
use std::path::Path;
use std::time::{Duration, Instant};

use measure::bench::median;
use raybook::scene_files::nff;
use raybook::toolkit::Vec3;
use raybook::toolkit::scene::Shape;
use raybook::tracer::{Camera, Ray, intersect_triangle};

/// A triangle test: the ray, the corners, the t found.
type Test = dyn Fn(&Ray, [Vec3; 3]) -> Option<f32>;

/// The watertight test with its own t, as chapter 2 had it before.
fn watertight_f32([p0, p1, p2]: [Vec3; 3], ray: &Ray, t_min: f32, t_max: f32) -> Option<f32> {
    let d = ray.direction;
    let kz = d.abs().max_position();
    let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
    if d[kz] < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    let (sx, sy, sz) = (d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
    let project = |p: Vec3| {
        let p = p - ray.origin;
        (p[kx] - sx * p[kz], p[ky] - sy * p[kz], sz * p[kz])
    };
    let (x0, y0, z0) = project(p0);
    let (x1, y1, z1) = project(p1);
    let (x2, y2, z2) = project(p2);
    let edge = |px: f32, py: f32, qx: f32, qy: f32| px * qy - py * qx;
    let (u, v, w) = (
        edge(x2, y2, x1, y1),
        edge(x0, y0, x2, y2),
        edge(x1, y1, x0, y0),
    );
    let outside = (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0);
    let determinant = u + v + w;
    if outside || determinant == 0.0 {
        return None;
    }
    let t = (u * z0 + v * z1 + w * z2) / determinant;
    (t.is_finite() && t > t_min && t < t_max).then_some(t)
}

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/spd");
    println!(
        "| scene | triangles | rays × triangles | f32 t | f64 t | ratio | tests that pass through |"
    );
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for name in ["tetra-3", "teapot-2"] {
        let scene = nff::load(root.join(format!("{name}.nff"))).unwrap();
        let triangles: Vec<[Vec3; 3]> = scene
            .objects
            .iter()
            .filter_map(|o| match o.shape {
                Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
                    Some(vertices)
                }
                _ => None,
            })
            .collect();
        let camera = Camera::new(&scene.camera, 64, 48);
        let rays: Vec<Ray> = (0..48)
            .flat_map(|y| (0..64).map(move |x| (x, y)))
            .map(|(x, y)| camera.primary_ray(x, y))
            .collect();
        let through = rays
            .iter()
            .flat_map(|r| triangles.iter().map(move |&t| (r, t)))
            .filter(|(r, t)| intersect_triangle(*t, r, f32::NEG_INFINITY, f32::INFINITY).is_some())
            .count();
        let f32_t = |ray: &Ray, t: [Vec3; 3]| watertight_f32(t, ray, 0.0, f32::INFINITY);
        let f64_t =
            |ray: &Ray, t: [Vec3; 3]| intersect_triangle(t, ray, 0.0, f32::INFINITY).map(|h| h.0);
        let ways: [&Test; 2] = [&f32_t, &f64_t];
        let mut times: [Vec<Duration>; 2] = Default::default();
        for _ in 0..15 {
            for (i, way) in ways.iter().enumerate() {
                let start = Instant::now();
                for ray in &rays {
                    for &t in &triangles {
                        black_box(way(black_box(ray), t));
                    }
                }
                times[i].push(start.elapsed());
            }
        }
        let ms = |d: &Duration| d.as_secs_f64() * 1e3;
        let ratio = median(times[1].iter().zip(&times[0]).map(|(a, b)| ms(a) / ms(b)));
        let tests = rays.len() * triangles.len();
        println!(
            "| {name} | {} | {tests} | {:.1} ms | {:.1} ms | {ratio:.3} | {:.2}% |",
            triangles.len(),
            median(times[0].iter().map(ms)),
            median(times[1].iter().map(ms)),
            100.0 * through as f64 / tests as f64
        );
    }
    println!("\n(64×48 primary rays against every triangle, one thread; median of 15 rounds)");
}
