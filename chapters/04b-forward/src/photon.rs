//! One photon's life: emitted by a light, reflected once by a diffuse
//! surface, and, if it gets through the aperture, counted on a pixel. Below:
//! why its value is what it is.
//!
//! Before it casts rays backwards from the eye, the lecture asks whether we
//! could simply do what nature does: let the lights emit rays, let them
//! bounce, and colour the image where they arrive. This crate does exactly
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
//! directions, each carries the flux Φ = 4π·C·I / N. With several lights,
//! each photon first picks light k with the probability p_k, its share of
//! the total power, and carries Φ = 4π·C_k·I_k / (N·p_k): light k gets
//! N·p_k of the photons, and dividing by p_k gives each light its whole
//! power whatever its share (the README derives it). At its first hit the
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
//! [`expected_image`](crate::expected_image) computes backwards with chapter 4's tracer. It differs
//! from chapter 4's picture (one ray through each pixel's centre from the
//! exact eye) only where P changes within a pixel or within a radius of a:
//! at the edges of objects and shadows.
//!
//! *The pinhole limit.* A photon leaving x gets through the disc with a
//! probability of about cos θ_o · cos θ_c · a² / d², d the distance to the
//! eye, so the share of photons that make a picture falls as a², and each
//! carries a value growing as 1/a². For a true pinhole (a = 0) no photon ever
//! arrives: the expected picture is right, but the picture is black.

use rand::RngExt;
use rand_pcg::Pcg64Mcg;

use ch04_shadows::toolkit::scene::Light;
use ch04_shadows::toolkit::{Color, Scene, Vec3};
use ch04_shadows::{Ray, World, offset_origin};

use crate::sensor::Sensor;

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

/// A point light as a source of photons.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Emitter {
    position: Vec3,
    /// C·I: colour times intensity.
    power: Color,
    /// The chance that a photon comes from this light, in proportion to its
    /// power (the mean of its channels). Dividing by it keeps every light's
    /// share right however many photons it gets.
    probability: f32,
}

pub(crate) fn emitters(scene: &Scene) -> Vec<Emitter> {
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

/// One photon's life: emitted, hits a surface, reflected diffusely; if it
/// then lands on the image, which pixel and its value without the common
/// factor 4π / (N·a²·S) (see the module's documentation above):
/// ρ·C·I / (probability of its light · cos⁴θ_c).
pub(crate) fn trace_photon(
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
