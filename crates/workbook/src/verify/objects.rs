//! Which object each pixel of a reference picture shows: a small text file
//! beside the reference (`snapshots/<chapter>/<snapshot>.objects.txt`), so
//! that `workbook verify` can say which objects a wrong region covers
//! without depending on a chapter's tracer.
//!
//! The maps are written and kept current by crates/workbook/tests/verify/object_maps.rs, which renders
//! them with chapter 2's closest hit (`RAYBOOK_WRITE_OBJECT_MAPS=1 cargo test -p workbook
//! --test verify` rewrites them).
//!
//! The format, one item a line (`#` starts a comment):
//!
//! ```text
//! size 160 120
//! object 0: plane, material floor
//! object 1: sphere, material red
//! row 0: -*160
//! row 1: -*70 1*20 -*70
//! ```
//!
//! Each row is a list of runs `OBJECT*COUNT`, `-` meaning no object.

/// What kind of shape an object is: the ray tree's names (`sphere`, `plane`,
/// `triangle`, `smooth_triangle`, `cone`), so that verify and `--pixel` agree.
pub use crate::workbench::ray_tree::shape_name;

use super::runs;

/// One object of a scene, as a student recognises it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ObjectName {
    /// Its shape's name ([`shape_name`]).
    pub shape: String,
    /// The name of its material in the scene file.
    pub material: String,
}

impl std::fmt::Display for ObjectName {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}, material {}", self.shape, self.material)
    }
}

/// For each pixel of a reference picture, the object its primary ray hits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ObjectMap {
    pub width: u32,
    pub height: u32,
    /// The scene's objects, by index (the order of its `[[objects]]`).
    pub objects: Vec<ObjectName>,
    /// Row by row from the top left: the index of the object hit first by
    /// the ray through the pixel's centre, or `None` (the background).
    pub pixels: Vec<Option<usize>>,
}

impl ObjectMap {
    /// The object seen at pixel (x, y), if any.
    pub fn at(&self, x: u32, y: u32) -> Option<usize> {
        self.pixels[(y * self.width + x) as usize]
    }

    /// The map as text (the format of this module's documentation), with a
    /// header saying what it is and how to regenerate it.
    pub fn to_text(&self, picture: &str) -> String {
        let mut text = format!(
            "# Which object each pixel of {picture} shows: the first one hit by the ray\n\
             # through the pixel's centre, or - for none. Objects are numbered from 0 in\n\
             # the order of the scene file's [[objects]]. Rows are runs OBJECT*COUNT.\n\
             # Written by crates/workbook/tests/verify/object_maps.rs: RAYBOOK_WRITE_OBJECT_MAPS=1 cargo test -p workbook --test verify\n\
             size {} {}\n",
            self.width, self.height
        );
        for (index, object) in self.objects.iter().enumerate() {
            text += &format!("object {index}: {object}\n");
        }
        for (y, row) in self.pixels.chunks(self.width as usize).enumerate() {
            text += &format!("row {y}: {}\n", row_text(row));
        }
        text
    }

    /// Reads a map written by [`ObjectMap::to_text`].
    pub fn parse(text: &str) -> Result<ObjectMap, String> {
        let mut map = ObjectMap {
            width: 0,
            height: 0,
            objects: Vec::new(),
            pixels: Vec::new(),
        };
        for line in text
            .lines()
            .filter(|l| !l.is_empty() && !l.starts_with('#'))
        {
            let (key, rest) = line.split_once(' ').unwrap_or((line, ""));
            match key {
                "size" => (map.width, map.height) = runs::parse_size(rest)?,
                "object" => map.objects.push(parse_object(rest)?),
                "row" => map.pixels.extend(parse_row(rest, map.width)?),
                _ => return Err(format!("unknown line {line:?}")),
            }
        }
        let size = (map.width, map.height);
        runs::check_map(&map.pixels, size, map.objects.len(), "object")?;
        Ok(map)
    }
}

/// A row as runs of the same object: `-*3 0*5`.
fn row_text(row: &[Option<usize>]) -> String {
    runs::encode(row, |object| match object {
        Some(index) => index.to_string(),
        None => "-".into(),
    })
}

/// `3: sphere, material red` (the index must be the next one).
fn parse_object(text: &str) -> Result<ObjectName, String> {
    let bad = || format!("bad object {text:?}");
    let (_, name) = text.split_once(": ").ok_or_else(bad)?;
    let (shape, material) = name.split_once(", material ").ok_or_else(bad)?;
    Ok(ObjectName {
        shape: shape.to_owned(),
        material: material.to_owned(),
    })
}

/// `7: -*3 0*157`: the runs of one row, which must add up to `width`.
fn parse_row(text: &str, width: u32) -> Result<Vec<Option<usize>>, String> {
    runs::decode(text, width, |object| match object {
        "-" => Some(None),
        index => index.parse().ok().map(Some),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small_map() -> ObjectMap {
        ObjectMap {
            width: 3,
            height: 2,
            objects: vec![ObjectName {
                shape: "smooth triangle".into(),
                material: "dark blue".into(),
            }],
            pixels: vec![None, Some(0), Some(0), Some(0), Some(0), Some(0)],
        }
    }

    #[test]
    fn a_map_reads_back_as_written() {
        let text = small_map().to_text("x.png");
        assert!(text.contains("object 0: smooth triangle, material dark blue\n"));
        assert!(text.contains("row 0: -*1 0*2\nrow 1: 0*3\n"), "{text}");
        assert_eq!(ObjectMap::parse(&text), Ok(small_map()));
    }

    #[test]
    fn a_damaged_map_is_refused() {
        let text = small_map().to_text("x.png");
        for (from, to) in [("0*3", "0*2"), ("0*3", "1*3"), ("size 3 2", "size 3 3")] {
            let damaged = text.replace(from, to);
            assert!(ObjectMap::parse(&damaged).is_err(), "{damaged}");
        }
    }
}
