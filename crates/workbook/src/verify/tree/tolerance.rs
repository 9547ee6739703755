//! How close a student's value must be to the reference's, and how values
//! are shown in verify's messages.

use serde_json::Value;

/// Relative tolerance of t, distances, points and directions, relative to
/// the value or to 1, whichever is larger: 1e-4 absolute near zero (a
/// ten-thousandth of a scene unit), where a relative tolerance would ask
/// for more digits than a tracer in f32 has, and would depend on where the
/// scene puts its origin.
pub const RELATIVE: f64 = 1e-4;
/// Tolerance of weights and colours, per channel: one 8-bit step.
pub const STEP: f64 = 1.0 / 255.0;

/// How a field is compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tolerance {
    /// Equal: kinds, indices, names, flags, statuses.
    Exact,
    /// A length along a ray (t, a distance) or a ratio of indices:
    /// 1e-4 relative (absolute below 1).
    Length,
    /// A point or a direction (or a sphere's two roots): each component
    /// within 1e-4 of the longer vector's length (absolute below 1).
    Vector,
    /// A cosine (n·l, cos θ₁, sin²θ₂): within 1e-4.
    Cosine,
    /// A weight or a colour, per channel: within 1/255.
    Colour,
}

impl Tolerance {
    /// Are two numbers equal enough? `scale` is the size of the vector
    /// they belong to (for [`Tolerance::Vector`]).
    fn close(self, a: f64, b: f64, scale: f64) -> bool {
        let allowed = match self {
            Tolerance::Exact => 0.0,
            Tolerance::Length => RELATIVE * a.abs().max(b.abs()).max(1.0),
            Tolerance::Vector => RELATIVE * scale.max(1.0),
            Tolerance::Cosine => RELATIVE,
            Tolerance::Colour => STEP,
        };
        (a - b).abs() <= allowed
    }

    /// The tolerance in words, for a message.
    pub fn describe(self) -> &'static str {
        match self {
            Tolerance::Exact => "must be equal",
            Tolerance::Length => "within 1e-4 relative (absolute below 1)",
            Tolerance::Vector => {
                "each component within 1e-4 of the vector's length (absolute below 1)"
            }
            Tolerance::Cosine => "within 1e-4",
            Tolerance::Colour => "within 1/255 in each channel",
        }
    }
}

/// What is wrong with a student's value, besides being too far.
pub enum Mismatch {
    /// The values differ beyond the tolerance (or one is null).
    Differs,
    /// The student's value is not of the schema's type: what was expected.
    Type(String),
}

/// Compares the reference's value with the student's. A null reference
/// (the field does not apply) must be null in theirs too.
pub fn compare(reference: &Value, yours: &Value, tolerance: Tolerance) -> Result<(), Mismatch> {
    match (reference, yours) {
        (Value::Null, Value::Null) => Ok(()),
        (Value::Null, _) => Err(Mismatch::Differs),
        (_, Value::Null) => Err(Mismatch::Differs),
        (Value::Number(a), b) if tolerance != Tolerance::Exact => {
            let b = b
                .as_f64()
                .ok_or_else(|| Mismatch::Type("a number".into()))?;
            let a = a.as_f64().unwrap_or(f64::NAN);
            ok(tolerance.close(a, b, a.abs().max(b.abs())))
        }
        (Value::Array(a), b) if tolerance != Tolerance::Exact => {
            let expected = || Mismatch::Type(format!("an array of {} numbers", a.len()));
            let b = b
                .as_array()
                .filter(|b| b.len() == a.len())
                .ok_or_else(expected)?;
            let b: Vec<f64> = b
                .iter()
                .map(Value::as_f64)
                .collect::<Option<_>>()
                .ok_or_else(expected)?;
            let a: Vec<f64> = a.iter().map(|v| v.as_f64().unwrap_or(f64::NAN)).collect();
            let length = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
            let scale = length(&a).max(length(&b));
            ok(a.iter()
                .zip(&b)
                .all(|(&x, &y)| tolerance.close(x, y, scale)))
        }
        (a, b) => ok(same(a, b)),
    }
}

/// Equal values, numbers compared as numbers (`1` is `1.0`).
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(a), Value::Number(b)) => a.as_f64() == b.as_f64(),
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(a, b)| same(a, b))
        }
        (Value::Object(a), Value::Object(b)) => {
            a.len() == b.len() && a.iter().all(|(k, v)| b.get(k).is_some_and(|w| same(v, w)))
        }
        (a, b) => a == b,
    }
}

fn ok(equal: bool) -> Result<(), Mismatch> {
    if equal {
        Ok(())
    } else {
        Err(Mismatch::Differs)
    }
}

/// A value as a message shows it: numbers to 7 significant digits, arrays
/// as `(x, y, z)`, null as `none`.
pub fn show(value: &Value) -> String {
    match value {
        Value::Null => "none".into(),
        Value::Number(n) => n.as_f64().map_or_else(|| n.to_string(), number),
        Value::Array(items) => {
            let items: Vec<String> = items.iter().map(show).collect();
            format!("({})", items.join(", "))
        }
        Value::String(s) => s.clone(),
        Value::Object(map) => {
            let fields: Vec<String> = map
                .iter()
                .map(|(k, v)| format!("{k}: {}", show(v)))
                .collect();
            format!("{{{}}}", fields.join(", "))
        }
        other => other.to_string(),
    }
}

/// A number to 7 significant digits, without trailing zeros.
pub fn number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    if !(-4..7).contains(&magnitude) {
        let text = format!("{v:.6e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        return format!("{}e{exponent}", trim(mantissa));
    }
    trim(&format!("{v:.*}", (6 - magnitude).max(0) as usize))
}

/// `1.500000` → `1.5`, `2.000` → `2`.
fn trim(text: &str) -> String {
    if !text.contains('.') {
        return text.to_owned();
    }
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn numbers_show_seven_digits() {
        assert_eq!(number(5.45877), "5.45877");
        assert_eq!(number(0.058000002), "0.058");
        assert_eq!(number(-1.22e-6), "-1.22e-6");
        assert_eq!(number(2.0), "2");
        assert_eq!(number(12345678.9), "1.234568e7");
    }

    #[test]
    fn tolerances_are_relative_with_a_floor() {
        let same = |a: Value, b: Value, t| compare(&a, &b, t).is_ok();
        assert!(same(json!(100.0), json!(100.009), Tolerance::Length));
        assert!(!same(json!(100.0), json!(100.02), Tolerance::Length));
        assert!(same(json!(0.0), json!(9e-5), Tolerance::Length));
        assert!(!same(json!(0.5), json!(0.5002), Tolerance::Length));
        assert!(same(
            json!([0.0, 1.0, 0.0]),
            json!([5e-5, 1.0, 0.0]),
            Tolerance::Vector
        ));
        assert!(!same(
            json!([0.0, 1.0, 0.0]),
            json!([2e-4, 1.0, 0.0]),
            Tolerance::Vector
        ));
        assert!(same(
            json!([0.5, 0.5, 0.5]),
            json!([0.503, 0.5, 0.5]),
            Tolerance::Colour
        ));
        assert!(!same(
            json!([0.5, 0.5, 0.5]),
            json!([0.505, 0.5, 0.5]),
            Tolerance::Colour
        ));
        assert!(!same(
            json!(null),
            json!([0.0, 0.0, 0.0]),
            Tolerance::Colour
        ));
        assert!(same(json!("front"), json!("front"), Tolerance::Exact));
        assert!(same(json!(1), json!(1.0), Tolerance::Exact));
        assert!(matches!(
            compare(
                &json!([1.0, 2.0, 3.0]),
                &json!([1.0, 2.0]),
                Tolerance::Vector
            ),
            Err(Mismatch::Type(_))
        ));
    }
}
