#![doc = include_str!("../README.md")]

mod check;
mod compare;
mod film;
mod photon;
mod sensor;

pub use check::check_scene;
pub use compare::{Run, backward_image, expected_image, measure, rays_needed, strip};
pub use film::{CHUNK, Forward, Settings, trace_forward};
pub use photon::{Counts, cosine_hemisphere, uniform_sphere};
pub use sensor::Sensor;
