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
use super::{deserialize, parse_whole};
use crate::scene::{Object, Scene, SceneError};

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
) -> Result<Scene, SceneError> {
    let head_text: String = outline.head.iter().map(|r| &text[r.clone()]).collect();
    let check = Checker::of_ranges(file, text, &outline.head);
    let head: Result<SceneFile, Failure> = deserialize(&head_text, &check, 0);
    if head.as_ref().is_ok_and(|h| !h.objects.is_empty()) {
        return parse_whole(text, file); // objects in two ways: let toml say what is wrong
    }
    let names: Vec<&String> = head
        .as_ref()
        .map_or(vec![], |h| h.materials.keys().collect());
    let batches: Vec<_> = (outline.batches.par_iter())
        .map(|batch| parse_batch(text, file, batch, &names))
        .collect();
    let head =
        head.and_then(|h| (h.validate(&check)).map_err(|error| Failure::new(Stage::Rules, error)));
    join(head, batches, outline.objects)
}

/// The scene with the objects of every batch, in order; or, if a part has
/// a mistake, the one a parse of the whole file would report.
fn join(
    head: Result<Scene, Failure>,
    batches: Vec<Result<Vec<Object>, Failure>>,
    objects: usize,
) -> Result<Scene, SceneError> {
    let failures = head.as_ref().err().into_iter();
    let failures = failures.chain(batches.iter().filter_map(|b| b.as_ref().err()));
    if let Some(first) = failures.min_by_key(|f| f.rank()) {
        return Err(first.error.clone());
    }
    let mut scene = head.map_err(|failure| failure.error)?;
    scene.objects = Vec::with_capacity(objects);
    for batch in batches.into_iter().flatten() {
        scene.objects.extend(batch);
    }
    Ok(scene)
}

/// A batch of `[[objects]]` tables, as a TOML document of its own.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectsFile {
    objects: Vec<Spanned<ObjectFile>>,
}

/// The objects of one batch, checked against the scene's material names.
fn parse_batch(
    text: &str,
    file: &str,
    batch: &Batch,
    names: &[&String],
) -> Result<Vec<Object>, Failure> {
    let check = Checker::from(file, text, batch.span.start);
    let records: ObjectsFile = deserialize(&text[batch.span.clone()], &check, batch.first)?;
    objects_from_records(&records.objects, batch.first, names, &check)
        .map_err(|error| Failure::new(Stage::Rules, error))
}
