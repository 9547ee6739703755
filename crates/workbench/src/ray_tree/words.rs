//! The words and numbers the text tree and its folds share.

use super::RayKind;

/// A number for people: at most four decimals, no trailing zeros, no "-0";
/// three significant digits for a number too small for that (1.23e-5).
pub fn num(v: f32) -> String {
    if v != 0.0 && v.abs() < 0.0005 {
        return format!("{v:.2e}");
    }
    let text = format!("{v:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

/// A vector or colour for people: (x, y, z).
pub fn vec3(v: [f32; 3]) -> String {
    format!("({}, {}, {})", num(v[0]), num(v[1]), num(v[2]))
}

/// The letter of a bounce in a ray's path: R a reflection, T a refraction.
pub fn step(kind: RayKind) -> &'static str {
    if kind == RayKind::Refraction {
        "T"
    } else {
        "R"
    }
}
