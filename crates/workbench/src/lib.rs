//! What every chapter binary and test stands on, besides the lesson: the
//! command line (`cli/`), the snapshot checks of the tests (`snapshot.rs`,
//! with `compare.rs`: pictures within a tolerance and the diff picture),
//! the exercise markers (`exercise.rs`), the check that the chapters' Rust
//! listings equal their tests (`listings.rs`), the list of chapters
//! (`chapters.rs`, read from `chapters/chapters.toml`) and the ray tree's
//! data model and text (`ray_tree/`), which each chapter fills in.
//!
//! A student reads the lesson in `chapters/`; nothing here is a lesson.

pub mod chapters;
pub mod cli;
pub mod compare;
pub mod exercise;
pub mod listings;
pub mod pfm;
pub mod ray_tree;
pub mod snapshot;

pub use ch00_toolkit as toolkit;
pub use scene_files;
