//! Chapter 5: the mirror law, the mirror ray, the highlight, the recursion
//! (against a tracer whose answers the test fixes, and in two facing mirrors
//! whose pixels are known exactly), and the pictures.
//!
//! One test target (`cargo test -p ch05-reflection --test chapter05`), in
//! modules:
//!
//! * `mirror`: the mirror law (`reflect`) and the mirror ray (`mirror_ray`);
//! * `highlight`: the highlight, at the light's mirror image and off it;
//! * `recursion`: `trace` and `follow_secondary_rays` against a tracer whose
//!   answers the test fixes;
//! * `pictures`: two facing mirrors whose pixels are known exactly, the
//!   depth limit, and the snapshots;
//! * `ray_tree`: `--pixel X,Y --json`, mirror rays, their weights and the
//!   depth limit.
//!
//! Here: the mirror floor the first three share, and the rays that hit it.

/// The exercises later ones build on, checked first.
mod earlier;
mod highlight;
mod mirror;
mod pictures;
mod recursion;

/// `--pixel X,Y --json`: mirror rays, their weights, and the depth limit.
mod ray_tree;

use ch05_reflection::scene_files;
use ch05_reflection::toolkit::{Color, Scene, Vec3};
use ch05_reflection::{Ray, Surface, closest_hit};

/// A mirror floor (y = 0) under a blue-grey sky, shiny, in ambient light.
const FLOOR: &str = r#"
[camera]
eye = [0.0, 1.0, 3.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 4
height = 3
background = [0.2, 0.4, 0.6]

[materials.floor]
color = [0.5, 0.5, 0.5]
reflectance = [0.3, 0.3, 0.3]
specular = 0.5
shininess = 8.0

[[lights]]
type = "ambient"
color = [0.2, 0.2, 0.2]

[[objects]]
type = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0
material = "floor"
"#;

/// The [`FLOOR`] scene.
pub(crate) fn floor() -> Scene {
    scene_files::parse(FLOOR, "floor.toml").unwrap()
}

/// The point of the floor every test ray aims at: away from the origin, so
/// that its coordinates carry a rounding error that the offset must clear.
const SPOT: Vec3 = Vec3::new(0.3, 0.0, 0.7);

/// The ray that arrives at [`SPOT`] from above along `direction`.
pub(crate) fn arriving(direction: Vec3) -> Ray {
    let direction = direction.normalize();
    Ray {
        origin: SPOT - 2.0 * direction,
        direction,
    }
}

/// The floor as the ray sees it where it hits.
pub(crate) fn surface<'a>(scene: &'a Scene, ray: &Ray) -> Surface<'a> {
    let hit = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY).expect("the ray hits the floor");
    Surface::new(scene, hit, ray)
}

/// Whether two colours agree within 10⁻⁵ in every channel.
pub(crate) fn close(a: Color, b: Color) -> bool {
    (a - b).abs().max_element() < 1e-5
}

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
