//! The OBJ statements, read one line at a time: vertices and normals are
//! kept, faces are cut into triangles at once and only the triangles with
//! area are kept. What they all take of the memory is counted as they come
//! (see [`Tally`]).

use std::io::BufRead;
use std::path::Path;

use super::face::{Corner, Counts, corner};
use super::lines::{Lines, number, shown, words};
use super::{Mesh, Tally};
use crate::rules::has_area;
use crate::{SceneError, Shape, Vec3};

/// Statements of OBJ that describe nothing a ray tracer draws from a mesh
/// (groups, smoothing, materials the scene replaces, free-form curves and
/// surfaces, display hints), and points and lines, which have no area.
/// (`mtllib` is looked at: see [`Reader::material_libraries`].)
const SKIPPED: &str = "o g s mg usemtl l p vp cstype deg bmat step curv curv2 surf parm \
    trim hole scrv sp end con bevel c_interp d_interp lod usemap maplib shadow_obj trace_obj \
    ctech stech call csh";

/// What has been read so far.
pub(super) struct Reader<'a, R> {
    file: &'a str,
    /// The OBJ file's folder, where its material libraries would be.
    dir: Option<&'a Path>,
    lines: Lines<R>,
    positions: Vec<Vec3>,
    /// Unit normals (zero where `vn` is zero).
    normals: Vec<Vec3>,
    /// Texture coordinates are not used, only counted, so that a face's
    /// `v/vt` corner can be checked.
    texcoords: usize,
    /// Faces read, with area or not.
    faces: usize,
    /// The corners of the current face (kept to reuse their memory).
    corners: Vec<Corner>,
    mesh: Mesh,
    tally: Tally<'a>,
}

impl<'a, R: BufRead> Reader<'a, R> {
    pub fn new(input: R, file: &'a str, dir: Option<&'a Path>, tally: Tally<'a>) -> Self {
        Reader {
            file,
            dir,
            lines: Lines::new(input),
            positions: Vec::new(),
            normals: Vec::new(),
            texcoords: 0,
            faces: 0,
            corners: Vec::new(),
            mesh: Mesh::default(),
            tally,
        }
    }

    /// Reads every line, then checks that the mesh has something to draw.
    pub fn read(mut self) -> Result<Mesh, SceneError> {
        loop {
            match self.lines.next() {
                Ok(true) => self
                    .statement()
                    .map_err(|(column, e)| self.error(column, e))?,
                Ok(false) => break,
                Err((column, e)) => return Err(self.error(column, e)),
            }
        }
        self.tally.settle().map_err(|e| self.error(1, e))?;
        if self.mesh.shapes.is_empty() {
            return Err(self.whole_file_error(self.nothing_to_draw()));
        }
        Ok(self.mesh)
    }

    /// Reads the statement on the current line; an error is a column and a
    /// message.
    fn statement(&mut self) -> Result<(), (usize, String)> {
        let line = std::mem::take(&mut self.lines.text);
        let result = self.statement_of(&line);
        self.lines.text = line;
        result
    }

    fn statement_of(&mut self, line: &[u8]) -> Result<(), (usize, String)> {
        let mut words = words(line);
        let Some((_, keyword)) = words.next() else {
            return Ok(()); // blank, or a comment
        };
        let end = line.len() + 1;
        match keyword {
            b"f" => self.face(words, end),
            b"v" => self.vertex(&Few::of(words), end),
            b"vn" => self.normal(&Few::of(words), end),
            b"vt" => self.texcoord(&Few::of(words), end),
            b"mtllib" => {
                self.material_libraries(words);
                Ok(())
            }
            _ if SKIPPED
                .split_ascii_whitespace()
                .any(|s| s.as_bytes() == keyword) =>
            {
                Ok(())
            }
            _ => Err((1, unknown(keyword))),
        }
    }

    /// `v x y z`, with an optional weight `w` or colour `r g b` (not used).
    fn vertex(&mut self, words: &Few, end: usize) -> Result<(), (usize, String)> {
        if ![3, 4, 6].contains(&words.count) {
            let message = format!(
                "expected `v x y z` (or with a weight w, or a colour r g b), found {} numbers",
                words.count
            );
            return Err((words.column(0, end), message));
        }
        let point = xyz(words.words())?;
        self.positions.push(point);
        self.tally.vertex().map_err(|e| (1, e))
    }

    /// `vn x y z`, kept as a unit vector (zero if it is zero).
    fn normal(&mut self, words: &Few, end: usize) -> Result<(), (usize, String)> {
        if words.count != 3 {
            let message = format!("expected `vn x y z`, found {} numbers", words.count);
            return Err((words.column(0, end), message));
        }
        let normal = xyz(words.words())?;
        self.normals.push(normal.normalize_or_zero());
        self.tally.vertex().map_err(|e| (1, e))
    }

    /// `vt u [v [w]]`: counted only.
    fn texcoord(&mut self, words: &Few, end: usize) -> Result<(), (usize, String)> {
        if !(1..=3).contains(&words.count) {
            let message = format!("expected `vt u [v [w]]`, found {} numbers", words.count);
            return Err((words.column(0, end), message));
        }
        for &(column, word) in words.words() {
            number(word).map_err(|e| (column, e))?;
        }
        self.texcoords += 1;
        Ok(())
    }

    /// `f` and three or more corners: cut into a fan of triangles from the
    /// first corner, of which those with area are kept.
    fn face<'l>(
        &mut self,
        words: impl Iterator<Item = (usize, &'l [u8])>,
        end: usize,
    ) -> Result<(), (usize, String)> {
        let counts = Counts {
            positions: self.positions.len(),
            texcoords: self.texcoords,
            normals: self.normals.len(),
        };
        self.corners.clear();
        let mut first = end;
        for (column, word) in words {
            first = first.min(column);
            self.corners
                .push(corner(word, &counts).map_err(|e| (column, e))?);
        }
        if self.corners.len() < 3 {
            let message = format!("a face has 3 corners or more, found {}", self.corners.len());
            return Err((first, message));
        }
        self.faces += 1;
        for i in 1..self.corners.len() - 1 {
            let triangle = [self.corners[0], self.corners[i], self.corners[i + 1]];
            if let Some(shape) = self.triangle(triangle) {
                self.mesh.shapes.push(shape);
                self.tally.triangle().map_err(|e| (1, e))?;
            }
        }
        Ok(())
    }

    /// The triangle of three corners, if it has area: smooth when each
    /// corner has a normal that is not zero.
    fn triangle(&self, corners: [Corner; 3]) -> Option<Shape> {
        let vertices = corners.map(|c| self.positions[c.position]);
        if !has_area(vertices) {
            return None;
        }
        let normals = corners.map(|c| c.normal.map(|n| self.normals[n]));
        Some(match normals {
            [Some(a), Some(b), Some(c)] if [a, b, c].iter().all(|n| n.length() > 0.5) => {
                Shape::SmoothTriangle {
                    vertices,
                    normals: [a, b, c],
                }
            }
            _ => Shape::Triangle { vertices },
        })
    }

    /// `mtllib` names material libraries. The scene gives the mesh its
    /// material, so they are not read; one that is missing is only noted.
    fn material_libraries<'l>(&mut self, names: impl Iterator<Item = (usize, &'l [u8])>) {
        let Some(dir) = self.dir else { return };
        for (_, name) in names {
            let name = shown(name);
            if !dir.join(&name).exists() {
                self.mesh.warnings.push(format!(
                    "{}:{}: the material library `{name}` is missing; the scene's material \
                     colours the mesh, so nothing is lost",
                    self.file, self.lines.number
                ));
            }
        }
    }

    /// Why a file that was read to its end has no triangle to draw.
    fn nothing_to_draw(&self) -> String {
        match (self.lines.number, self.faces) {
            (0, _) => "the OBJ file is empty: a mesh needs vertices (v lines) and faces \
                       (f lines)"
                .into(),
            (_, 0) => "the OBJ file has no faces (f lines), so no triangles".into(),
            (_, faces) => format!(
                "the OBJ file has no triangles with area: each of its {faces} faces has \
                 corners that coincide or lie on a line"
            ),
        }
    }

    /// An error at a column of the current line.
    fn error(&self, column: usize, message: String) -> SceneError {
        SceneError {
            file: self.file.to_owned(),
            line: Some(self.lines.number as u32),
            column: Some(column as u32),
            path: String::new(),
            message,
            source_line: Some(shown(&self.lines.text)),
        }
    }

    /// An error about the whole file.
    fn whole_file_error(&self, message: String) -> SceneError {
        SceneError::at(self.file, "", None, "", message)
    }
}

/// The words after a keyword of a line that has only a few (a vertex's,
/// a normal's), kept without allocating.
struct Few<'l> {
    first: [(usize, &'l [u8]); Few::ROOM],
    /// How many words there are, including those beyond the room.
    count: usize,
}

impl<'l> Few<'l> {
    const ROOM: usize = 7;

    fn of(words: impl Iterator<Item = (usize, &'l [u8])>) -> Few<'l> {
        let mut few = Few {
            first: [(0, &[][..]); Few::ROOM],
            count: 0,
        };
        for word in words {
            if let Some(room) = few.first.get_mut(few.count) {
                *room = word;
            }
            few.count += 1;
        }
        few
    }

    /// The words kept: all of them when there are no more than the room.
    fn words(&self) -> &[(usize, &'l [u8])] {
        &self.first[..self.count.min(Few::ROOM)]
    }

    /// The column of word `i`, or `end` if there is none.
    fn column(&self, i: usize, end: usize) -> usize {
        self.words().get(i).map_or(end, |w| w.0)
    }
}

/// Three coordinates `x y z` from the first three words.
fn xyz(words: &[(usize, &[u8])]) -> Result<Vec3, (usize, String)> {
    let mut xyz = [0.0; 3];
    for (x, &(column, word)) in xyz.iter_mut().zip(words) {
        *x = number(word).map_err(|e| (column, e))?;
    }
    for &(column, word) in &words[3..] {
        number(word).map_err(|e| (column, e))?;
    }
    Ok(Vec3::from_array(xyz))
}

/// Why a statement is refused that OBJ does not have.
fn unknown(keyword: &[u8]) -> String {
    format!(
        "unknown statement `{}`; a mesh is read from v, vn, vt and f lines (and # comments), \
         other OBJ statements are skipped",
        shown(keyword)
    )
}
