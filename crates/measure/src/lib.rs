//! The `raybook` command's measuring tools, around the complete tracer (the
//! `raybook` crate at the workspace root): `bench`, its speed against its
//! peers (POV-Ray, tinyraytracer and Embree, where they are installed), and
//! `accuracy`, what depth, threshold, samples per pixel and effects cost in
//! time against the error they leave; and `render`, which writes its picture
//! in the format that `-o` names (`output`).
//!
//! Both render with the tracer `raybook render` uses: [`raybook::render`],
//! the complete tracer against [`raybook::world`], the wide BVH.

pub mod accuracy;
pub mod bench;
pub mod output;
pub mod render;
