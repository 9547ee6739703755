//! The reference's facts for every pixel of a chapter's default scene, at
//! the snapshot size (160×120): what the lab (crates/lab) shows beside a
//! student's ray tree for any pixel they click, in a handout that has no
//! reference code to trace it with.
//!
//! A full ray tree is about 2 KB of JSON; 19 200 of them per chapter would
//! be far too much to commit. So each pixel keeps a *shortened* tree
//! ([`shorten`]), the same one the student's tree is cut to before the two
//! are compared with `verify --tree`'s own [`compare_trees`]:
//!
//! * the primary ray in full but for the details that follow from others:
//!   its hit's object, t, point, normal and side; each light's status
//!   (free, blocked, dark…) and what it adds; the colour it brings back;
//! * its secondary rays (reflection, refraction) one level deep: their
//!   origin, direction, weight, hit and the colour they bring back, not
//!   their own lights or rays.
//!
//! The first difference is thus found among the fields both trees keep, in
//! the order verify finds it. A deeper difference still shows, as the
//! colour a secondary ray brings back.
//!
//! The facts are stored as `snapshots/<folder>/<snapshot>.facts.gz`: gzip of
//! one JSON line for the picture, then one per pixel in row order, numbers
//! rounded to 6 significant digits (verify's tolerances are 1e-4 relative
//! and 1/255: rounding costs at most 5e-6 of them), nulls and each hit's
//! point (o + t·d, put back when read) left out. crates/workbook/tests/
//! verify/facts.rs checks them current and rewrites them with
//! `RAYBOOK_WRITE_FACTS=1 cargo test -p workbook --test verify facts`.

use std::io::{Read, Write};

use serde_json::{Map, Value, json};

use super::{Comparison, compare_trees};

/// The size of the picture the facts are of: the snapshot size, which the
/// reference pictures (and `workbook verify`) have.
pub const SIZE: (u32, u32) = (160, 120);

/// How many levels of rays below the primary ray the facts keep.
pub const DEPTH: u64 = 1;

/// What the page says about the reference's shortened tree.
pub const SHORTENED: &str = "the reference's tree is shortened: the primary ray's hit, \
lights and colour, and its secondary rays one level deep (their hit and the colour they \
bring back, not their own lights and rays); yours is cut the same way before the two are compared";

/// The fields of a ray the facts keep (the others are left out of both trees).
const RAY: &[&str] = &[
    "kind",
    "depth",
    "origin",
    "direction",
    "weight",
    "traced",
    "end",
    "hit",
    "lights",
    "color",
    "secondary",
];
/// ...of a hit.
const HIT: &[&str] = &["object", "t", "point", "normal", "side"];
/// ...of a light at a hit.
const LIGHT: &[&str] = &["light", "status", "adds"];

/// Where a chapter's facts live, under snapshots/.
pub fn facts_path(folder: &str, snapshot: &str) -> String {
    format!("{folder}/{snapshot}.facts.gz")
}

/// A ray tree (as `--pixel X,Y --json` writes it) cut to what the facts
/// keep: the same cut for the reference's and the student's.
pub fn shorten(tree: &Value) -> Value {
    let mut out = Map::new();
    for key in ["chapter", "pixel", "image"] {
        if let Some(value) = tree.get(key) {
            out.insert(key.into(), value.clone());
        }
    }
    if let Some(primary) = tree.get("primary") {
        out.insert("primary".into(), shorten_ray(primary, 0));
    }
    Value::Object(out)
}

fn keep(node: &Value, fields: &[&str]) -> Map<String, Value> {
    let mut out = Map::new();
    if let Some(node) = node.as_object() {
        for &field in fields {
            if let Some(value) = node.get(field) {
                out.insert(field.into(), value.clone());
            }
        }
    }
    out
}

/// A ray at `depth` below the primary ray, shortened.
fn shorten_ray(ray: &Value, depth: u64) -> Value {
    let mut out = keep(ray, RAY);
    if let Some(hit) = out.get_mut("hit").filter(|h| h.is_object()) {
        *hit = Value::Object(keep(hit, HIT));
    }
    if depth >= DEPTH {
        out.remove("lights");
        out.remove("secondary");
    }
    if let Some(Value::Array(lights)) = out.get_mut("lights") {
        for light in lights.iter_mut() {
            *light = Value::Object(keep(light, LIGHT));
        }
    }
    if let Some(Value::Array(rays)) = out.get_mut("secondary") {
        for ray in rays.iter_mut() {
            *ray = shorten_ray(ray, depth + 1);
        }
    }
    Value::Object(out)
}

/// Compares the student's tree `yours` with the reference's facts of the
/// same pixel, `reference` (from [`Facts::tree`]), as `verify --tree`
/// does, on the fields both keep.
pub fn compare_with_facts(reference: &Value, yours: &Value) -> Result<Comparison, String> {
    compare_trees(reference, &shorten(yours))
}

/// A number rounded to 6 significant digits; others as they are.
fn rounded(value: &Value) -> Value {
    match value {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap_or(0.0);
            let text = format!("{x:.5e}");
            json!(text.parse::<f64>().unwrap_or(x))
        }
        Value::Array(items) => Value::Array(items.iter().map(rounded).collect()),
        Value::Object(map) => Value::Object(
            map.iter()
                .filter(|(key, value)| !value.is_null() && key.as_str() != "point")
                .map(|(key, value)| (key.clone(), rounded(value)))
                .collect(),
        ),
        other => other.clone(),
    }
}

/// Writes the facts file of a picture: `head` (its chapter, scene and
/// size) and each pixel's tree in row order, each shortened and rounded.
pub fn encode(head: &Value, trees: impl IntoIterator<Item = Value>) -> Vec<u8> {
    let mut zip = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    let mut line = |value: &Value| {
        let text = value.to_string() + "\n";
        zip.write_all(text.as_bytes())
            .expect("writing to memory never fails");
    };
    line(head);
    for tree in trees {
        line(&pixel_line(&tree));
    }
    zip.finish().expect("writing to memory never fails")
}

/// A pixel's line of the facts: its tree's primary ray, shortened and rounded.
pub fn pixel_line(tree: &Value) -> Value {
    rounded(&shorten(tree)["primary"])
}

/// A chapter's facts, read.
pub struct Facts {
    /// The picture's chapter, scene and size.
    pub head: Value,
    /// One line per pixel, in row order: its shortened primary ray.
    lines: Vec<String>,
}

impl Facts {
    /// Reads a facts file written by [`encode`].
    pub fn decode(bytes: &[u8]) -> Result<Facts, String> {
        let mut text = String::new();
        flate2::read::GzDecoder::new(bytes)
            .read_to_string(&mut text)
            .map_err(|e| format!("the reference's facts cannot be read: {e}"))?;
        let mut lines = text.lines().map(str::to_owned);
        let head = lines.next().unwrap_or_default();
        let head: Value = serde_json::from_str(&head)
            .map_err(|e| format!("the reference's facts have no valid first line: {e}"))?;
        Ok(Facts {
            head,
            lines: lines.collect(),
        })
    }

    /// The picture's size.
    pub fn size(&self) -> (u32, u32) {
        let side = |i: usize| self.head["image"][i].as_u64().unwrap_or(0) as u32;
        (side(0), side(1))
    }

    /// Pixel (x, y)'s line as stored (see [`pixel_line`]).
    pub fn line(&self, x: u32, y: u32) -> Option<&str> {
        let (width, _) = self.size();
        self.lines.get((y * width + x) as usize).map(String::as_str)
    }

    /// The reference's shortened tree of pixel (x, y), in the schema of a
    /// ray tree.
    pub fn tree(&self, x: u32, y: u32) -> Result<Value, String> {
        let (width, height) = self.size();
        if x >= width || y >= height {
            return Err(format!(
                "pixel ({x}, {y}) is outside the picture, which is {width}×{height}: x from 0 to {}, y from 0 to {}",
                width.saturating_sub(1),
                height.saturating_sub(1)
            ));
        }
        let line = (self.lines.get((y * width + x) as usize))
            .ok_or("the reference's facts are cut short")?;
        let mut primary: Value = serde_json::from_str(line)
            .map_err(|e| format!("the reference's facts of ({x}, {y}) cannot be read: {e}"))?;
        put_back_points(&mut primary);
        Ok(json!({
            "chapter": self.head["chapter"],
            "scene": self.head["scene"],
            "pixel": [x, y],
            "image": [width, height],
            "primary": primary,
        }))
    }
}

/// Puts back each hit's point, o + t·d, into a ray and those below it.
fn put_back_points(ray: &mut Value) {
    let vector = |v: &Value| -> Option<[f64; 3]> {
        let a = v.as_array()?;
        Some([
            a.first()?.as_f64()?,
            a.get(1)?.as_f64()?,
            a.get(2)?.as_f64()?,
        ])
    };
    let (Some(origin), Some(direction)) = (vector(&ray["origin"]), vector(&ray["direction"]))
    else {
        return;
    };
    if let Some(hit) = ray.get_mut("hit").and_then(Value::as_object_mut)
        && let Some(t) = hit.get("t").and_then(Value::as_f64)
    {
        let point: Vec<f64> = (0..3).map(|i| origin[i] + t * direction[i]).collect();
        hit.insert("point".into(), json!(point));
    }
    if let Some(Value::Array(rays)) = ray.get_mut("secondary") {
        rays.iter_mut().for_each(put_back_points);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tree() -> Value {
        json!({
            "chapter": "05-reflection", "scene": "s.toml", "pixel": [1, 0], "image": [2, 1],
            "samples": 1, "tracer": {},
            "primary": {
                "kind": "primary", "depth": 0, "origin": [0.0, 0.0, 0.0],
                "direction": [0.0, 0.0, -1.0], "weight": [1.0, 1.0, 1.0],
                "path_weight": [1.0, 1.0, 1.0], "traced": true, "end": null,
                "hit": {"object": 1, "shape": "sphere", "t": 2.123456789,
                        "point": [0.0, 0.0, -2.123456789], "normal": [0.0, 0.0, 1.0],
                        "side": "front", "roots": [2.1, 4.0]},
                "lights": [{"light": 0, "kind": "point", "status": "free", "adds": [0.5, 0.5, 0.5],
                            "shadow_ray": {"origin": [0.0, 0.0, -2.0]}}],
                "local": [0.5, 0.5, 0.5],
                "secondary": [{
                    "kind": "reflection", "depth": 1, "origin": [0.0, 0.0, -2.0],
                    "direction": [0.0, 0.0, 1.0], "weight": [0.5, 0.5, 0.5], "traced": true,
                    "hit": null, "lights": [], "secondary": [], "color": [0.1, 0.1, 0.1]
                }],
                "color": [0.55, 0.55, 0.55]
            }
        })
    }

    #[test]
    fn the_facts_keep_the_primary_ray_and_one_level_below_it() {
        let short = shorten(&tree());
        let primary = &short["primary"];
        assert_eq!(primary["hit"]["object"], 1);
        assert!(primary["hit"].get("shape").is_none() && primary.get("local").is_none());
        assert_eq!(
            primary["lights"][0],
            json!({"light": 0, "status": "free", "adds": [0.5, 0.5, 0.5]})
        );
        let reflection = &primary["secondary"][0];
        assert!(reflection.get("lights").is_none() && reflection.get("secondary").is_none());
        assert_eq!(reflection["color"], json!([0.1, 0.1, 0.1]));
    }

    #[test]
    fn facts_read_back_compare_equal_and_name_a_changed_field() {
        let other = {
            let mut t = tree();
            t["pixel"] = json!([0, 0]);
            t["primary"]["hit"] = Value::Null;
            t
        };
        let bytes = encode(
            &json!({"chapter": "05-reflection", "image": [2, 1]}),
            [other, tree()],
        );
        let facts = Facts::decode(&bytes).unwrap();
        let reference = facts.tree(1, 0).unwrap();
        let same = compare_with_facts(&reference, &tree()).unwrap();
        assert!(same.differences.is_empty(), "{:?}", same.differences);
        let mut wrong = tree();
        wrong["primary"]["secondary"][0]["color"] = json!([0.2, 0.1, 0.1]);
        let found = compare_with_facts(&reference, &wrong).unwrap();
        assert_eq!(found.differences[0].rays, ["primary", "reflection"]);
        assert!(
            facts
                .tree(2, 0)
                .unwrap_err()
                .contains("outside the picture")
        );
        assert!(facts.tree(0, 0).unwrap()["primary"]["hit"].is_null());
    }
}
