#![doc = include_str!("../README.md")]

pub mod ray_tree;

pub use ch00_toolkit as toolkit;
use ch00_toolkit::scene::CameraSpec;
use ch00_toolkit::{Color, Image, Scene, Stats, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
pub use workbench::{self, scene_files};

/// A ray r(t) = r0 + t·rd with a unit direction, so t is a distance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    /// r0: where the ray starts.
    pub origin: Vec3,
    /// rd: where it goes, always of length 1.
    pub direction: Vec3,
}

impl Ray {
    /// A ray from `origin` along `direction` (any non-zero length; it is
    /// normalised so that `t` measures distance along the ray).
    pub fn new(origin: Vec3, direction: Vec3) -> Ray {
        Ray {
            origin,
            direction: direction.normalize(),
        }
    }

    /// The point r(t) = r0 + t·rd.
    pub fn at(&self, t: f32) -> Vec3 {
        // EXERCISE(ch01-at): the point of the ray at distance t from its origin
        crate::workbench::exercise::solution_begins("ch01-at");
        self.origin + t * self.direction
        // END EXERCISE
    }
}

/// A pinhole camera: every ray starts at the eye and passes through one
/// point of an image plane one unit in front of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    /// Unit vectors of the camera: `right` and `up` span the image plane,
    /// `forward` points from the eye to its centre.
    pub right: Vec3,
    pub up: Vec3,
    pub forward: Vec3,
    /// Half the width and height of the image plane at distance 1.
    pub half_width: f32,
    pub half_height: f32,
    pub width: u32,
    pub height: u32,
}

impl Camera {
    /// The camera of a scene for an image of `width` × `height` pixels: its
    /// frame and the size of its image plane (the README derives both).
    ///
    /// * forward = normalise(look_at − eye): from the eye to the centre of
    ///   the picture.
    /// * right = normalise(forward × up₀), with up₀ the scene's up: at right
    ///   angles to both, and to the viewer's right (x right, y up, looking
    ///   down −z is a right-handed frame, and (−z) × y = x).
    /// * up = right × forward: the scene's up made perpendicular to forward
    ///   (it is only a hint when the camera looks up or down), of length 1
    ///   because right and forward are unit vectors at right angles.
    /// * half_height = tan(vfov / 2): the ray to the top edge makes half the
    ///   vertical field of view with forward, on a plane at distance 1.
    /// * half_width = half_height · width / height, so pixels are square.
    pub fn new(spec: &CameraSpec, width: u32, height: u32) -> Camera {
        // EXERCISE(ch01-frame): the camera's unit frame (forward towards look_at, right to the viewer's right, up at right angles to both) and the image plane's half width and half height at distance 1, from the vertical field of view and the aspect ratio
        crate::workbench::exercise::solution_begins("ch01-frame");
        let forward = (spec.look_at - spec.eye).normalize();
        let right = forward.cross(spec.up).normalize();
        let up = right.cross(forward);
        let half_height = (spec.vfov_degrees.to_radians() / 2.0).tan();
        let half_width = half_height * width as f32 / height as f32;
        Camera {
            eye: spec.eye,
            right,
            up,
            forward,
            half_width,
            half_height,
            width,
            height,
        }
        // END EXERCISE
    }

    /// The ray through image position (px, py), measured in pixels from the
    /// top-left corner of the image (so the centre of pixel (x, y) is at
    /// (x + 0.5, y + 0.5)). It is cast backwards: from the eye into the
    /// scene, the opposite way to the light that makes the picture.
    pub fn ray_through(&self, px: f32, py: f32) -> Ray {
        // EXERCISE(ch01-ray-through): the ray from the eye through the point of the image plane at pixel position (px, py), the image's top-left corner being (0, 0) and its bottom-right (width, height)
        crate::workbench::exercise::solution_begins("ch01-ray-through");
        let u = (2.0 * px / self.width as f32 - 1.0) * self.half_width;
        let v = (1.0 - 2.0 * py / self.height as f32) * self.half_height;
        Ray::new(self.eye, self.forward + u * self.right + v * self.up)
        // END EXERCISE
    }

    /// The primary ray of pixel (x, y): through the pixel's centre.
    pub fn primary_ray(&self, x: u32, y: u32) -> Ray {
        self.ray_through(x as f32 + 0.5, y as f32 + 0.5)
    }
}

/// Where the rays of pixel (x, y) pass, in image coordinates: `samples` = N
/// positions, one in each cell of a √N × √N grid over the pixel, at a random
/// point inside its cell ("stratified" or "jittered" sampling: random enough
/// to break up the stair steps of edges, even enough to leave no gaps). One
/// sample is the pixel's centre. N is a square number (scene files are
/// checked for it).
///
/// The random numbers are seeded by the pixel's index `index`, so a pixel
/// gets the same rays whichever thread renders it, and the picture is the
/// same bytes every time.
pub fn sample_positions(
    x: u32,
    y: u32,
    samples: u32,
    index: u64,
) -> impl Iterator<Item = (f32, f32)> {
    let side = samples.isqrt(); // samples is a square: N = side²
    // One sample needs no random numbers: it is the centre.
    let mut rng = (side > 1).then(|| Pcg64Mcg::seed_from_u64(index));
    (0..side * side).map(move |cell| {
        let Some(rng) = rng.as_mut() else {
            return (x as f32 + 0.5, y as f32 + 0.5);
        };
        let (i, j) = (cell % side, cell / side);
        let u: f32 = rng.random();
        let v: f32 = rng.random();
        (
            x as f32 + (i as f32 + u) / side as f32,
            y as f32 + (j as f32 + v) / side as f32,
        )
    })
}

/// Renders a scene with the scene's number of primary rays per pixel
/// (`[image] samples`, one by default): `trace` gives the colour seen along
/// a ray, and a pixel is the average over its rays. Every later chapter
/// renders through this function and only brings a better `trace`.
pub fn render(
    scene: &Scene,
    trace: impl Fn(&Ray, &mut Stats) -> Color + Sync,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    let (width, height) = (scene.image.width, scene.image.height);
    let samples = scene.image.samples.max(1);
    let camera = Camera::new(&scene.camera, width, height);
    let pixel = |x, y, stats: &mut Stats| {
        if samples == 1 {
            // One ray, through the pixel's centre: no positions to draw
            // and no average to take.
            stats.primary += 1;
            return trace(&camera.primary_ray(x, y), stats);
        }
        let index = y as u64 * width as u64 + x as u64;
        let mut sum = Color::ZERO;
        for (px, py) in sample_positions(x, y, samples, index) {
            stats.primary += 1;
            sum += trace(&camera.ray_through(px, py), stats);
        }
        sum / samples as f32
    };
    Image::render(width, height, pixel, on_row)
}

/// What an empty world looks like: a sky that is white at the horizon and
/// blue overhead, and a grey ground below, chosen by the ray's direction.
pub fn sky(ray: &Ray) -> Color {
    let up = ray.direction.y;
    if up < 0.0 {
        return Color::new(0.35, 0.3, 0.25) * (1.0 + up);
    }
    let horizon = Color::new(1.0, 1.0, 1.0);
    let zenith = Color::new(0.3, 0.5, 0.9);
    horizon.lerp(zenith, up.sqrt())
}

/// Chapter 1's picture: what the camera sees of an empty world.
pub fn render_sky(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    render(scene, |ray, _| sky(ray), on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
