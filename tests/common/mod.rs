//! What several integration tests share.

use std::path::PathBuf;

/// Every scene file of the chapters (`chapters/*/scenes/*.toml`), sorted, so
/// that tests walk them in the same order on every machine.
pub fn chapter_scene_files() -> Vec<PathBuf> {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/chapters");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(root)
        .unwrap()
        .flat_map(|chapter| std::fs::read_dir(chapter.unwrap().path().join("scenes")))
        .flatten()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 12, "found only {paths:?}");
    paths
}
