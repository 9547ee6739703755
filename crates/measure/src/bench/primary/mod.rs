//! `bench --primary`: how many primary rays a second one thread traces with
//! raybook's BVH, and with Embree 4 on the same rays and the same triangles.
//!
//! The rays are the renderer's own: one per pixel, through its centre, from
//! chapter 1's [`Camera`](raybook::tracer::Camera) ([`primary_rays`]).
//! raybook traces them with `closest_hit` against [`primary_world`] (the
//! complete tracer's wide BVH, [`raybook::wide`]), on one thread
//! and on `--threads` threads; Embree traces them through the PyPI package
//! embreex, run by `crates/measure/src/bench/embree_primary.py` in a Python that can import
//! it, on one thread and in `--threads` processes at once. Only the tracing
//! is timed on either side: not making the rays, not building either BVH,
//! not passing the files. The two answers are compared ray by ray (hit or
//! miss, and the distance), so that the table shows they did the same work.
//!
//! Embree runs in `--threads` processes as well as on one thread, so that
//! both sides are compared under the same contention (why, and what it
//! changes: book/appendix/performance.md, "Primary rays against Embree").
//!
//! The parts:
//!
//! * `trace`: the primary rays, the world they are traced against, and
//!   tracing them on one thread or many;
//! * `embree`: running Embree's script, and reading its report and answers;
//! * `compare`: how far two tracers' answers to the same rays agree;
//! * `report`: timing each scene on both sides, and the report around the table;
//! * `rows`: the table, a row per scene.

mod compare;
mod embree;
mod report;
mod rows;
mod trace;

pub use compare::{Agreement, agreement};
pub use embree::PYTHON_VAR;
pub(super) use report::report;
pub use trace::{hit_distances, primary_rays, primary_world};
