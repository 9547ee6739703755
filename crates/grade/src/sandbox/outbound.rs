//! What leaves a student's sandbox besides the probe's values (which come
//! on a pipe, `judging/probe.rs`): the failure pictures their tests wrote, read
//! beneath their build folder by `sandbox/beneath.rs` (a regular file, no link on
//! the way, bounded, within a time), then written here into the grader's
//! own report folder.

use std::path::Path;
use std::time::Duration;

/// The most a file copied out may hold: a failure picture is a few
/// hundred KiB.
pub const MAX_BYTES: u64 = 32 << 20;

/// The most a chapter's failure pictures may hold together. They stay on
/// the teacher's disk twice (the cache and the report), so without it a
/// student's tests could leave 32 pictures of 32 MiB a chapter there: 14
/// GiB for seven chapters, kept. A chapter has a few snapshot tests, and
/// the largest picture of the workbook is 30 KB (its failure picture,
/// three panels, a few hundred KB at most).
pub const MAX_CHAPTER_BYTES: u64 = 8 << 20;

/// The longest the pictures of one chapter may take to read.
pub const MAX_TIME: Duration = Duration::from_secs(10);

/// Writes `bytes`, read from a student's folder, to `to` in the grader's
/// own folder (atomically: a reader never sees half a picture).
pub fn write(to: &Path, bytes: &[u8]) -> Result<(), String> {
    if let Some(parent) = to.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    ch00_toolkit::image::write_atomically(to, bytes).map_err(|e| format!("{}: {e}", to.display()))
}
