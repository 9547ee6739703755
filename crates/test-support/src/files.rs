//! Every file under a folder, for tests that check what a command wrote or
//! left alone.

use std::path::{Path, PathBuf};

/// Every file under `dir` (not its folders), in no particular order; none
/// if `dir` cannot be read.
pub fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![dir.to_owned()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(folder).into_iter().flatten().flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else {
                files.push(path);
            }
        }
    }
    files
}
