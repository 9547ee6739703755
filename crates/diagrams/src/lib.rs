//! The chapters' diagrams, drawn from the chapters' own maths.
//!
//! `cargo run -p diagrams` writes every diagram to
//! `chapters/<chapter>/diagrams/<name>.svg`, where the chapter's README
//! shows it. Where a chapter's code gives the numbers (the camera's rays,
//! `refract`, the critical angle, the spot's cone, the BVH's boxes, the
//! ray tree of a glass pixel), the diagram asks that code. The tests check
//! that the committed files are what this program writes now, and that the
//! numbers a diagram shows are the ones its chapter's text states.

use std::path::{Path, PathBuf};

pub mod svg;
mod text;

mod ch01;
mod ch02;
mod ch03;
mod ch04;
mod ch04b;
mod ch05;
mod ch06;
mod ch06_tree;
mod ch08;

/// One diagram of one chapter.
pub struct Diagram {
    /// The chapter's folder, such as `06-refraction`.
    pub chapter: &'static str,
    /// The file's name without `.svg`.
    pub name: &'static str,
    /// The SVG file's text.
    pub svg: String,
    /// Texts the diagram shows that the chapter's README states word for
    /// word (in the README's notation, `d_i` for d with a subscript i).
    pub facts: Vec<String>,
}

impl Diagram {
    /// A diagram from what [`svg::Svg::finish`] made of it.
    pub fn new(chapter: &'static str, name: &'static str, drawn: svg::Drawn) -> Diagram {
        Diagram {
            chapter,
            name,
            svg: drawn.svg,
            facts: drawn.facts,
        }
    }

    /// Where the file goes, from the workspace's root.
    pub fn path(&self) -> PathBuf {
        Path::new("chapters")
            .join(self.chapter)
            .join("diagrams")
            .join(format!("{}.svg", self.name))
    }

    /// How the chapter's README refers to it: `](diagrams/NAME.svg)`.
    pub fn link(&self) -> String {
        format!("](diagrams/{}.svg)", self.name)
    }
}

/// Every diagram, chapter by chapter.
pub fn all() -> Vec<Diagram> {
    let mut diagrams = Vec::new();
    diagrams.extend(ch01::diagrams());
    diagrams.extend(ch02::diagrams());
    diagrams.extend(ch03::diagrams());
    diagrams.extend(ch04::diagrams());
    diagrams.extend(ch04b::diagrams());
    diagrams.extend(ch05::diagrams());
    diagrams.extend(ch06::diagrams());
    diagrams.push(ch06_tree::diagram());
    diagrams.extend(ch08::diagrams());
    diagrams
}

/// The workspace's root (this crate is `crates/diagrams` in it).
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}
