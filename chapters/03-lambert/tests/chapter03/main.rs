//! Chapter 3: the cosine law, the spot cone, ambient light, and the picture.
//!
//! One test target (`cargo test -p ch03-lambert --test chapter03`), in modules:
//!
//! * `lambert`: the cosine law, on a lit sphere and a floor seen from either side;
//! * `direct_light`: the lights added up, ambient light, and which lights
//!   `visible` is asked about;
//! * `spot`: the spot light's smooth cone, and nothing lit outside it;
//! * `pictures`: the whole picture in ambient light, clamping, and the snapshot;
//! * `cli`: the chapter binary on a later chapter's scene or option, and on a bad scene.
//!
//! Here: the scenes the modules share, a lit sphere and a floor seen from above.

mod direct_light;
mod lambert;
mod pictures;
mod spot;

/// The chapter binary's command line: later chapters' scenes and options, a bad scene.
mod cli;

use ch03_lambert::scene_files;
use ch03_lambert::toolkit::{Color, Image, Scene, Vec3};
use ch03_lambert::{Ray, render_lambert};

/// The chapter's picture of `scene`.
pub(crate) fn render(scene: &Scene) -> Image {
    render_lambert(scene, || {}).0
}

/// A unit sphere at the origin seen from +z, lit by one point light placed
/// `degrees` away from the normal of the sphere's front point (0, 0, 1), at
/// distance 10 from that point.
pub(crate) fn sphere_lit_at(degrees: f32) -> Scene {
    let (s, c) = degrees.to_radians().sin_cos();
    let light = Vec3::new(0.0, 0.0, 1.0) + 10.0 * Vec3::new(s, 0.0, c);
    let text = format!(
        r#"
        [camera]
        eye = [0, 0, 5]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 41
        height = 41
        [materials.white]
        color = [0.9, 0.9, 0.9]
        [[lights]]
        type = "point"
        position = [{}, {}, {}]
        intensity = 50
        [[objects]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "white"
        "#,
        light.x, light.y, light.z
    );
    scene_files::parse(&text, "cosine.toml").unwrap()
}

/// A floor of albedo (0.5, 0.6, 0.7) seen from straight above, with the
/// scene's `lights` (TOML), and the ray that sees its point (0, 0, 0).
pub(crate) fn floor_with(lights: &str) -> (Scene, Ray) {
    floor_facing(1.0, lights)
}

/// The same floor, its plane y = 0 written with the normal (0, `up`, 0).
pub(crate) fn floor_facing(up: f32, lights: &str) -> (Scene, Ray) {
    let text = format!(
        r#"
        [camera]
        eye = [0, 5, 0.001]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 9
        height = 9
        [materials.floor]
        color = [0.5, 0.6, 0.7]
        [[objects]]
        type = "plane"
        normal = [0, {up}, 0]
        offset = 0
        material = "floor"
        {lights}
        "#
    );
    let scene = scene_files::parse(&text, "floor.toml").unwrap();
    (scene, Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::NEG_Y))
}

/// The floor's albedo.
pub(crate) const ALBEDO: Vec3 = Vec3::new(0.5, 0.6, 0.7);

/// Whether two colours agree within 10⁻⁵ in every channel.
pub(crate) fn close(a: Color, b: Color) -> bool {
    (a - b).abs().max_element() < 1e-5
}

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
