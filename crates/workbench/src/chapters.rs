//! The list of the workbook's chapters, read from `chapters/chapters.toml`.
//!
//! It is the one place that names the chapters, as rustlings' `info.toml`
//! names its exercises: the chapter binaries' messages, the effects each
//! chapter can simulate, `workbook progress`, `handout` and `verify`, and the
//! tests that walk every chapter's scenes all derive from it. The file is
//! built into the toolkit, so the list is the same wherever a binary runs.

use std::path::{Path, PathBuf};
use std::sync::LazyLock;

use serde::Deserialize;

use scene_files::{Effect, Effects};

/// The manifest's text, as the toolkit was built with it.
const MANIFEST: &str = include_str!("../../../chapters/chapters.toml");

/// One chapter (or companion crate) of the workbook.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChapterEntry {
    /// Its folder under `chapters/`, such as `03-lambert`.
    pub folder: String,
    /// What it teaches, in a few words.
    pub title: String,
    /// The effects it teaches its tracer.
    #[serde(default)]
    pub introduces: Vec<Effect>,
    /// Does the handout take exercises out of it?
    #[serde(default)]
    pub exercises: bool,
    /// The picture `workbook verify` checks a student's tracer against.
    pub verify: Option<VerifyReference>,
    /// A crate beside the chain of chapters rather than a step of it.
    #[serde(default)]
    pub companion: bool,
    /// The `[trace]` criteria it teaches its tracer to end paths by.
    #[serde(default)]
    pub ends_paths: Vec<Criterion>,
}

/// A `[trace]` criterion that ends a path of rays before it hits nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Criterion {
    /// More bounces than `max_depth` (chapter 5).
    MaxDepth,
    /// A path's weight below `min_weight` in every channel (chapter 7).
    MinWeight,
}

/// A chapter's reference picture for `workbook verify`.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VerifyReference {
    /// The snapshot's name: `snapshots/<folder>/<snapshot>.snap.png`.
    pub snapshot: String,
    /// What the chapter binary needs besides the size to render it.
    #[serde(default)]
    pub args: Vec<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Manifest {
    chapter: Vec<ChapterEntry>,
}

static CHAPTERS: LazyLock<Vec<ChapterEntry>> = LazyLock::new(|| {
    let manifest: Manifest = toml::from_str(MANIFEST)
        .unwrap_or_else(|e| panic!("chapters/chapters.toml is not a valid manifest: {e}"));
    manifest.chapter
});

/// Every entry of the manifest, in the order a student takes them.
pub fn all() -> &'static [ChapterEntry] {
    &CHAPTERS
}

/// The entry with this folder (`03-lambert`) or package (`ch03-lambert`).
pub fn find(name: &str) -> Option<&'static ChapterEntry> {
    all()
        .iter()
        .find(|c| c.folder == name || c.package() == name)
}

/// The chapter that introduces `effect`.
pub fn introducing(effect: Effect) -> &'static ChapterEntry {
    all()
        .iter()
        .find(|c| c.introduces.contains(&effect))
        .unwrap_or_else(|| panic!("no chapter in chapters/chapters.toml introduces {effect}"))
}

impl ChapterEntry {
    /// Its number: 3 for `03-lambert`.
    pub fn number(&self) -> u32 {
        self.folder[..2].parse().unwrap_or(0)
    }

    /// Its cargo package: `ch03-lambert`.
    pub fn package(&self) -> String {
        format!("ch{}", self.folder)
    }

    /// Its folder relative to the workspace root: `chapters/03-lambert`.
    pub fn path(&self) -> PathBuf {
        Path::new("chapters").join(&self.folder)
    }

    /// Its default scene, relative to the workspace root.
    pub fn default_scene_path(&self) -> String {
        format!("chapters/{}/scenes/default.toml", self.folder)
    }

    /// The effects its tracer can simulate: those that it and every chapter
    /// before it introduce. (A companion's are those of the chain up to it.)
    pub fn effects(&self) -> Effects {
        self.up_to_here()
            .flat_map(|c| c.introduces.iter().copied())
            .fold(Effects::NONE, Effects::with)
    }

    /// Does its tracer end paths by `criterion`: does it or a chapter
    /// before it teach it?
    pub fn ends_paths_by(&self, criterion: Criterion) -> bool {
        self.up_to_here().any(|c| c.ends_paths.contains(&criterion))
    }

    /// The entries of the manifest up to this one, itself included.
    fn up_to_here(&self) -> impl Iterator<Item = &'static ChapterEntry> {
        let upto = all()
            .iter()
            .position(|c| c == self)
            .expect("an entry of the manifest");
        all()[..=upto].iter()
    }

    /// The first chapter whose tracer ends paths by `criterion`.
    pub fn introducing_criterion(criterion: Criterion) -> &'static ChapterEntry {
        all()
            .iter()
            .find(|c| c.ends_paths.contains(&criterion))
            .unwrap_or_else(|| {
                panic!("no chapter in chapters/chapters.toml ends paths by {criterion:?}")
            })
    }
}

/// The scene files (`*.toml`) of every chapter's `scenes/` folder under the
/// workspace `root`, chapter by chapter in the manifest's order, each
/// chapter's sorted by name: the same order on every machine.
pub fn scene_files(root: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    for chapter in all() {
        let dir = root.join(chapter.path()).join("scenes");
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        let mut scenes: Vec<PathBuf> = entries
            .filter_map(|e| Some(e.ok()?.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        scenes.sort();
        files.extend(scenes);
    }
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_is_a_crate_folder_of_its_package() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for chapter in all() {
            let manifest = root.join(chapter.path()).join("Cargo.toml");
            let text = std::fs::read_to_string(&manifest)
                .unwrap_or_else(|e| panic!("{}: {e}", manifest.display()));
            let name = format!("name = \"{}\"", chapter.package());
            assert!(text.contains(&name), "{}: no {name}", manifest.display());
        }
    }

    #[test]
    fn every_chapter_folder_is_in_the_manifest() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../chapters");
        for entry in std::fs::read_dir(root).unwrap() {
            let path = entry.unwrap().path();
            if path.join("Cargo.toml").is_file() {
                let folder = path.file_name().unwrap().to_str().unwrap();
                assert!(find(folder).is_some(), "{folder} is not in chapters.toml");
            }
        }
    }

    #[test]
    fn the_chain_is_numbered_in_order_and_each_effect_has_one_chapter() {
        let chain: Vec<u32> = all()
            .iter()
            .filter(|c| !c.companion)
            .map(ChapterEntry::number)
            .collect();
        assert_eq!(chain, (0..chain.len() as u32).collect::<Vec<_>>());
        for effect in Effect::ALL {
            let count = all()
                .iter()
                .filter(|c| c.introduces.contains(&effect))
                .count();
            assert_eq!(count, 1, "{effect} is introduced by {count} chapters");
        }
    }

    #[test]
    fn a_chapter_simulates_what_it_and_the_chapters_before_introduce() {
        let effects = |folder| find(folder).unwrap().effects();
        assert!(effects("02-hits").is_empty());
        assert_eq!(
            effects("04-shadows"),
            Effects::of(&[Effect::Lambert, Effect::Spot, Effect::Shadows])
        );
        assert_eq!(effects("08-bvh"), Effects::ALL);
        assert_eq!(introducing(Effect::Refraction).folder, "06-refraction");
        assert_eq!(find("ch05-reflection").unwrap().number(), 5);
    }

    #[test]
    fn depth_ends_paths_from_chapter_5_and_weight_from_chapter_7() {
        let ends = |folder, criterion| find(folder).unwrap().ends_paths_by(criterion);
        assert!(!ends("04-shadows", Criterion::MaxDepth));
        assert!(!ends("04b-forward", Criterion::MaxDepth));
        assert!(ends("05-reflection", Criterion::MaxDepth));
        assert!(!ends("06-refraction", Criterion::MinWeight));
        assert!(ends("07-termination", Criterion::MinWeight));
        assert!(ends("08-bvh", Criterion::MaxDepth) && ends("08-bvh", Criterion::MinWeight));
    }
}
