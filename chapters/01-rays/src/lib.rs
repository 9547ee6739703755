#![doc = include_str!("../README.md")]

pub mod ray_tree;

pub use ch00_toolkit as toolkit;
use ch00_toolkit::scene::CameraSpec;
use ch00_toolkit::{Color, Image, Scene, Stats, Vec3};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
pub use workbench::{self, scene_files};

/// A ray: a half-line from its origin r0 along its direction rd, a unit
/// vector, so that the parameter t of its points is a distance (README,
/// section *The ray*).
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

    /// The point r(t) of the ray's line at parameter `t`: the point at
    /// distance `t` from the origin r0, in the direction rd (derived in the
    /// README, section *The ray*).
    ///
    /// * `t` is any finite number. t = 0 gives the origin itself; a negative
    ///   t gives a point behind the origin, on the same line (chapter 2 needs
    ///   those), so `t` is not clamped at 0.
    /// * `direction` already has length 1 ([`Ray::new`] made it so), so `t`
    ///   is a distance as it is: nothing to normalise here.
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
    /// The camera of a scene for an image of `width` × `height` pixels: the
    /// camera's frame and the size of its image plane, derived in the README,
    /// sections *The frame* and *The image plane*.
    ///
    /// `spec` (the scene's `[camera]`) gives the eye, the point `look_at` it
    /// looks at, the scene's up up₀ (`spec.up`, of length 1 but only a hint:
    /// it need not be at right angles to the view) and the vertical field of
    /// view vfov in **degrees** (`spec.vfov_degrees`, between 0 and 180): the
    /// angle between the rays through the middles of the picture's top and
    /// bottom edges. The scene file has already refused a camera whose
    /// look_at is its eye or whose up₀ lies along the view, so there is no
    /// degenerate case to handle.
    ///
    /// The camera returned has `eye`, `width` and `height` as given, and
    ///
    /// * `forward`, `right`, `up`: three vectors of length 1, each at right
    ///   angles to the other two. forward points from the eye towards
    ///   look_at. right points to the viewer's right, so the picture is not
    ///   mirrored (a camera looking down −z with y up has +x on its right).
    ///   up lies on up₀'s side of the picture, so it is not upside down.
    /// * `half_height`, `half_width`: half the height and half the width of
    ///   the image plane that lies one unit in front of the eye, along
    ///   forward. The rays through the middles of its top and bottom edges
    ///   are vfov apart, and its pixels are square: it is as many times
    ///   wider than high as the image is.
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

    /// The ray from the eye through the point of the image plane that lies
    /// at image position (`px`, `py`), derived in the README, section *The
    /// ray through a pixel*. It is cast backwards: from the eye into the
    /// scene, the opposite way to the light that makes the picture.
    ///
    /// * (`px`, `py`) is measured in pixels from the image's top-left corner,
    ///   x to the right and y **down**: (0, 0) is the top-left corner,
    ///   (width, height) the bottom-right one, and the centre of pixel (x, y)
    ///   is (x + 0.5, y + 0.5). The position is used as it is: no half pixel
    ///   is added here ([`Camera::primary_ray`] does that), and any position
    ///   inside the image will do, not only pixel centres (anti-aliasing casts
    ///   rays through other points of a pixel).
    /// * The image's corners go to the corners of the image plane, one unit
    ///   in front of the eye along forward, `half_width` to either side along
    ///   right and `half_height` above and below along up (the image's top is
    ///   on up's side). The image's centre goes to the plane's centre, straight
    ///   along forward, and positions in between go to the plane in proportion.
    /// * The ray starts at the eye, not on the image plane, and its direction
    ///   has length 1.
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
    let centre = (side == 1).then_some((x as f32 + 0.5, y as f32 + 0.5));
    let jittered = (side > 1).then(|| jittered_positions(x, y, samples, index));
    centre.into_iter().chain(jittered.into_iter().flatten())
}

/// [`sample_positions`] without the exception for one sample: N positions,
/// one at a random point of each cell of a √N × √N grid over pixel (x, y),
/// drawn from the random-number stream `stream`. One sample is a random
/// point of the whole pixel, so that the average of many renders with
/// different streams is the pixel's mean colour, whatever N.
pub fn jittered_positions(
    x: u32,
    y: u32,
    samples: u32,
    stream: u64,
) -> impl Iterator<Item = (f32, f32)> {
    let side = samples.isqrt().max(1); // samples is a square: N = side²
    let mut rng = Pcg64Mcg::seed_from_u64(stream);
    (0..side * side).map(move |cell| {
        let (i, j) = (cell % side, cell / side);
        let u: f32 = rng.random();
        let v: f32 = rng.random();
        (
            x as f32 + (i as f32 + u) / side as f32,
            y as f32 + (j as f32 + v) / side as f32,
        )
    })
}

/// The random-number stream of pixel `index` under `--seed seed`: the two
/// mixed into one number by SplitMix64's finaliser (Steele, Lea and Flood,
/// 2014), so that each (seed, pixel) pair gets a stream of its own, unlike
/// any seed's other pixels, and any thread draws the same numbers for it.
pub fn seeded_stream(seed: u64, index: u64) -> u64 {
    let mix = |mut z: u64| {
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    mix(mix(seed.wrapping_add(0x9e37_79b9_7f4a_7c15)) ^ index)
}

/// Renders a scene with the scene's number of primary rays per pixel
/// (`[image] samples`, one by default): `trace` gives the colour seen along
/// a ray, and a pixel is the average over its rays. Every later chapter
/// renders through this function and only brings a better `trace`.
///
/// Where the rays go: without a seed (`scene.image.seed`, `--seed`),
/// [`sample_positions`] of the pixel's index; with one,
/// [`jittered_positions`] of a [`seeded_stream`], so that renders with
/// different seeds are independent estimates of the same picture.
pub fn render(
    scene: &Scene,
    trace: impl Fn(&Ray, &mut Stats) -> Color + Sync,
    on_row: impl Fn() + Sync,
) -> (Image, Stats) {
    let (width, height) = (scene.image.width, scene.image.height);
    let samples = scene.image.samples.max(1);
    let camera = Camera::new(&scene.camera, width, height);
    let average = |positions: &mut dyn Iterator<Item = (f32, f32)>, stats: &mut Stats| {
        let mut sum = Color::ZERO;
        for (px, py) in positions {
            stats.primary += 1;
            sum += trace(&camera.ray_through(px, py), stats);
        }
        sum / samples as f32
    };
    let pixel = |x, y, stats: &mut Stats| {
        let index = y as u64 * width as u64 + x as u64;
        match scene.image.seed {
            // One ray, through the pixel's centre: no positions to draw
            // and no average to take.
            None if samples == 1 => {
                stats.primary += 1;
                trace(&camera.primary_ray(x, y), stats)
            }
            None => average(&mut sample_positions(x, y, samples, index), stats),
            Some(seed) => {
                let stream = seeded_stream(seed, index);
                average(&mut jittered_positions(x, y, samples, stream), stats)
            }
        }
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
