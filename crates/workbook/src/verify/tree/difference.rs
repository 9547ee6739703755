//! A difference between two ray trees, and how verify words it.

use std::fmt;

use serde_json::{Map, Value};

use super::tolerance::{Tolerance, show};

type Node = Map<String, Value>;

/// One difference between the trees.
#[derive(Debug, Clone, PartialEq)]
pub struct Difference {
    /// The ray, by the kinds of the rays from the eye: `primary`,
    /// `refraction`, `reflection`.
    pub rays: Vec<String>,
    pub what: What,
}

/// What differs at a ray.
#[derive(Debug, Clone, PartialEq)]
pub enum What {
    /// A field (`hit.t`, `lights[1].adds`, `color`), as each tree has it.
    Field {
        field: String,
        reference: String,
        yours: String,
        tolerance: Tolerance,
    },
    /// The reference traces this ray; the student's tree has none.
    Missing { summary: String },
    /// The student's tree has a ray the reference does not trace.
    Extra { summary: String },
}

/// A value in a schema error, cut short.
pub fn shortened(value: &Value) -> String {
    let text = value.to_string();
    match text.char_indices().nth(60) {
        Some((end, _)) => format!("{}…", &text[..end]),
        None => text,
    }
}

/// "object 0 (sphere, material glass) at t = 5.45877", or "nothing".
pub fn hit_summary(hit: &Value) -> String {
    let Some(hit) = hit.as_object() else {
        return "nothing (the ray misses)".into();
    };
    let get = |name: &str| hit.get(name).map(show);
    let mut text = match get("object") {
        Some(object) => format!("object {object}"),
        None => "a hit".into(),
    };
    if let (Some(shape), Some(material)) = (get("shape"), get("material")) {
        text += &format!(" ({shape}, material {material})");
    }
    if let Some(t) = get("t") {
        text += &format!(" at t = {t}");
    }
    text
}

/// "light 1 (point): free, adds (0.2, 0.2, 0.2)".
pub fn light_summary(light: &Node) -> String {
    let get = |name: &str| light.get(name).map(show).unwrap_or_else(|| "?".into());
    let mut text = format!("light {}", get("light"));
    if light.contains_key("kind") {
        text += &format!(" ({})", get("kind"));
    }
    if light.contains_key("status") {
        text += &format!(": {}", get("status"));
    }
    format!("{text}, adds {}", get("adds"))
}

/// "depth 1, weight (0.912, 0.912, 0.912), from (…) along (…)".
pub fn ray_summary(ray: &Node) -> String {
    let parts: Vec<String> = [
        ("depth", "depth "),
        ("weight", "weight "),
        ("origin", "from "),
        ("direction", "along "),
    ]
    .iter()
    .filter_map(|&(name, label)| ray.get(name).map(|v| format!("{label}{}", show(v))))
    .collect();
    parts.join(", ")
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let path = self.rays.join(" → ");
        let kind = self.rays.last().map_or("", String::as_str);
        match &self.what {
            What::Field {
                field,
                reference,
                yours,
                tolerance,
            } => write!(
                f,
                "{path}: {field} differs\n  reference: {reference}\n  yours:     {yours}\n  tolerance: {}",
                tolerance.describe()
            ),
            What::Missing { summary } => write!(
                f,
                "{path}: a ray is missing: the reference traces a {kind} ray here ({summary}); your tree has none"
            ),
            What::Extra { summary } => write!(
                f,
                "{path}: an extra ray: your tree has a {kind} ray here ({summary}) that the reference does not trace"
            ),
        }
    }
}
