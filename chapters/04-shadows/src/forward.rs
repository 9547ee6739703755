//! Idea 1: tracing light *forward*, from the lights to the camera.
//!
//! Before it casts rays backwards from the eye, the lecture asks whether we
//! could simply do what nature does: let the lights emit rays, let them
//! bounce, and colour the image where they arrive. This module does exactly
//! that for the scenes chapter 4 can render (diffuse surfaces, point lights,
//! one bounce), so that its pictures and numbers can be set beside chapter
//! 4's backward image. See the chapter text for what they show.
//!
//! # The photon's weight
//!
//! *What the backward image shows.* Chapter 3 gives a point x of a diffuse
//! surface (albedo ρ), lit by a point light of colour C and intensity I at
//! distance r from direction l, the pixel value
//!
//! ```text
//! P = ρ · C·I · max(0, n·l) / r²
//! ```
//!
//! C·I·cos θ / r² is the *irradiance* E (power per unit area arriving at x),
//! so P = ρE is the power per unit area the surface sends back, its
//! *radiosity*. A diffuse surface sends it equally into every direction of
//! its hemisphere, as the *radiance* L = ρE/π. So the chapter's pixel value
//! is P = π·L: π times the radiance along the pixel's ray.
//!
//! *What a photon carries.* A light of intensity I sends I per unit solid
//! angle, 4π·I over the whole sphere. Emitting N photons in uniformly random
//! directions, each carries the flux Φ = 4π·C·I / N. At its first hit the
//! surface keeps (1 − ρ) of it and sends ρΦ off again, in a direction drawn
//! with density cos θ_o / π about the normal (θ_o from the normal): that is
//! the diffuse law, which sends radiance equally into all directions.
//!
//! *What the camera measures.* The pinhole becomes a disc of radius a (area
//! A = π·a²) around the eye, perpendicular to the camera's forward axis. A
//! reflected photon that crosses the disc in direction ω lands on the pixel
//! whose backward ray has the direction −ω (the pixel says which way the
//! light came from, not where it crossed the disc: a camera focused at
//! infinity). By the definition of radiance, the flux crossing the disc from
//! the directions of pixel j is
//!
//! ```text
//! Φ_j = ∫_disc ∫_(pixel j) L · cos θ_c dω dA
//! ```
//!
//! where θ_c is the angle of the direction to the camera's axis. The pixel is
//! a rectangle of area S on the image plane at distance 1; a patch dS of it
//! at angle θ_c lies at distance 1/cos θ_c and is tilted by θ_c, so it spans
//! the solid angle dω = cos³θ_c · dS, and cos θ_c dω = cos⁴θ_c dS.
//!
//! *The estimator.* Give each photon that lands on pixel j the value
//!
//! ```text
//! w = π · ρΦ / (A · S · cos⁴θ_c) = ρΦ / (a² · S · cos⁴θ_c)
//! ```
//!
//! and add up the values on each pixel. Photon tracing is an unbiased
//! estimate of flux (the expected flux of the photons crossing a region is
//! the flux of light crossing it), so the expected sum on pixel j is
//!
//! ```text
//! ∫_disc ∫_(pixel j) L · cos θ_c · π / (A · S · cos⁴θ_c) dω dA
//!     = 1/(A·S) ∫_disc ∫_(pixel j) π·L dS dA
//! ```
//!
//! the chapter's pixel value π·L = P averaged over the pixel's area and over
//! the aperture. As N grows the image converges to that average, which
//! [`expected_image`] computes backwards with chapter 4's tracer. It differs
//! from chapter 4's picture (one ray through each pixel's centre from the
//! exact eye) only where P changes within a pixel or within a radius of a:
//! at the edges of objects and shadows.
//!
//! *The pinhole limit.* A photon leaving x gets through the disc with a
//! probability of about cos θ_o · cos θ_c · a² / d², d the distance to the
//! eye, so the share of photons that make a picture falls as a², and each
//! carries a value growing as 1/a². For a true pinhole (a = 0) no photon ever
//! arrives: the expected picture is right, but the picture is black.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
use rayon::prelude::*;

use crate::toolkit::scene::Light;
use crate::toolkit::{Color, Image, Scene, Stats, Vec3};
use crate::{Camera, Origin, Ray, World, offset_origin, render_shadows, trace};

/// Photons per chunk. Each chunk has its own random number generator, seeded
/// from the chunk's index: the same chunks give the same photons whatever
/// thread traces them.
pub const CHUNK: u64 = 1 << 14;

/// Chunks traced in parallel before their photons are added to the image, in
/// the chunks' order.
const BATCH: u64 = 64;

/// How a forward picture is taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Photons emitted, over all lights.
    pub rays: u64,
    /// The radius a of the aperture disc around the eye, in scene units.
    pub aperture: f32,
    /// Seed of the random numbers: the same seed gives the same picture.
    pub seed: u64,
}

/// What became of the photons.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Photons emitted.
    pub emitted: u64,
    /// Photons that hit a surface (the rest fly off to infinity).
    pub hit: u64,
    /// Reflected photons that cross the aperture disc.
    pub aperture: u64,
    /// Of those, the ones that land on the image: inside the field of view
    /// and not blocked on their way from the surface to the aperture.
    pub on_image: u64,
}

impl std::ops::AddAssign for Counts {
    fn add_assign(&mut self, o: Counts) {
        self.emitted += o.emitted;
        self.hit += o.hit;
        self.aperture += o.aperture;
        self.on_image += o.on_image;
    }
}

/// A forward-traced picture and what became of its photons.
#[derive(Debug, Clone, PartialEq)]
pub struct Forward {
    pub image: Image,
    pub counts: Counts,
}

impl Forward {
    /// The share of the emitted photons that reached the image.
    pub fn share(&self) -> f64 {
        self.counts.on_image as f64 / self.counts.emitted.max(1) as f64
    }
}

/// Can the forward tracer render this scene so that it converges to chapter
/// 4's picture? It needs what both tracers agree on: point lights only (no
/// ambient light, which comes from nowhere; no spot light), every light and
/// object casting shadows, and a black background (a photon that hits
/// nothing is lost; it never paints the sky). Both see every material as
/// diffuse with its albedo `color`. The error names what is in the way.
pub fn check_scene(scene: &Scene) -> Result<(), String> {
    let mut problems = Vec::new();
    for (i, light) in scene.lights.iter().enumerate() {
        match light {
            Light::Point { shadows: true, .. } => {}
            Light::Point { .. } => problems.push(format!(
                "lights[{i}] has shadows = false: its light would pass through objects"
            )),
            Light::Ambient { .. } => problems.push(format!(
                "lights[{i}] is ambient light: it comes from nowhere, so no photon carries it"
            )),
            _ => problems.push(format!(
                "lights[{i}] is not a point light: only point lights emit photons here"
            )),
        }
    }
    for (i, object) in scene.objects.iter().enumerate() {
        if !object.shadows {
            problems.push(format!(
                "objects[{i}] has shadows = false: photons cannot pass through it"
            ));
        }
    }
    if scene.image.background != Color::ZERO {
        problems.push(format!(
            "the background is {}, not black: no photon paints the sky",
            scene.image.background
        ));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("\n"))
    }
}

/// A point light as a source of photons.
#[derive(Debug, Clone, Copy)]
struct Emitter {
    position: Vec3,
    /// C·I: colour times intensity.
    power: Color,
    /// The chance that a photon comes from this light, in proportion to its
    /// power (the mean of its channels). Dividing by it keeps every light's
    /// share right however many photons it gets.
    probability: f32,
}

fn emitters(scene: &Scene) -> Vec<Emitter> {
    let mut emitters: Vec<Emitter> = scene
        .lights
        .iter()
        .filter_map(|light| match *light {
            Light::Point {
                position,
                color,
                intensity,
                ..
            } => Some(Emitter {
                position,
                power: color * intensity,
                probability: 0.0,
            }),
            _ => None,
        })
        .collect();
    let total: f32 = emitters.iter().map(|e| e.power.element_sum()).sum();
    if total > 0.0 {
        for e in &mut emitters {
            e.probability = e.power.element_sum() / total;
        }
    }
    emitters
}

/// Which light emits the next photon, for a uniform random `u` in [0, 1).
fn pick(emitters: &[Emitter], u: f32) -> Option<&Emitter> {
    let mut below = 0.0;
    let mut last = None;
    for e in emitters.iter().filter(|e| e.probability > 0.0) {
        below += e.probability;
        last = Some(e);
        if u < below {
            return last;
        }
    }
    last // rounding left `below` a hair under 1
}

/// A direction uniformly distributed over the unit sphere, from two uniform
/// numbers in [0, 1): z is uniform in [−1, 1] (Archimedes' hat-box theorem:
/// equal slices of height cut equal areas of the sphere), the angle around
/// the z axis uniform in [0, 2π).
pub fn uniform_sphere(u: f32, v: f32) -> Vec3 {
    let z = 1.0 - 2.0 * u;
    let ring = (1.0 - z * z).max(0.0).sqrt();
    let (sin, cos) = (std::f32::consts::TAU * v).sin_cos();
    Vec3::new(ring * cos, ring * sin, z)
}

/// A direction about the unit `normal` with density cos θ / π, from two
/// uniform numbers in [0, 1): a uniform point of the unit disc lifted onto
/// the hemisphere above it (Malley's method). The area of the disc under a
/// patch of the hemisphere is the patch's area times cos θ.
pub fn cosine_hemisphere(normal: Vec3, u: f32, v: f32) -> Vec3 {
    let radius = u.sqrt();
    let (sin, cos) = (std::f32::consts::TAU * v).sin_cos();
    let height = (1.0 - u).max(0.0).sqrt();
    let (a, b) = normal.any_orthonormal_pair();
    (radius * cos * a + radius * sin * b + height * normal).normalize()
}

/// The camera as a receiver of light: the aperture disc and the image behind it.
#[derive(Debug, Clone, Copy)]
pub struct Sensor {
    pub camera: Camera,
    /// The aperture's radius a.
    pub aperture: f32,
    /// S: the area of one pixel on the image plane at distance 1.
    pub pixel_area: f32,
}

impl Sensor {
    pub fn new(scene: &Scene, aperture: f32) -> Sensor {
        let camera = Camera::new(&scene.camera, scene.image.width, scene.image.height);
        let pixel_area = (2.0 * camera.half_width / camera.width as f32)
            * (2.0 * camera.half_height / camera.height as f32);
        Sensor {
            camera,
            aperture,
            pixel_area,
        }
    }

    /// Does the ray from `origin` along the unit `direction` cross the
    /// aperture disc, coming from in front of the camera? If so, the distance
    /// along the ray to the disc's plane.
    pub fn crossing(&self, origin: Vec3, direction: Vec3) -> Option<f32> {
        let axis = self.camera.forward;
        let towards = direction.dot(axis);
        if towards >= 0.0 {
            return None; // parallel to the disc, or going away from the camera
        }
        let t = (self.camera.eye - origin).dot(axis) / towards;
        if t <= 0.0 {
            return None; // the disc's plane is behind: the origin is behind the camera
        }
        let from_centre = origin + t * direction - self.camera.eye;
        (from_centre.length_squared() <= self.aperture * self.aperture).then_some(t)
    }

    /// The pixel that light arriving in `direction` (a unit vector, from the
    /// scene towards the camera) lands on, as an index into the image's
    /// pixels, and cos θ_c of its angle to the camera's axis; `None` outside
    /// the field of view. It inverts [`Camera::ray_through`].
    pub fn pixel(&self, direction: Vec3) -> Option<(usize, f32)> {
        let c = &self.camera;
        let back = -direction; // the backward ray's direction
        let cos = back.dot(c.forward);
        if cos <= 0.0 {
            return None;
        }
        let s = back.dot(c.right) / cos / c.half_width;
        let t = back.dot(c.up) / cos / c.half_height;
        let px = (s + 1.0) * 0.5 * c.width as f32;
        let py = (1.0 - t) * 0.5 * c.height as f32;
        let inside = (0.0..c.width as f32).contains(&px) && (0.0..c.height as f32).contains(&py);
        // `as` rounds towards zero; px and py are not negative here.
        inside.then(|| (py as usize * c.width as usize + px as usize, cos))
    }
}

/// One photon's life: emitted, hits a surface, reflected diffusely; if it
/// then lands on the image, which pixel and its value without the common
/// factor 4π / (N·a²·S) (see the module's documentation):
/// ρ·C·I / (probability of its light · cos⁴θ_c).
fn trace_photon(
    scene: &Scene,
    sensor: &Sensor,
    emitters: &[Emitter],
    rng: &mut Pcg64Mcg,
    counts: &mut Counts,
) -> Option<(usize, Color)> {
    counts.emitted += 1;
    let light = pick(emitters, rng.random())?;
    let ray = Ray {
        origin: light.position,
        direction: uniform_sphere(rng.random(), rng.random()),
    };
    let world = &scene.objects[..];
    // The closest hit is, by construction, lit by the light without a blocker.
    let hit = world.closest_hit(&ray, 0.0, f32::INFINITY)?;
    counts.hit += 1;
    // Reflect to the side the photon came from.
    let facing = if hit.normal.dot(ray.direction) > 0.0 {
        -hit.normal
    } else {
        hit.normal
    };
    let out = cosine_hemisphere(facing, rng.random(), rng.random());
    let origin = offset_origin(&hit, out);
    let to_disc = sensor.crossing(origin, out)?;
    counts.aperture += 1;
    let (pixel, cos) = sensor.pixel(out)?;
    let reflected = Ray {
        origin,
        direction: out,
    };
    if world.any_hit(&reflected, 0.0, to_disc) {
        return None; // something stands between the surface and the camera
    }
    counts.on_image += 1;
    let albedo = scene.material(&scene.objects[hit.object]).color;
    Some((
        pixel,
        albedo * light.power / (light.probability * cos.powi(4)),
    ))
}

/// The seed of one chunk's generator.
fn chunk_seed(seed: u64, chunk: u64) -> u64 {
    seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ chunk
}

/// Traces the photons of one chunk; returns the pixels they landed on.
fn trace_chunk(
    scene: &Scene,
    sensor: &Sensor,
    emitters: &[Emitter],
    settings: &Settings,
    chunk: u64,
) -> (Vec<(usize, Color)>, Counts) {
    let mut rng = Pcg64Mcg::seed_from_u64(chunk_seed(settings.seed, chunk));
    let photons = CHUNK.min(settings.rays - chunk * CHUNK);
    let mut counts = Counts::default();
    let landed = (0..photons)
        .filter_map(|_| trace_photon(scene, sensor, emitters, &mut rng, &mut counts))
        .collect();
    (landed, counts)
}

/// Idea 1: emits `settings.rays` photons from the scene's point lights and
/// records those that reach the image through the aperture (see the module's
/// documentation for each one's value). `progress(photons)` is called as
/// chunks of photons finish.
///
/// The chunks run in parallel; their photons are added to the image in the
/// chunks' order, so the picture is the same bytes whatever the number of
/// threads. The scene should pass [`check_scene`].
pub fn trace_forward(scene: &Scene, settings: &Settings, progress: impl Fn(u64) + Sync) -> Forward {
    let sensor = Sensor::new(scene, settings.aperture);
    let emitters = emitters(scene);
    let (width, height) = (scene.image.width, scene.image.height);
    let mut sums = vec![[0f64; 3]; width as usize * height as usize];
    let mut counts = Counts::default();
    let chunks = settings.rays.div_ceil(CHUNK);
    for first in (0..chunks).step_by(BATCH as usize) {
        let batch: Vec<_> = (first..chunks.min(first + BATCH))
            .into_par_iter()
            .map(|chunk| {
                let traced = trace_chunk(scene, &sensor, &emitters, settings, chunk);
                progress(traced.1.emitted);
                traced
            })
            .collect();
        for (landed, chunk_counts) in batch {
            counts += chunk_counts;
            for (pixel, value) in landed {
                for (sum, v) in sums[pixel].iter_mut().zip(value.to_array()) {
                    *sum += f64::from(v);
                }
            }
        }
    }
    let a = f64::from(settings.aperture);
    let scale = 4.0 * std::f64::consts::PI
        / (settings.rays.max(1) as f64 * a * a * f64::from(sensor.pixel_area));
    let pixels = sums
        .iter()
        .map(|s| Color::new(s[0] as f32, s[1] as f32, s[2] as f32) * scale as f32)
        .map(|c| if c.is_finite() { c } else { Color::ZERO })
        .collect();
    Forward {
        image: Image {
            width,
            height,
            pixels,
        },
        counts,
    }
}

/// Idea 2, for comparison: chapter 4's picture of the scene, one ray per
/// pixel cast backwards from the eye.
pub fn backward_image(scene: &Scene, on_row: impl Fn() + Sync) -> Image {
    render_shadows(scene, Origin::Offset, on_row).0
}

/// What [`trace_forward`] converges to, computed backwards with chapter 4's
/// tracer: each pixel's value averaged over its area and over the aperture
/// disc (rays from points of the disc, in the directions of the pixel's
/// points), with `samples`² rays per pixel. Both averages are stratified:
/// the pixel is cut into `samples` × `samples` cells, the disc into as many
/// cells of equal area (rings × sectors), and each ray pairs one cell of
/// each, at random positions inside them, seeded by the pixel's index.
///
/// Its distance from [`backward_image`] is the part of the forward image's
/// error that no number of photons removes.
pub fn expected_image(
    scene: &Scene,
    aperture: f32,
    samples: u32,
    on_row: impl Fn() + Sync,
) -> Image {
    let (width, height) = (scene.image.width, scene.image.height);
    let camera = Camera::new(&scene.camera, width, height);
    let n = samples.max(1);
    let pixel = |x: u32, y: u32, stats: &mut Stats| {
        let index = u64::from(y) * u64::from(width) + u64::from(x);
        let mut rng = Pcg64Mcg::seed_from_u64(chunk_seed(0x5EED, index));
        // Which disc cell each pixel cell is paired with: a random permutation.
        let mut disc_cells: Vec<u32> = (0..n * n).collect();
        for i in (1..disc_cells.len()).rev() {
            disc_cells.swap(i, rng.random_range(0..=i));
        }
        let mut sum = Color::ZERO;
        for (cell, disc_cell) in (0..n * n).zip(disc_cells) {
            let px = x as f32 + ((cell % n) as f32 + rng.random::<f32>()) / n as f32;
            let py = y as f32 + ((cell / n) as f32 + rng.random::<f32>()) / n as f32;
            let ring = ((disc_cell / n) as f32 + rng.random::<f32>()) / n as f32;
            let sector = ((disc_cell % n) as f32 + rng.random::<f32>()) / n as f32;
            let r = aperture * ring.sqrt(); // equal areas: r² uniform
            let (sin, cos) = (std::f32::consts::TAU * sector).sin_cos();
            let ray = Ray {
                origin: camera.eye + r * (cos * camera.right + sin * camera.up),
                direction: camera.ray_through(px, py).direction,
            };
            sum += trace(scene, &ray, Origin::Offset, stats);
        }
        sum / (n * n) as f32
    };
    Image::render(width, height, pixel, on_row).0
}

/// How many photons make the noise `target`, from a run of `rays` photons
/// whose noise (RMSE against [`expected_image`]) was `noise`. Each photon is
/// independent of the others, so the variance of the picture falls as 1/N
/// and its RMSE as 1/√N: N·noise² is the same for every N.
pub fn rays_needed(rays: u64, noise: f64, target: f64) -> f64 {
    rays as f64 * (noise / target).powi(2)
}
