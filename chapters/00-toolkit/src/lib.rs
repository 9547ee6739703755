#![doc = include_str!("../README.md")]

pub mod image;
pub mod scene;
pub mod stats;

pub use glam::DVec3;
/// A point, direction or colour: three f32, x, y, z. It is glam's `Vec3A`,
/// which keeps them in one 16-byte SSE register, so that +, −, × and ÷ of
/// two vectors are one instruction each (what that bought is measured in
/// book/appendix/performance.md). Same methods as glam's `Vec3` (`new`,
/// `dot`, `cross`, `length`, `normalize`, ...). Compiler messages call it
/// `Vec3A`: write `Vec3::new(x, y, z)` (it has no `Vec3 { x, y, z }` form)
/// and use this `Vec3`, not glam's own.
pub use glam::Vec3A as Vec3;
pub use image::Image;
pub use scene::Scene;
pub use stats::Stats;

/// Linear RGB, one f32 per channel. Values above 1 are allowed while we add
/// light up; [`Image::to_rgb8`] clamps to [0, 1] when the picture is written.
pub type Color = Vec3;
