//! Chapter 1: the camera's frame and image plane, and the way from a
//! pixel to a point of that plane. Both use the README's example camera
//! (at the origin, looking down −z, vfov = 90°, 4 × 2 pixels), built by the
//! chapter's own `Camera`.

use ch01_rays::toolkit::Vec3;
use ch01_rays::toolkit::scene::CameraSpec;
use ch01_rays::{Camera, Ray};
use glam::DVec2;

use crate::Diagram;
use crate::svg::{FRAME, HEADING, INK, LABEL, MEASURE, MUTED, NOTE, RAY, SURFACE, Svg, number, xy};

const CHAPTER: &str = "01-rays";

pub fn diagrams() -> Vec<Diagram> {
    let camera = example_camera();
    vec![
        Diagram::new(CHAPTER, "camera-frame", camera_frame(&camera)),
        Diagram::new(CHAPTER, "pixel-to-plane", pixel_to_plane(&camera)),
    ]
}

/// The README's example: the camera at the origin looking down −z with y
/// up, vfov = 90°, an image of 4 × 2 pixels.
fn example_camera() -> Camera {
    let spec = CameraSpec {
        eye: Vec3::ZERO,
        look_at: Vec3::new(0.0, 0.0, -1.0),
        up: Vec3::Y,
        vfov_degrees: 90.0,
    };
    Camera::new(&spec, 4, 2)
}

/// Where a ray meets the image plane, one unit along forward.
fn on_plane(camera: &Camera, ray: &Ray) -> Vec3 {
    ray.origin + ray.direction / ray.direction.dot(camera.forward)
}

/// The point's coordinates along right and up, measured from the plane's
/// centre: (u, v).
fn plane_uv(camera: &Camera, point: Vec3) -> DVec2 {
    let from_centre = point - (camera.eye + camera.forward);
    DVec2::new(
        from_centre.dot(camera.right) as f64,
        from_centre.dot(camera.up) as f64,
    )
}

/// The world as a cabinet drawing: x to the right and y up on the page,
/// and −z (the camera's forward) receding up and to the right.
struct Oblique {
    eye: DVec2,
    scale: f64,
    depth: DVec2,
}

impl Oblique {
    fn at(&self, p: Vec3) -> DVec2 {
        self.eye + xy(p.x as f64, -p.y as f64) * self.scale + self.depth * (-p.z as f64)
    }
}

/// The eye, its frame, the image plane one unit in front with its 4 × 2
/// pixels, and the ray through the centre of pixel (0, 0).
fn camera_frame(camera: &Camera) -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        370.0,
        "The camera's frame and its image plane",
        "The eye at the origin with its three unit vectors: forward towards the centre \
         of the image plane one unit away, right and up. The plane is half_width = 2 to \
         either side and half_height = 1 above and below (vfov = 90°, 4 × 2 pixels). \
         The ray from the eye through the centre of pixel (0, 0), the top-left one, \
         meets the plane at P = (−1.5, 0.5, −1).",
    );
    let view = Oblique {
        eye: xy(95.0, 300.0),
        scale: 62.0,
        depth: xy(230.0, -105.0),
    };
    let (eye, forward, right, up) = (camera.eye, camera.forward, camera.right, camera.up);
    let centre = eye + forward;
    let (hw, hh) = (camera.half_width, camera.half_height);
    let corner = |sx: f32, sy: f32| centre + sx * hw * right + sy * hh * up;
    let corners = [
        corner(-1.0, 1.0),
        corner(1.0, 1.0),
        corner(1.0, -1.0),
        corner(-1.0, -1.0),
    ];
    svg.text(
        xy(20.0, 28.0),
        "The camera: eye, frame and image plane",
        HEADING,
    );
    svg.fact(xy(20.0, 50.0), "vfov = 90°", NOTE);
    svg.fact(xy(100.0, 50.0), "4 × 2 pixels", NOTE);
    // The plane, its pixels, and pixel (0, 0) shaded.
    let page: Vec<DVec2> = corners.iter().map(|&c| view.at(c)).collect();
    svg.polygon(&page, "#eef3f8", SURFACE);
    let pixel = |x: f32, y: f32| view.at(on_plane(camera, &camera.ray_through(x, y)));
    svg.shade(
        &[
            pixel(0.0, 0.0),
            pixel(1.0, 0.0),
            pixel(1.0, 1.0),
            pixel(0.0, 1.0),
        ],
        RAY,
        0.18,
    );
    for x in 1..camera.width {
        let x = x as f32;
        svg.line(pixel(x, 0.0), pixel(x, 2.0), MUTED, 0.8);
    }
    svg.line(pixel(0.0, 1.0), pixel(4.0, 1.0), MUTED, 0.8);
    // The frustum's edges, faint.
    for &c in &corners {
        svg.dashed(view.at(eye), view.at(c), MUTED, 0.8);
    }
    // The frame at the eye.
    let e = view.at(eye);
    svg.arrow(e, view.at(centre), FRAME, 2.5);
    svg.arrow(e, view.at(eye + right), FRAME, 2.5);
    svg.arrow(e, view.at(eye + up), FRAME, 2.5);
    svg.text(
        view.at(eye + 0.5 * forward) + xy(2.0, 24.0),
        "forward",
        LABEL.colour(FRAME).bold(),
    );
    svg.text(
        view.at(eye + right) + xy(-6.0, 22.0),
        "right",
        LABEL.colour(FRAME).bold().middle(),
    );
    svg.text(
        view.at(eye + up) + xy(-8.0, -2.0),
        "up",
        LABEL.colour(FRAME).bold().end(),
    );
    svg.dot(e, INK);
    svg.text(e + xy(-8.0, 22.0), "eye", LABEL.bold());
    svg.dot(view.at(centre), FRAME);
    svg.text(
        view.at(centre) + xy(8.0, 18.0),
        "eye + forward",
        LABEL.colour(FRAME),
    );
    // The half sizes, along the plane's edges.
    let bottom_mid = view.at(centre - hh * up);
    let bottom_right = view.at(corners[2]);
    svg.line(
        bottom_mid + xy(0.0, 14.0),
        bottom_right + xy(0.0, 14.0),
        MEASURE,
        1.5,
    );
    svg.fact(
        (bottom_mid + bottom_right) / 2.0 + xy(0.0, 38.0),
        "half_width = 2",
        LABEL.colour(MEASURE).middle(),
    );
    let right_mid = view.at(centre + hw * right);
    let top_right = view.at(corners[1]);
    svg.line(
        right_mid + xy(14.0, 0.0),
        top_right + xy(14.0, 0.0),
        MEASURE,
        1.5,
    );
    svg.fact(
        (right_mid + top_right) / 2.0 + xy(22.0, 5.0),
        "half_height = 1",
        LABEL.colour(MEASURE),
    );
    // The ray through the centre of pixel (0, 0).
    let ray = camera.primary_ray(0, 0);
    let p = on_plane(camera, &ray);
    svg.arrow(e, view.at(eye + 1.3 * (p - eye)), RAY, 2.0);
    svg.dot(view.at(p), RAY);
    svg.text(
        view.at(p) + xy(-54.0, -40.0),
        "pixel (0, 0)",
        LABEL.colour(RAY).end(),
    );
    let point = format!("({}, {}, {})", num(p.x), num(p.y), num(p.z));
    svg.text_with_fact(
        view.at(p) + xy(-54.0, -20.0),
        &format!("P = {point}"),
        &point,
        LABEL.colour(RAY).end(),
    );
    svg.text(
        xy(20.0, 358.0),
        "The plane lies one unit along forward; right and up span it.",
        NOTE,
    );
    svg.finish()
}

fn num(x: f32) -> String {
    number(x as f64, 2)
}

/// The same 4 × 2 image twice: in pixels, from the top-left corner with y
/// down, and on the image plane, from its centre with v up; the centre of
/// pixel (0, 0) in both.
fn pixel_to_plane(camera: &Camera) -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        370.0,
        "From a pixel to a point of the image plane",
        "Left, the 4 × 2 image in pixels: (0, 0) is the top-left corner, x grows to the \
         right and y grows down, and pixel (0, 0) has its centre at (0.5, 0.5). Right, \
         the same rectangle on the image plane, in units from its centre: u along right \
         from −2 to 2, v along up from 1 at the top to −1 at the bottom. The centre of \
         pixel (0, 0) lands at u = −1.5, v = 0.5.",
    );
    let cell = 48.0;
    let left = xy(70.0, 80.0);
    let right = xy(355.0, 80.0);
    let (w, h) = (camera.width as f64, camera.height as f64);
    svg.text(xy(30.0, 30.0), "the image, in pixels", HEADING);
    svg.text(xy(345.0, 30.0), "the image plane, in units", HEADING);
    for origin in [left, right] {
        svg.shade(
            &[
                origin,
                origin + xy(cell, 0.0),
                origin + xy(cell, cell),
                origin + xy(0.0, cell),
            ],
            RAY,
            0.18,
        );
        svg.rect(origin, xy(w * cell, h * cell), "none", SURFACE, 1.5);
        for x in 1..camera.width {
            let x = origin.x + x as f64 * cell;
            svg.line(xy(x, origin.y), xy(x, origin.y + h * cell), MUTED, 0.8);
        }
        svg.line(
            origin + xy(0.0, cell),
            origin + xy(w * cell, cell),
            MUTED,
            0.8,
        );
    }
    pixel_axes(&mut svg, left, cell, camera);
    plane_axes(&mut svg, right, cell, camera);
    // Pixel (0, 0)'s centre, in both.
    let centre_px = left + xy(0.5, 0.5) * cell;
    svg.dot(centre_px, RAY);
    svg.text(
        left + xy(0.0, h * cell + 32.0),
        "centre of pixel (x, y):",
        NOTE,
    );
    svg.fact(
        left + xy(0.0, h * cell + 52.0),
        "(x + ½, y + ½)",
        LABEL.colour(RAY),
    );
    svg.text_with_fact(
        left + xy(0.0, h * cell + 74.0),
        "pixel (0, 0): (0.5, 0.5)",
        "(0.5, 0.5)",
        LABEL.colour(RAY),
    );
    let uv = plane_uv(camera, on_plane(camera, &camera.primary_ray(0, 0)));
    let centre_uv = right + xy(2.0 + uv.x, 1.0 - uv.y) * cell;
    svg.dot(centre_uv, RAY);
    svg.text(
        right + xy(0.0, h * cell + 32.0),
        "on the plane, it lands at",
        NOTE,
    );
    svg.text(
        right + xy(0.0, h * cell + 52.0),
        &format!("(u, v) = ({}, {})", number(uv.x, 2), number(uv.y, 2)),
        LABEL.colour(RAY),
    );
    let mid = left.y + h * cell / 2.0;
    svg.arrow(xy(282.0, mid), xy(322.0, mid), INK, 2.0);
    svg.text(
        xy(300.0, 320.0),
        "u: from −half_width (left) to half_width (right)",
        LABEL.middle(),
    );
    svg.text(
        xy(300.0, 346.0),
        "v: from half_height (top) to −half_height (bottom)",
        LABEL.middle(),
    );
    svg.finish()
}

/// The pixel coordinates: x along the top, y down the left side.
fn pixel_axes(svg: &mut Svg, origin: DVec2, cell: f64, camera: &Camera) {
    for x in 0..=camera.width {
        let at = origin + xy(x as f64 * cell, -8.0);
        svg.text(at, &x.to_string(), NOTE.middle());
    }
    for y in 0..=camera.height {
        let at = origin + xy(-8.0, y as f64 * cell + 5.0);
        svg.text(at, &y.to_string(), NOTE.end());
    }
    let top = origin + xy(camera.width as f64 * cell + 8.0, -12.0);
    svg.arrow(top, top + xy(22.0, 0.0), FRAME, 1.8);
    svg.text(top + xy(0.0, -8.0), "px", LABEL.colour(FRAME));
    let side = origin + xy(-30.0, 4.0);
    svg.arrow(side, side + xy(0.0, 26.0), FRAME, 1.8);
    svg.text(side + xy(-6.0, 20.0), "py", LABEL.colour(FRAME).end());
}

/// The plane's coordinates, through its centre: u to the right, v up.
fn plane_axes(svg: &mut Svg, origin: DVec2, cell: f64, camera: &Camera) {
    let (hw, hh) = (camera.half_width as f64, camera.half_height as f64);
    let centre = origin + xy(hw, hh) * cell;
    svg.arrow(
        centre - xy(hw * cell + 8.0, 0.0),
        centre + xy(hw * cell + 26.0, 0.0),
        FRAME,
        1.5,
    );
    svg.arrow(
        centre + xy(0.0, hh * cell + 8.0),
        centre - xy(0.0, hh * cell + 26.0),
        FRAME,
        1.5,
    );
    svg.text(
        centre + xy(hw * cell + 14.0, 20.0),
        "u",
        LABEL.colour(FRAME),
    );
    svg.text(
        centre + xy(8.0, -hh * cell - 14.0),
        "v",
        LABEL.colour(FRAME),
    );
    for u in [-hw, hw] {
        let at = centre + xy(u * cell, -hh * cell - 8.0);
        svg.text(at, &number(u, 2), NOTE.middle());
    }
    for v in [hh, -hh] {
        let at = centre + xy(-hw * cell - 8.0, -v * cell + 5.0);
        svg.text(at, &number(v, 2), NOTE.end());
    }
}
