//! raybook: the complete tracer of the workbook and its tools.
//!
//! The tracer is the most advanced chapter's; this crate adds the tools
//! around it (the `raybook` command line).

/// The complete tracer: the most advanced chapter, and the intersection
/// routines of chapter 2 that it is built on.
pub mod tracer {
    pub use ch02_hits::{
        hit_at, intersect, intersect_plane, intersect_sphere, intersect_triangle, sphere_point,
        sphere_roots, triangle_normal,
    };
    pub use ch07_termination::*;
}

pub use ch07_termination::toolkit;

pub mod accuracy;
pub mod bench;
pub mod handout;
pub mod nff;
pub mod progress;
pub mod verify;

use toolkit::cli::Chapter;
use toolkit::{Image, Scene, Stats};

/// The chapter whose tracer raybook renders with, and whose default scene is
/// the showcase.
pub const CHAPTER: Chapter = tracer::CHAPTER;

/// Renders a scene with the complete tracer and the scene's own criteria,
/// its rays traced against a BVH of the scene (chapter 8).
pub fn render(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    ch08_bvh::render_bvh(scene, tracer::Termination::of(scene), on_row)
}
