//! Triangle meshes from Wavefront OBJ files, read by a small reader of the
//! subset a scene's mesh needs.
//!
//! Why not the tobj crate, which read them before: it reads the whole file
//! and keeps every face before it makes the first triangle (a 160 MB file
//! of 20 million faces without area took 2.2 GiB and 6.3 s before it could
//! be refused), and its errors (`FaceVertexOutOfBounds`, ...) do not say on
//! which line. This reader reads one line at a time (`lines.rs`), keeps
//! only the triangles with area, counts the memory they take as they come
//! (a mesh too large for the machine is refused at the line where it
//! becomes so) and names the file, line and column of every error.
//!
//! | statement | read as |
//! | --- | --- |
//! | `v x y z` | a vertex; a weight `w` or a colour `r g b` after it is checked, not used |
//! | `vn x y z` | a vertex normal, made unit length |
//! | `vt u [v [w]]` | counted, so that faces can name them; not used |
//! | `f` with 3 or more corners `v`, `v/vt`, `v/vt/vn` or `v//vn` | a fan of triangles from the first corner (as tobj cut them); indices from 1, or negative: back from the face (`face.rs`) |
//! | `l`, `p`, and `o`, `g`, `s`, `usemtl`, the free-form geometry's statements | skipped: no area, or nothing the scene uses (the scene gives the material) |
//! | `mtllib` | skipped; a library that is missing is a warning |
//! | `#` | a comment, to the line's end |
//!
//! A triangle without area (corners that coincide or lie on a line, common
//! in real meshes) is left out; one whose three corners have normals is
//! smooth. CRLF line ends and a UTF-8 byte order mark are read as OBJ
//! allows them. Coordinates are finite f32 numbers; a statement OBJ does
//! not have, a face that names a vertex its file does not define above it,
//! or bytes that are not text, are refused where they are.

mod face;
mod lines;
mod reader;

use std::io::{BufRead, BufReader};
use std::path::Path;

use crate::file::memory::{BYTES_PER_VERTEX, MeshBudget, size};
use crate::{BYTES_PER_OBJECT, MemoryLimit, SceneError, Shape};
use reader::Reader;

/// The triangles of an OBJ file, and what was noticed while reading it.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Mesh {
    /// The triangles with area, in the file's order.
    pub shapes: Vec<Shape>,
    /// `file:line: what` for what is odd but harmless (a missing material
    /// library).
    pub warnings: Vec<String>,
}

/// Reads OBJ text from `input`; `file` names it in errors. A mesh that
/// would need more memory than `limit` is refused (`None` checks nothing).
pub fn read(
    input: impl BufRead,
    file: &str,
    limit: Option<&MemoryLimit>,
) -> Result<Mesh, SceneError> {
    let budget = limit.map(|limit| MeshBudget::new(limit, 0));
    let tally = Tally::new(budget.as_ref(), None);
    Reader::new(input, file, None, tally).read()
}

/// Reads the OBJ file at `path`, a regular file (see `input.rs`), its
/// triangles and vertices taking from `budget`.
pub(crate) fn load(path: &Path, budget: Option<&MeshBudget>) -> Result<Mesh, SceneError> {
    let name = path.display().to_string();
    let refuse = |why| {
        SceneError::at(
            &name,
            "",
            None,
            "",
            format!("cannot read the OBJ file: {why}"),
        )
    };
    let (file, bytes) = crate::input::open_regular(path).map_err(refuse)?;
    let tally = Tally::new(budget, Some(bytes));
    let input = BufReader::with_capacity(1 << 16, file);
    Reader::new(input, &name, path.parent(), tally).read()
}

/// A mesh's share of the memory, counted as it is read: [`BYTES_PER_OBJECT`]
/// a triangle with area, [`BYTES_PER_VERTEX`] a vertex or normal. It is taken
/// from the scene's budget a MiB at a time (the meshes of one scene are read
/// in parallel, and take from one budget).
pub(super) struct Tally<'a> {
    budget: Option<&'a MeshBudget>,
    /// The OBJ file's size, for messages.
    file_size: Option<u64>,
    /// Counted, not yet taken from the budget.
    pending: u64,
    triangles: u64,
    vertices: u64,
}

impl<'a> Tally<'a> {
    fn new(budget: Option<&'a MeshBudget>, file_size: Option<u64>) -> Tally<'a> {
        Tally {
            budget,
            file_size,
            pending: 0,
            triangles: 0,
            vertices: 0,
        }
    }

    /// Counts a vertex or a normal; a message if the memory is spent.
    pub fn vertex(&mut self) -> Result<(), String> {
        self.vertices += 1;
        self.add(BYTES_PER_VERTEX)
    }

    /// Counts a triangle with area; a message if the memory is spent.
    pub fn triangle(&mut self) -> Result<(), String> {
        self.triangles += 1;
        self.add(BYTES_PER_OBJECT)
    }

    fn add(&mut self, bytes: u64) -> Result<(), String> {
        self.pending += bytes;
        if self.pending < 1 << 20 {
            return Ok(());
        }
        self.settle()
    }

    /// Takes what is counted from the budget; a message if it is spent.
    pub fn settle(&mut self) -> Result<(), String> {
        let bytes = std::mem::take(&mut self.pending);
        let Some(budget) = self.budget else {
            return Ok(());
        };
        budget
            .take(bytes)
            .map_err(|need| self.too_large(need, budget.limit()))
    }

    /// Why a mesh that needs `need` bytes with the rest of its scene is
    /// refused.
    fn too_large(&self, need: u64, limit: &MemoryLimit) -> String {
        let file = match self.file_size {
            Some(bytes) => format!(" of the {} file", size(bytes)),
            None => String::new(),
        };
        format!(
            "the mesh is too large for the memory: by this line{file} it has {} triangles \
             with area and {} vertices and normals, and with the rest of the scene would need \
             about {} of memory to load and render (about {BYTES_PER_OBJECT} bytes a triangle), \
             but only {} is available ({}); render a smaller mesh, or free memory",
            self.triangles,
            self.vertices,
            size(need),
            size(limit.bytes),
            limit.source
        )
    }
}

#[cfg(test)]
mod tests;
