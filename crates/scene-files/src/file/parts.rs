//! A scene file parsed in parts (see `outline.rs`): first the head (camera,
//! image, materials, lights), then the `[[objects]]` tables in batches, in
//! parallel, each batch's records turned into objects and dropped before the
//! next. Memory then grows with the objects, not with toml's spanned values
//! of the whole file.
//!
//! The errors are the ones a parse of the whole file gives: the spans of a
//! part are placed back in the file (its lines), and `objects[i]` counts the
//! objects of the whole file. Where a file has several mistakes, the one
//! reported is chosen as the whole file's parse would choose it: syntax
//! before types before rules, and then the first in the file (for rules:
//! the camera, then the objects, then the lights).

use rayon::prelude::*;
use serde::Deserialize;
use toml::Spanned;

use super::outline::{Batch, Outline};
use super::records::{ObjectFile, SceneFile};
use super::validate::{Checker, objects_from_records};
use super::{MeshBudget, deserialize, parse_whole};
use crate::{Object, Scene, SceneError};

/// Which step of reading a file found a mistake, in the order of the steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Stage {
    /// Not TOML (toml's parser).
    Syntax,
    /// TOML, but not the records' types (serde).
    Types,
    /// Records that break a rule across fields (`validate.rs`).
    Rules,
}

/// A mistake and the step that found it.
pub(super) struct Failure {
    pub stage: Stage,
    pub error: SceneError,
}

impl Failure {
    pub fn new(stage: Stage, error: SceneError) -> Failure {
        Failure { stage, error }
    }

    /// Of two failures, the one a parse of the whole file would report.
    fn or(self, other: Failure) -> Failure {
        if other.rank() < self.rank() {
            other
        } else {
            self
        }
    }

    /// Of two failures, the one with the smaller rank is reported.
    fn rank(&self) -> (Stage, u8, u32, u32) {
        let e = &self.error;
        // Rules are checked for the camera, then objects, then lights.
        let group = match self.stage {
            Stage::Rules if e.path.starts_with("camera") => 0,
            Stage::Rules if e.path.starts_with("lights") => 2,
            _ => 1,
        };
        // Mistakes without a place (a missing table) show up last.
        let line = e.line.unwrap_or(u32::MAX);
        (self.stage, group, line, e.column.unwrap_or(u32::MAX))
    }
}

/// Parses the head, then the batches of objects; see the module's text.
pub(super) fn parse_in_parts(
    text: &str,
    file: &str,
    outline: &Outline,
    budget: Option<&MeshBudget>,
) -> Result<Scene, SceneError> {
    let head_text: String = outline.head.iter().map(|r| &text[r.clone()]).collect();
    let check = Checker::of_ranges(file, text, &outline.head);
    let head: Result<SceneFile, Failure> = deserialize(&head_text, &check, 0);
    if head.as_ref().is_ok_and(|h| !h.objects.is_empty()) {
        return parse_whole(text, file, budget); // objects in two ways: let toml say what is wrong
    }
    let names: Vec<&String> = head
        .as_ref()
        .map_or(vec![], |h| h.materials.keys().collect());
    let objects = parse_batches(text, file, outline, &names, budget);
    let head =
        head.and_then(|h| (h.validate(&check)).map_err(|error| Failure::new(Stage::Rules, error)));
    match (head, objects) {
        (Ok(scene), Ok(objects)) => Ok(Scene { objects, ..scene }),
        (Err(a), Err(b)) => Err(a.or(b).error),
        (Err(failure), _) | (_, Err(failure)) => Err(failure.error),
    }
}

/// Batches parsed at once, on all cores. Their objects join the scene's
/// list before the next batches are parsed, so that the lists of only a few
/// batches are alive at a time (and the memory they held is used again).
const GROUP: usize = 32;

/// The objects of every batch, in order; or the failure to report.
fn parse_batches(
    text: &str,
    file: &str,
    outline: &Outline,
    names: &[&String],
    budget: Option<&MeshBudget>,
) -> Result<Vec<Object>, Failure> {
    let mut objects = Vec::with_capacity(outline.objects);
    let mut failure: Option<Failure> = None;
    for group in outline.batches.chunks(GROUP) {
        let parsed: Vec<_> = (group.par_iter())
            .map(|batch| parse_batch(text, file, batch, names, budget))
            .collect();
        for batch in parsed {
            match batch {
                Ok(batch) => objects.extend(batch),
                Err(f) => {
                    failure = Some(match failure.take() {
                        Some(earlier) => earlier.or(f),
                        None => f,
                    })
                }
            }
        }
    }
    failure.map_or(Ok(objects), Err)
}

/// A batch of `[[objects]]` tables, as a TOML document of its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectsFile {
    objects: Vec<Spanned<ObjectFile>>,
}

/// The objects of one batch, checked against the scene's material names;
/// its meshes take from `budget`.
fn parse_batch(
    text: &str,
    file: &str,
    batch: &Batch,
    names: &[&String],
    budget: Option<&MeshBudget>,
) -> Result<Vec<Object>, Failure> {
    let check = Checker::from(file, text, batch.span.start).within(budget);
    let records: ObjectsFile = deserialize(&text[batch.span.clone()], &check, batch.first)?;
    objects_from_records(&records.objects, batch.first, names, &check)
        .map_err(|error| Failure::new(Stage::Rules, error))
}
