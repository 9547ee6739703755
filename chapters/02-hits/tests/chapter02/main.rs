//! Chapter 2: the three intersections, the closest hit, and the pictures.
//!
//! One test target (`cargo test -p ch02-hits --test chapter02`), in modules:
//!
//! * `planes`: the plane, n·x + d = 0, its bounds and parallel rays;
//! * `spheres`: the lecture's quadratic, the stable roots, the nearest hit ahead;
//! * `triangles`: the lecture's plane-then-α-and-β test against the watertight one;
//! * `closest`: the closest hit among a scene's objects;
//! * `pictures`: the lecture's methods drawing the flat picture, the snapshots,
//!   and the snapshot tolerance on this chapter's own pictures;
//! * `cone`: the bonus primitive, cones and cylinders;
//! * `ray_tree`: `--pixel X,Y`, the ray tree of one pixel as text and JSON.

mod closest;
mod pictures;
mod planes;
mod spheres;
mod triangles;

/// The bonus cones and cylinders: exact cases, then random rays.
mod cone;
/// `--pixel X,Y`: the chapter binary prints a pixel's ray tree, text and JSON.
mod ray_tree;

use ch02_hits::toolkit::{Image, Scene};
use ch02_hits::{CHAPTER, Method, View, render_hits};

pub(crate) const INF: f32 = f32::INFINITY;

/// The chapter's default scene, at 160×120.
pub(crate) fn scene() -> Scene {
    CHAPTER.default_scene().unwrap().with_size(160, 120)
}

/// The picture of `scene` in `view`.
pub(crate) fn render(scene: &Scene, view: View) -> Image {
    render_hits(scene, view, Method::Lecture, || {}).0
}

/// The text's Rust listings, each a test, and the check that the text
/// shows them as they are here.
mod listings;
