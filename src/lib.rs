//! raybook: the complete tracer of the workbook and its tools.
//!
//! The tracer is the most advanced chapter's; this crate adds the tools
//! around it (the `raybook` command line).

pub use ch02_hits as tracer;
pub use ch02_hits::toolkit;

use toolkit::cli::Chapter;
use toolkit::{Image, Scene, Stats};

/// The chapter whose tracer raybook renders with, and whose default scene is
/// the showcase.
pub const CHAPTER: Chapter = tracer::CHAPTER;

/// Renders a scene with the complete tracer.
pub fn render(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    tracer::render_hits(scene, tracer::View::Flat, on_row)
}
