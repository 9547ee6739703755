//! `workbook verify --tree CHAPTER X,Y MINE.json`: one pixel's ray tree,
//! written by a student's own tracer in any language in the schema of
//! book/appendix/ray-tree.md, against the reference's.
//!
//! The reference trees are committed beside the snapshots,
//! `snapshots/<chapter>/trees/default-X-Y.json`, for the pixels of
//! [`TREE_PIXELS`]: each is what `cargo run -p <chapter> -- --pixel X,Y
//! --json` prints for the chapter's default scene at its own size. They are
//! built into the workbook binary, so verify needs no chapter's code (a
//! handout's chapters are unsolved). crates/workbook/tests/verify/trees.rs
//! checks that they are current and rewrites them with
//! `RAYBOOK_WRITE_RAY_TREES=1 cargo test -p workbook --test verify reference_trees`.

pub mod compare;
pub mod difference;
pub mod facts;
pub mod schema;
pub mod tolerance;

use std::fmt;
use std::path::Path;

use serde_json::Value;

pub use compare::{Comparison, compare_trees};
pub use difference::{Difference, What};

use crate::workbench::chapters::{self, ChapterEntry};

/// A pixel with a reference tree, and what it shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TreePixel {
    pub x: u32,
    pub y: u32,
    pub shows: &'static str,
}

const fn at(x: u32, y: u32, shows: &'static str) -> TreePixel {
    TreePixel { x, y, shows }
}

/// The pixels of each chapter's default scene (at its own size: 320×240,
/// 640×480 for chapters 7 and 8) whose ray trees are committed: a miss, a
/// direct hit, a shadowed point, a mirror, glass, as the chapter has them.
/// Each lies well inside its object (its neighbours hit the same objects,
/// with the same lights), so that a correct tracer's last bits cannot make
/// it hit another. Documented in book/appendix/ray-tree.md.
pub const TREE_PIXELS: &[(&str, &[TreePixel])] = &[
    (
        "01-rays",
        &[
            at(
                0,
                0,
                "the top-left corner: the camera's frame and the pixel's centre",
            ),
            at(160, 120, "the middle of the picture"),
            at(319, 239, "the bottom-right corner"),
        ],
    ),
    (
        "02-hits",
        &[
            at(160, 20, "a miss: the background"),
            at(40, 200, "the floor, a plane"),
            at(90, 70, "the red sphere"),
            at(235, 140, "the yellow sphere"),
            at(230, 90, "the blue triangle"),
        ],
    ),
    (
        "03-lambert",
        &[
            at(160, 20, "a miss: the background"),
            at(
                80,
                120,
                "the red sphere, lit by the point light (outside the spot's cone)",
            ),
            at(
                260,
                170,
                "the floor inside the spot's inner cone, lit by the point light and the spot",
            ),
            at(
                200,
                190,
                "the floor in the spot's ramp, between its inner and outer cones",
            ),
        ],
    ),
    (
        "04-shadows",
        &[
            at(160, 20, "a miss: the background"),
            at(60, 110, "the red sphere, lit by the point light"),
            at(
                110,
                150,
                "the floor in the red sphere's shadow: the point light blocked",
            ),
            at(190, 170, "the floor lit by the point light and the spot"),
            at(
                180,
                120,
                "the blue triangle: the point light blocked, the spot behind it",
            ),
        ],
    ),
    (
        "05-reflection",
        &[
            at(160, 20, "a miss: the background"),
            at(50, 130, "the red sphere, matte: a direct hit"),
            at(300, 170, "the floor in shadow"),
            at(162, 128, "the mirror sphere, reflecting the floor"),
            at(
                270,
                150,
                "the blue sphere, a little reflective: its mirror ray sees the sky",
            ),
        ],
    ),
    (
        "06-refraction",
        &[
            at(160, 20, "a miss: the background"),
            at(215, 106, "the red sphere, lit by the point light"),
            at(222, 121, "the floor in the red sphere's shadow"),
            at(
                160,
                110,
                "the glass sphere: refraction, Fresnel and internal reflections, 8 bounces deep",
            ),
        ],
    ),
    (
        "07-termination",
        &[
            at(320, 40, "a miss: the background"),
            at(300, 300, "the red sphere, lit by the point light"),
            at(
                300,
                262,
                "the floor: the point light blocked, the spot free",
            ),
            at(180, 180, "the mirror sphere"),
            at(380, 220, "the glass sphere: a path ended by min_weight"),
        ],
    ),
    (
        "08-bvh",
        &[
            at(100, 400, "the floor, lit by both point lights"),
            at(560, 420, "the floor, light 2 blocked"),
            at(330, 160, "the sphereflake's big sphere, reflective"),
        ],
    ),
];

/// A chapter with reference trees, found by number (`6`, `06`), folder
/// (`06-refraction`) or package (`ch06-refraction`).
pub fn tree_chapter(name: &str) -> Option<(&'static ChapterEntry, &'static [TreePixel])> {
    let number = name.parse::<u32>().ok();
    TREE_PIXELS.iter().find_map(|&(folder, pixels)| {
        let chapter = chapters::all().iter().find(|c| c.folder == folder)?;
        let found =
            chapter.folder == name || chapter.package() == name || number == Some(chapter.number());
        found.then_some((chapter, pixels))
    })
}

/// Where the reference tree of pixel (x, y) of a chapter lives, under snapshots/.
pub fn tree_path(folder: &str, x: u32, y: u32) -> String {
    format!("{folder}/trees/default-{x}-{y}.json")
}

/// The reference tree of pixel (x, y) of a chapter, built into the binary.
pub fn reference_tree(folder: &str, x: u32, y: u32) -> Option<&'static str> {
    super::SNAPSHOTS
        .get_file(tree_path(folder, x, y))
        .and_then(|f| f.contents_utf8())
}

/// The reference's facts of every pixel of a chapter's picture (see
/// [`facts`]), built into the binary; None for a chapter without.
pub fn reference_facts(folder: &str) -> Option<&'static [u8]> {
    let verify = chapters::find(folder)?.verify.as_ref()?;
    super::SNAPSHOTS
        .get_file(facts::facts_path(folder, &verify.snapshot))
        .map(|f| f.contents())
}

/// Parses `X,Y`.
pub fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    text.split_once(',')
        .and_then(|(x, y)| Some((x.trim().parse().ok()?, y.trim().parse().ok()?)))
        .ok_or_else(|| format!("expected the pixel as X,Y, such as 160,110; found {text:?}"))
}

/// What `verify --tree` found.
pub struct TreeOutcome {
    pub chapter: &'static ChapterEntry,
    pub pixel: (u32, u32),
    pub comparison: Comparison,
}

impl TreeOutcome {
    pub fn passed(&self) -> bool {
        self.comparison.differences.is_empty()
    }
}

/// Compares the student's tree in `mine` with the reference tree of pixel
/// `pixel` of `chapter`, or with the tree in `against` if given (any
/// pixel, any scene, as a chapter binary writes it).
pub fn verify_tree(
    chapter: &str,
    pixel: (u32, u32),
    mine: &Path,
    against: Option<&Path>,
) -> Result<TreeOutcome, String> {
    let (entry, pixels) = tree_chapter(chapter).ok_or_else(|| {
        let names: Vec<&str> = TREE_PIXELS.iter().map(|(folder, _)| *folder).collect();
        format!(
            "no chapter {chapter:?}; the chapters with reference trees are {}",
            names.join(", ")
        )
    })?;
    let reference = match against {
        Some(path) => read(path)?,
        None => reference_tree(&entry.folder, pixel.0, pixel.1)
            .ok_or_else(|| no_reference(entry, pixels, pixel))?
            .to_owned(),
    };
    let reference: Value = serde_json::from_str(&reference)
        .map_err(|e| format!("the reference tree cannot be read: {e}"))?;
    let yours: Value = serde_json::from_str(&read(mine)?)
        .map_err(|e| format!("{} is not JSON: {e}", mine.display()))?;
    if let Some(theirs) = reference.get("pixel")
        && tolerance::compare(
            theirs,
            &Value::from(vec![pixel.0, pixel.1]),
            tolerance::Tolerance::Exact,
        )
        .is_err()
    {
        return Err(format!(
            "the tree given with --against is of pixel {}, not ({}, {})",
            tolerance::show(theirs),
            pixel.0,
            pixel.1
        ));
    }
    Ok(TreeOutcome {
        chapter: entry,
        pixel,
        comparison: compare_trees(&reference, &yours)?,
    })
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

/// The message for a pixel without a reference tree: the pixels that have one.
fn no_reference(chapter: &ChapterEntry, pixels: &[TreePixel], (x, y): (u32, u32)) -> String {
    let mut text = format!(
        "chapter {} has no reference tree of pixel ({x}, {y}); it has these, of its default scene at its own size:",
        chapter.folder
    );
    for p in pixels {
        text += &format!("\n  {},{}  {}", p.x, p.y, p.shows);
    }
    text += &format!(
        "\nor compare with a tree the workbook writes (where the chapter is solved):\n  \
         cargo run -q -p {} -- --pixel {x},{y} --json > reference.json\n  \
         cargo run -q -p workbook -- verify --tree {} {x},{y} MINE.json --against reference.json",
        chapter.package(),
        chapter.number()
    );
    text
}

/// The tolerances, for the messages.
pub const TOLERANCES: &str = "t, points and directions within 1e-4 relative (absolute below 1), \
     cosines within 1e-4, weights and colours within 1/255";

impl fmt::Display for TreeOutcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let c = &self.comparison;
        let (x, y) = self.pixel;
        let head = format!("chapter {}, pixel ({x}, {y})", self.chapter.folder);
        match c.differences.split_first() {
            None => write!(
                f,
                "PASS: {head}: your ray tree matches the reference's: {} ray{}, {} values compared",
                c.rays,
                if c.rays == 1 { "" } else { "s" },
                c.values
            )?,
            Some((first, rest)) => {
                write!(
                    f,
                    "FAIL: {head}: your ray tree differs from the reference's in {} of {} values compared\n\
                     first difference, at {first}",
                    c.differences.len(),
                    c.values
                )?;
                if !rest.is_empty() {
                    write!(
                        f,
                        "\n{} more after it, which may follow from it: fix the first, then verify again",
                        rest.len()
                    )?;
                }
            }
        }
        if !c.left_out.is_empty() {
            let fields: Vec<&str> = c.left_out.iter().map(String::as_str).collect();
            write!(
                f,
                "\nnot compared, as your tree leaves them out: {}",
                fields.join(", ")
            )?;
        }
        write!(f, "\ntolerances: {TOLERANCES}")
    }
}
