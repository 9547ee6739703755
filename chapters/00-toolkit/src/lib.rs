#![doc = include_str!("../README.md")]

pub mod chapters;
pub mod cli;
pub mod compare;
pub mod exercise;
pub mod image;
pub mod ray_tree;
pub mod scene;
pub mod snapshot;
pub mod stats;

pub use glam::{DVec3, Vec3};
pub use image::Image;
pub use scene::{Scene, SceneError};
pub use stats::Stats;

/// Linear RGB, one f32 per channel. Values above 1 are allowed while we add
/// light up; [`Image::to_rgb8`] clamps to [0, 1] when the picture is written.
pub type Color = Vec3;
