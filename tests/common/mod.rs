//! What several integration tests share.

use std::path::PathBuf;

/// Every scene file of the chapters (`chapters/*/scenes/*.toml`), in the
/// order of chapters/chapters.toml, so that tests walk them in the same order
/// on every machine.
pub fn chapter_scene_files() -> Vec<PathBuf> {
    let paths = raybook::workbench::chapters::scene_files(env!("CARGO_MANIFEST_DIR").as_ref());
    assert!(paths.len() >= 12, "found only {paths:?}");
    paths
}
