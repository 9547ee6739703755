//! The workbook's tools for students and maintainers: `progress` (where you
//! are), `verify` (your own tracer's picture against a chapter's reference)
//! and `handout` (a copy with the exercises taken out, and its checks).
//! All three read the workspace and its exercise regions (`workspace.rs`,
//! `regions.rs`).
//!
//! They depend on the toolkit and the workbench and on no chapter, so that
//! a student's edit to a chapter rebuilds the chapter and its tests, never
//! the tools.

pub use ch00_toolkit as toolkit;
pub use workbench;

pub mod handout;
pub mod hint;
pub mod progress;
pub mod regions;
pub mod verify;
pub mod workspace;
