//! raybook: the complete tracer of the workbook.
//!
//! The tracer is the most advanced chapter's ([`tracer`]), chosen once per
//! scene by the effects it calls for, and traced against a wide BVH (eight
//! lanes with AVX2, else four: [`wide`], chapter 8's tree collapsed). The `raybook` command that
//! renders with it and measures it lives in `crates/measure`; the
//! student's tools in `crates/workbook`.

pub use ch07_termination::{scene_files, toolkit, workbench};
/// NFF, the SPD scenes' format: read by the scene-files crate, beside TOML and OBJ.
pub use scene_files::nff;

pub mod tracer;
pub mod wide;

use std::borrow::Cow;

use toolkit::scene::Shape;
use toolkit::{Image, Scene, Stats};
use workbench::cli::Chapter;

/// The chapter whose tracer raybook renders with, and whose default scene is
/// the showcase.
pub const CHAPTER: Chapter = tracer::CHAPTER;

/// Renders a scene with the complete tracer and the scene's own criteria,
/// in the camera's space ([`camera_relative`]), its rays traced against a
/// wide BVH of the scene ([`wide`], chapter 8's tree collapsed), by
/// the tracer the scene calls for ([`tracer::render_complete`]).
pub fn render(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    let scene = camera_relative(scene);
    let bvh = world(&scene);
    tracer::render_complete(&scene, &bvh, tracer::Termination::of(&scene), on_row)
}

/// How many times farther from the origin than from what it looks at the
/// eye may be before [`camera_relative`] moves the scene: 2⁴, so that the
/// coordinates near what the camera sees spend at most four of f32's 24 bits
/// on where the scene is.
pub const FAR: f32 = 16.0;

/// The scene moved so that the eye is at the origin, where the complete
/// tracer renders it if the eye is far from the origin (pbrt-v4's
/// "camera-world" space, for this reason).
///
/// An f32 has 24 bits: near 10⁵ its neighbouring values are 2⁻⁷ ≈ 0.008
/// apart, near 10⁶ 2⁻⁴. Every hit point, error bound e and shadow ray's
/// origin computed there is that coarse, though what the picture shows (a
/// ball of radius 1 seen from 5 away) needs far finer steps: chapter 4's
/// offsets grow with the coordinates, and the shading with them. Moved by
/// −eye, every coordinate is about as large as its distance from the eye,
/// as at the origin. The move is exact near the eye: x − eye for x within
/// a factor 2 of eye has no rounding (Sterbenz's lemma), so the scene is
/// the same scene, only its numbers smaller. A plane's d becomes d + n·eye,
/// worked out in f64: in f32, n·eye would be off by a step of eye's size.
///
/// A scene is moved only if its eye is more than [`FAR`] times farther from
/// the origin than from the point it looks at: elsewhere the move would
/// round coordinates it cannot make more exact, and a scene scaled by 10⁻³
/// would no longer give the same bytes as at its own size. Nor is a scene
/// near the origin copied.
pub fn camera_relative(scene: &Scene) -> Cow<'_, Scene> {
    let (eye, look_at) = (scene.camera.eye, scene.camera.look_at);
    if eye.abs().max_element() <= FAR * (look_at - eye).abs().max_element() {
        return Cow::Borrowed(scene);
    }
    let mut moved = scene.clone().translated(-eye);
    for (object, original) in moved.objects.iter_mut().zip(&scene.objects) {
        if let (Shape::Plane { offset, .. }, Shape::Plane { normal, offset: d }) =
            (&mut object.shape, original.shape)
        {
            *offset = (d as f64 + normal.as_dvec3().dot(eye.as_dvec3())) as f32;
        }
    }
    Cow::Owned(moved)
}

/// What the complete tracer traces rays against: the wide BVH of the
/// scene's objects (eight wide where the CPU has AVX2, else four).
pub fn world(scene: &Scene) -> wide::WideBvh<'_> {
    wide::WideBvh::build(&scene.objects)
}
