//! Chapter 1: the ray's point, the camera's frame, the ray through a point
//! of the image.

use super::Probe;
use crate::Case;
use crate::draw::{Rng, number, point, show, unit, v3, whole};
use ch01_rays::toolkit::scene::CameraSpec;
use ch01_rays::{Camera, Ray};
use serde_json::json;

pub fn probes() -> Vec<Probe> {
    let probe = |id, case| Probe {
        id,
        chapter: "01-rays",
        tolerance: 1e-4,
        case,
    };
    vec![
        probe("ch01-at", at),
        probe("ch01-frame", frame),
        probe("ch01-ray-through", ray_through),
    ]
}

/// r(t) of a ray made field by field (not by `Ray::new`), t of either sign.
fn at(rng: &mut Rng) -> Option<Case> {
    let ray = Ray {
        origin: point(rng, 20.0),
        direction: unit(rng),
    };
    let t = number(rng, -30.0, 30.0);
    Some(Case {
        input: format!(
            "ray {} → {}, t = {t:?}",
            show(ray.origin),
            show(ray.direction)
        ),
        value: v3(ray.at(t)),
    })
}

/// `Camera::new` of a camera looking anywhere, up₀ a unit vector well off
/// the view, vfov in (10°, 150°), any picture size.
fn frame(rng: &mut Rng) -> Option<Case> {
    let eye = point(rng, 10.0);
    let look_at = eye + unit(rng) * number(rng, 0.5, 20.0);
    let up = unit(rng);
    let view = (look_at - eye).normalize();
    if view.dot(up).abs() > 0.9 {
        return None;
    }
    let spec = CameraSpec {
        eye,
        look_at,
        up,
        vfov_degrees: number(rng, 10.0, 150.0),
    };
    let (width, height) = (whole(rng, 8, 1200), whole(rng, 8, 1200));
    let c = Camera::new(&spec, width, height);
    Some(Case {
        input: format!(
            "eye {}, look_at {}, up {}, vfov {:?}°, {width}×{height}",
            show(eye),
            show(look_at),
            show(up),
            spec.vfov_degrees
        ),
        value: json!([
            v3(c.eye),
            v3(c.forward),
            v3(c.right),
            v3(c.up),
            c.half_width,
            c.half_height,
            c.width,
            c.height
        ]),
    })
}

/// `ray_through` of a camera made field by field (its frame not from the
/// student's `Camera::new`), at any point of the image. For an even width
/// the eye is up to 10⁴ from the origin, where a direction taken as P − eye
/// keeps P's rounding (about 10⁻³): the direction must not depend on where
/// the eye is.
fn ray_through(rng: &mut Rng) -> Option<Case> {
    let forward = unit(rng);
    let hint = unit(rng);
    if forward.dot(hint).abs() > 0.9 {
        return None;
    }
    let right = forward.cross(hint).normalize();
    let up = right.cross(forward);
    let (width, height) = (whole(rng, 8, 1200), whole(rng, 8, 1200));
    let far = if width % 2 == 0 { 1000.0 } else { 1.0 };
    let camera = Camera {
        eye: point(rng, 10.0) * far,
        right,
        up,
        forward,
        half_width: number(rng, 0.1, 3.0),
        half_height: number(rng, 0.1, 3.0),
        width,
        height,
    };
    let (px, py) = (
        number(rng, 0.0, width as f32),
        number(rng, 0.0, height as f32),
    );
    let ray = camera.ray_through(px, py);
    Some(Case {
        input: format!(
            "camera eye {}, forward {}, right {}, up {}, half size {:?} × {:?}, {width}×{height}; \
             position ({px:?}, {py:?})",
            show(camera.eye),
            show(forward),
            show(right),
            show(up),
            camera.half_width,
            camera.half_height
        ),
        value: json!([v3(ray.origin), v3(ray.direction)]),
    })
}
