//! Reads scene files into the toolkit's checked [`Scene`]: the workbook's
//! TOML format (`file/`: its serde records, its self-checking values and
//! their validation into a scene), the SPD scenes' NFF (`nff/`) and the OBJ
//! meshes a TOML scene may name (`obj/`). Both formats check with one
//! set of rules (`rules.rs`), and every error names the file, the line, the
//! field and what would be valid (`error.rs`). Only regular files are read,
//! the scene and the files it names (`input.rs`): a pipe or a device would
//! never end. Scenes of millions of objects are read in parts
//! (`file/outline.rs`, `file/parts.rs`), and a scene too large for the
//! machine is refused before it is read, a mesh as it is read
//! (`file/memory.rs`).
//!
//! ```
//! let scene = scene_files::parse(r#"
//!     [camera]
//!     eye = [0, 0, 5]
//!     look_at = [0, 0, 0]
//!     up = [0, 1, 0]
//!     vfov = 45
//!     [image]
//!     width = 4
//!     height = 2
//! "#, "tiny.toml").unwrap();
//! assert_eq!(scene.image.width, 4);
//! ```

mod error;
mod file;
mod input;
pub mod nff;
pub mod obj;
mod rules;

use std::path::Path;

pub use error::SceneError;
pub use file::{BYTES_PER_OBJECT, MemoryLimit, write_sphere_cloud};
pub use rules::{MAX_IMAGE_SIDE, is_square_sample_count};

// The scene model the readers fill in, named here as the readers' modules
// name it (`super::Shape`, `crate::Scene`).
pub use ch00_toolkit::scene::*;
use ch00_toolkit::{Color, Vec3};

/// Reads and validates a scene file.
///
/// A file larger than the memory the machine has is refused before it
/// is read, and one whose scene would need more before its objects are
/// parsed (see [`parse_within`]).
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    load_within(path, MemoryLimit::of_machine().as_ref())
}

/// [`load`] within `limit`; `None` checks nothing.
pub fn load_within(
    path: impl AsRef<Path>,
    limit: Option<&MemoryLimit>,
) -> Result<Scene, SceneError> {
    let (text, name) = read_within(path.as_ref(), limit)?;
    parse_within(&text, &name, limit)
}

/// The text of the scene file at `path` and its name for messages. Only a
/// regular file is read (see `input.rs`: a pipe or a device would never
/// end), and one larger than `limit` is refused before it is read. Both
/// formats read their files this way.
fn read_within(path: &Path, limit: Option<&MemoryLimit>) -> Result<(String, String), SceneError> {
    use std::io::Read;
    let name = path.display().to_string();
    let (mut file, bytes) =
        input::open_regular(path).map_err(|why| SceneError::unreadable(&name, why))?;
    file::check_file_size(&name, bytes, limit)?;
    let mut text = String::with_capacity(usize::try_from(bytes).unwrap_or(0));
    (file.read_to_string(&mut text)).map_err(|e| SceneError::unreadable(&name, e))?;
    Ok((text, name))
}

/// Parses and validates scene text; `file_name` is used in error messages.
/// A scene that would need more memory than the machine has is refused
/// before its objects are parsed (see [`parse_within`]).
pub fn parse(text: &str, file_name: &str) -> Result<Scene, SceneError> {
    parse_within(text, file_name, MemoryLimit::of_machine().as_ref())
}

/// [`parse`], refusing a scene whose estimated memory (about
/// [`BYTES_PER_OBJECT`] per object) is more than `limit`; `None` checks
/// nothing.
pub fn parse_within(
    text: &str,
    file_name: &str,
    limit: Option<&MemoryLimit>,
) -> Result<Scene, SceneError> {
    file::parse(text, file_name, limit)
}
