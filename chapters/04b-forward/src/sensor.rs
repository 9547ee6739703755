//! The camera as a receiver of light: where a photon crosses the aperture,
//! and which pixel its direction lands on.

use ch04_shadows::Camera;
use ch04_shadows::toolkit::{Scene, Vec3};

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
