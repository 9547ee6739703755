//! The grader's probe: what a student's code computes on inputs it has
//! never seen, written as data for the grader to judge outside the sandbox.
//!
//! The binary (`main.rs`, built per chapter with `--features chN`) draws
//! each exercise's inputs from a seed, calls the exercise's function
//! directly (its inputs made with the toolkit's types, never with the
//! student's other exercises where the function allows it), and writes the
//! values as JSON ([`Probed`]); and it renders a few seeded random scenes
//! of each chapter with the chapter's own render path. The grader runs the
//! same probe on the reference (trusted) and in each student's copy, then
//! compares the two with [`agree`] and the pictures with the chapters'
//! snapshot tolerance, always taking the inputs, the tolerance and what a
//! scene draws with from the *reference's* output: a student's file is
//! only ever read as the values it claims.
//!
//! Why this and not the tests' verdicts: a student's process can print
//! `test NAME ... ok` or replace a reference picture in its copy, but it
//! cannot know values on inputs drawn at grading time without computing
//! them. Every drawn number is also kept off the short decimals that tests
//! write ([`is_short_decimal`]), so no input of a probe is ever one of a
//! test's, and a table of the tests' expected values gains nothing.
//!
//! Without features this is the output format and its comparison only,
//! which is what the grader links.

use serde::{Deserialize, Serialize};
use serde_json::Value;

#[cfg(feature = "ch01")]
pub mod draw;
#[cfg(feature = "ch01")]
pub mod probes;
#[cfg(feature = "ch01")]
pub mod scenes;

/// The version of the output format.
pub const FORMAT: &str = "raybook-probe-1";

/// What one run of the probe wrote: one exercise's values, or one
/// chapter's scenes.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Probed {
    pub format: String,
    pub seed: u64,
    pub exercises: Vec<Values>,
    pub scenes: Vec<Picture>,
}

/// An exercise's values on its drawn inputs.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Values {
    /// `ch02-sphere`.
    pub id: String,
    /// How far two numbers may be apart and agree: |a − b| ≤ tolerance ·
    /// max(1, |a|). The grader takes it from the reference's output.
    pub tolerance: f64,
    pub cases: Vec<Case>,
}

/// One drawn input and what the function returned for it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// The input, as the report shows it.
    pub input: String,
    /// The result: numbers, arrays of them, `null` for `None`, booleans.
    pub value: Value,
}

/// A seeded scene rendered by a chapter's own render path.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Picture {
    /// `02-hits seed scene 1 (normals)`.
    pub name: String,
    /// The exercises whose code draws it, of this chapter and the ones
    /// before.
    pub uses: Vec<String>,
    pub width: u32,
    pub height: u32,
    /// 8-bit RGB, row by row, as the chapter's PNGs store it.
    pub rgb: Vec<u8>,
}

/// The first case on which `found` disagrees with `expected` (its index),
/// or `None` if they agree on every case. A missing case, or an input that
/// is not the one drawn, disagrees.
pub fn first_disagreement(expected: &Values, found: &Values) -> Option<usize> {
    (0..expected.cases.len()).find(|&i| {
        let Some(theirs) = found.cases.get(i) else {
            return true;
        };
        let ours = &expected.cases[i];
        theirs.input != ours.input || !agree(&ours.value, &theirs.value, expected.tolerance)
    })
}

/// Do two values agree: the same shape, equal booleans, texts and `null`s,
/// and numbers within `tolerance` relative to max(1, |expected|)?
pub fn agree(expected: &Value, found: &Value, tolerance: f64) -> bool {
    match (expected, found) {
        (Value::Number(a), Value::Number(b)) => match (a.as_f64(), b.as_f64()) {
            (Some(a), Some(b)) => (a - b).abs() <= tolerance * a.abs().max(1.0),
            _ => false,
        },
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(a, b)| agree(a, b, tolerance))
        }
        (Value::Null, Value::Null) => true,
        (Value::Bool(a), Value::Bool(b)) => a == b,
        // Numbers JSON cannot hold ("inf", "NaN"; `draw::num`).
        (Value::String(a), Value::String(b)) => a == b,
        _ => false,
    }
}

/// Is `x` a number with at most three decimals (0.5, −2, 0.125, 1e4)?
/// Tests write such numbers; a probe never draws one.
pub fn is_short_decimal(x: f64) -> bool {
    let scaled = x * 1000.0;
    (scaled - scaled.round()).abs() < 1e-6 * scaled.abs().max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn values(cases: &[(&str, Value)]) -> Values {
        Values {
            id: "ch01-at".into(),
            tolerance: 1e-4,
            cases: cases
                .iter()
                .map(|(i, v)| Case {
                    input: (*i).into(),
                    value: v.clone(),
                })
                .collect(),
        }
    }

    #[test]
    fn values_agree_within_the_tolerance_and_in_shape() {
        assert!(agree(
            &json!([1.0, null, true]),
            &json!([1.00001, null, true]),
            1e-4
        ));
        assert!(!agree(&json!([1.0, 2.0]), &json!([1.0, 2.01]), 1e-4));
        assert!(agree(&json!(1000.0), &json!(1000.05), 1e-4), "relative");
        assert!(!agree(&json!([1.0]), &json!([1.0, 2.0]), 1e-4));
        assert!(!agree(&json!(null), &json!(0.0), 1e-4));
        assert!(!agree(&json!(1.0), &json!("1.0"), 1e-4));
        assert!(agree(&json!("inf"), &json!("inf"), 1e-4));
        assert!(
            !agree(&json!(null), &json!("inf"), 1e-4),
            "no hit is not a hit at ∞"
        );
    }

    #[test]
    fn the_first_disagreeing_case_is_found_and_a_missing_or_other_input_disagrees() {
        let ours = values(&[("a", json!(1.0)), ("b", json!(2.0))]);
        assert_eq!(first_disagreement(&ours, &ours), None);
        let wrong = values(&[("a", json!(1.0)), ("b", json!(3.0))]);
        assert_eq!(first_disagreement(&ours, &wrong), Some(1));
        let short = values(&[("a", json!(1.0))]);
        assert_eq!(first_disagreement(&ours, &short), Some(1));
        let other = values(&[("x", json!(1.0)), ("b", json!(2.0))]);
        assert_eq!(first_disagreement(&ours, &other), Some(0));
    }

    #[test]
    fn short_decimals_are_recognised() {
        for x in [0.5, -2.0, 0.125, 1e4, 0.1, 0.0] {
            assert!(is_short_decimal(x), "{x}");
        }
        for x in [0.1234, std::f64::consts::PI, -7.0001] {
            assert!(!is_short_decimal(x), "{x}");
        }
    }
}
