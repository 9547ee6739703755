//! The scene file as written: TOML, deserialised with serde into typed records,
//! then checked and turned into a [`Scene`].
//!
//! * `records.rs`: the records, one per table, strict about unknown fields;
//!   objects and lights are flat records (see there why).
//! * `values.rs`: the numbers, vectors and colours inside them, each a small
//!   type whose `Deserialize` checks it, so an error found there carries
//!   toml's span (the line) and serde_path_to_error's path (`objects[3].radius`).
//! * `validate.rs`: records to scene, for the checks that span fields.
//! * `outline.rs`: where the `[[objects]]` tables are, so that a large scene
//!   is parsed a batch of objects at a time, in parallel, in memory that
//!   grows with the objects alone (not with toml's view of the whole file);
//!   `parts.rs` parses it so, with the errors a parse of the whole file gives.
//! * `memory.rs`: the memory a scene needs, estimated before its objects are
//!   parsed, and refused when the machine does not have it; the bytes each
//!   object costs.
//! * `sphere_cloud.rs`: writes a scene of many spheres, to measure with.
//!
//! The rules themselves (image sizes, the camera, triangles with area) are
//! shared with the NFF reader in `scene/rules.rs`.

pub(crate) mod memory;
mod outline;
mod parts;
mod records;
mod sphere_cloud;
mod validate;
mod values;

use serde::Deserialize;

pub use memory::{BYTES_PER_OBJECT, MemoryLimit};
pub(crate) use memory::{MeshBudget, check_file_size, check_nff};
pub use sphere_cloud::write_sphere_cloud;

use super::{Scene, SceneError};
use outline::Outline;
use parts::{Failure, Stage, parse_in_parts};
use records::SceneFile;
use validate::Checker;

/// Parses TOML text into a validated scene, refusing one that would need
/// more memory than `limit`: before its objects are parsed, by their count;
/// then as its meshes are read, by their triangles.
pub(super) fn parse(
    text: &str,
    file: &str,
    limit: Option<&MemoryLimit>,
) -> Result<Scene, SceneError> {
    let outline = Outline::of(text);
    let need = memory::check(file, text, &outline, limit)?;
    let budget = limit.map(|limit| MeshBudget::new(limit, need));
    if outline.unusual || outline.batches.is_empty() {
        return parse_whole(text, file, budget.as_ref());
    }
    parse_in_parts(text, file, &outline, budget.as_ref())
}

/// Parses the whole text at once; its meshes take from `budget`.
fn parse_whole(text: &str, file: &str, budget: Option<&MeshBudget>) -> Result<Scene, SceneError> {
    let check = Checker::whole(file, text).within(budget);
    let scene: SceneFile = deserialize(text, &check, 0).map_err(|f| f.error)?;
    scene.validate(&check)
}

/// Deserialises `text` (a part of the file that `check` places), whose first
/// `[[objects]]` table is `objects[first]` of the file.
///
/// Keeping track of the path costs a quarter of the time, so it is done only
/// for text that has a mistake, in a second pass that finds it again.
fn deserialize<'a, T: Deserialize<'a>>(
    text: &'a str,
    check: &Checker,
    first: usize,
) -> Result<T, Failure> {
    let toml_error =
        |path: &str, e: &toml::de::Error| check.error_at(e.span(), path, e.message().trim_end());
    let parse = || {
        toml::Deserializer::parse(text).map_err(|e| Failure::new(Stage::Syntax, toml_error("", &e)))
    };
    if let Ok(value) = T::deserialize(parse()?) {
        return Ok(value);
    }
    serde_path_to_error::deserialize(parse()?).map_err(|e| {
        // `Spanned` shows up in serde's path as a private field: leave it out.
        let path = e
            .path()
            .to_string()
            .replace(".$__serde_spanned_private_value", "");
        let path = if path == "." { String::new() } else { path };
        let error = toml_error(&renumber(&path, first), e.inner());
        Failure::new(Stage::Types, error)
    })
}

/// `objects[i]...` as `objects[first + i]...`; other paths as they are.
fn renumber(path: &str, first: usize) -> String {
    let index = path.strip_prefix("objects[").and_then(|rest| {
        let (i, after) = rest.split_once(']')?;
        Some((i.parse::<usize>().ok()?, after))
    });
    match index {
        Some((i, after)) => format!("objects[{}]{after}", first + i),
        None => path.to_owned(),
    }
}

#[cfg(test)]
mod tests;
