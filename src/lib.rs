//! raybook: the complete tracer of the workbook.
//!
//! The tracer is the most advanced chapter's ([`tracer`]), chosen once per
//! scene by the effects it calls for, and traced against a four-wide BVH
//! ([`wide`], chapter 8's tree collapsed). The `raybook` command that
//! renders with it and measures it lives in `crates/measure`; the
//! student's tools in `crates/workbook`.

pub use ch07_termination::{scene_files, toolkit, workbench};
/// NFF, the SPD scenes' format: read by the scene-files crate, beside TOML and OBJ.
pub use scene_files::nff;

pub mod tracer;
pub mod wide;

use toolkit::{Image, Scene, Stats};
use workbench::cli::Chapter;

/// The chapter whose tracer raybook renders with, and whose default scene is
/// the showcase.
pub const CHAPTER: Chapter = tracer::CHAPTER;

/// Renders a scene with the complete tracer and the scene's own criteria,
/// its rays traced against a four-wide BVH of the scene ([`wide`], chapter
/// 8's tree collapsed), by the tracer the scene calls for
/// ([`tracer::render_complete`]).
pub fn render(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    let bvh = world(scene);
    tracer::render_complete(scene, &bvh, tracer::Termination::of(scene), on_row)
}

/// What the complete tracer traces rays against: the four-wide BVH of the
/// scene's objects.
pub fn world(scene: &Scene) -> wide::WideBvh<'_> {
    wide::WideBvh::build(&scene.objects)
}
