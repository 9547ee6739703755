//! The scene file as written: TOML, deserialised with serde into typed records,
//! then checked and turned into a [`Scene`].
//!
//! * `records.rs`: the records, one per table, strict about unknown fields;
//!   objects and lights are flat records (see there why).
//! * `values.rs`: the numbers, vectors and colours inside them, each a small
//!   type whose `Deserialize` checks it, so an error found there carries
//!   toml's span (the line) and serde_path_to_error's path (`objects[3].radius`).
//! * `validate.rs`: records to scene, for the checks that span fields.
//!
//! The rules themselves (image sizes, the camera, triangles with area) are
//! shared with the NFF reader in `scene/rules.rs`.

mod records;
mod validate;
mod values;

use super::{Scene, SceneError};
use records::SceneFile;
use validate::Checker;

/// Parses TOML text into a validated scene.
pub(super) fn parse(text: &str, file: &str) -> Result<Scene, SceneError> {
    let toml_error = |path: &str, e: &toml::de::Error| {
        SceneError::at(file, text, e.span(), path, e.message().trim_end())
    };
    let deserializer = toml::Deserializer::parse(text).map_err(|e| toml_error("", &e))?;
    let scene: SceneFile = serde_path_to_error::deserialize(deserializer).map_err(|e| {
        // `Spanned` shows up in serde's path as a private field: leave it out.
        let path = e
            .path()
            .to_string()
            .replace(".$__serde_spanned_private_value", "");
        let path = if path == "." { String::new() } else { path };
        toml_error(&path, e.inner())
    })?;
    scene.validate(&Checker { file, text })
}
