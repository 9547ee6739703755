//! Points per exercise: a small TOML file the teacher edits. Without one,
//! grading writes `points.toml` into the output folder, every exercise at
//! one point, and reads it from then on: edit it and grade again, and only
//! the scores change (the test results come from the cache).

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

use crate::judging::exercise_tests::ExerciseTests;

/// The points of each exercise.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Points {
    /// The points of an exercise the file does not list.
    #[serde(default = "one")]
    pub default: f64,
    /// Points by exercise id.
    #[serde(default)]
    pub exercise: BTreeMap<String, f64>,
}

fn one() -> f64 {
    1.0
}

impl Points {
    /// The points of exercise `id`.
    pub fn of(&self, id: &str) -> f64 {
        self.exercise.get(id).copied().unwrap_or(self.default)
    }

    /// Reads the points: from `file` if given; else from `points.toml` in
    /// `out`, which is written first (every exercise at one point) if it is
    /// not there. An id the exercises do not have is an error (a typo would
    /// otherwise go unnoticed).
    pub fn load(
        file: Option<&Path>,
        out: &Path,
        exercises: &[ExerciseTests],
    ) -> Result<Points, String> {
        let path = match file {
            Some(file) => file.to_owned(),
            None => {
                let path = out.join("points.toml");
                if !path.exists() {
                    ch00_toolkit::image::write_atomically(&path, template(exercises).as_bytes())
                        .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
                }
                path
            }
        };
        let text = std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read the points, {}: {e}", path.display()))?;
        let points: Points =
            toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        let unknown: Vec<&String> = (points.exercise.keys())
            .filter(|id| !exercises.iter().any(|e| e.id == **id))
            .collect();
        if let Some(id) = unknown.first() {
            return Err(format!(
                "{}: no exercise {id} in the chapters graded",
                path.display()
            ));
        }
        Ok(points)
    }
}

/// The file grading writes when there is none: every exercise listed at
/// one point, with its hint as a comment.
fn template(exercises: &[ExerciseTests]) -> String {
    let mut text = String::from(
        "# Points per exercise for `grade`. Edit them and grade again:\n\
         # only the scores change (the test results are kept). An exercise not\n\
         # listed here gets `default`.\n\
         default = 1.0\n\n[exercise]\n",
    );
    for exercise in exercises {
        let hint: String = exercise.hint.chars().take(60).collect();
        text.push_str(&format!("{:<22} = 1.0  # {hint}\n", exercise.id));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exercise(id: &str) -> ExerciseTests {
        ExerciseTests {
            id: id.to_owned(),
            chapter: "01-rays".to_owned(),
            hint: "the hint".to_owned(),
            tests: vec![],
        }
    }

    #[test]
    fn a_template_is_written_then_read_and_an_unknown_id_is_refused() {
        let out = tempfile::tempdir().unwrap();
        let exercises = [exercise("ch01-a"), exercise("ch01-b")];
        let points = Points::load(None, out.path(), &exercises).unwrap();
        assert_eq!((points.of("ch01-a"), points.of("ch01-b")), (1.0, 1.0));
        let file = out.path().join("points.toml");
        std::fs::write(&file, "default = 2\n[exercise]\nch01-a = 5\n").unwrap();
        let points = Points::load(None, out.path(), &exercises).unwrap();
        assert_eq!((points.of("ch01-a"), points.of("ch01-b")), (5.0, 2.0));
        std::fs::write(&file, "[exercise]\nch01-typo = 5\n").unwrap();
        let error = Points::load(Some(&file), out.path(), &exercises).unwrap_err();
        assert!(error.contains("no exercise ch01-typo"), "{error}");
    }
}
