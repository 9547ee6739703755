//! A student's ray tree against the reference's, ray by ray: the fields of
//! each ray in order, then its secondary rays (matched by kind), then the
//! colour it brings back, which follows from them. The first difference
//! found is thus the earliest cause: a wrong refracted direction is named
//! before the colours it spoils.
//!
//! Which fields a tree must have is in the tables below and in
//! book/appendix/ray-tree.md; a field left out that is optional is not
//! compared, and is listed as such.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use serde_json::{Map, Value};

use super::difference::{Difference, What, hit_summary, light_summary, ray_summary, shortened};
use super::schema::Need::{Optional, Required};
use super::schema::{Field, HIT, LIGHT, LIGHT_TERMS, RAY, REFRACTION, SHADOW_RAY};
use super::tolerance::Tolerance::{Colour, Exact};
use super::tolerance::{Mismatch, Tolerance, compare, show};

/// What comparing the trees found.
#[derive(Debug, Clone, Default)]
pub struct Comparison {
    /// Every difference, the first (the earliest cause) first.
    pub differences: Vec<Difference>,
    /// The reference's rays compared with one of the student's.
    pub rays: usize,
    /// The values compared.
    pub values: usize,
    /// The optional fields the student's tree leaves out, not compared.
    pub left_out: BTreeSet<String>,
}

/// A tree's primary ray, if it is an object.
fn primary(tree: &Node) -> Option<&Node> {
    tree.get("primary").and_then(Value::as_object)
}

/// Compares the student's tree `yours` with the reference's.
/// Err: the student's tree does not follow the schema, or is of another
/// pixel or picture size; the message says where and why.
pub fn compare_trees(reference: &Value, yours: &Value) -> Result<Comparison, String> {
    let reference = reference
        .as_object()
        .expect("a reference tree is an object");
    let yours = yours
        .as_object()
        .ok_or("your tree must be a JSON object, {\"primary\": {...}}")?;
    for (field, what) in [("pixel", "pixel"), ("image", "picture size")] {
        let theirs = reference.get(field).unwrap_or(&Value::Null);
        if let Some(mine) = yours.get(field)
            && compare(theirs, mine, Exact).is_err()
        {
            return Err(format!(
                "your tree's {field} is {}, the reference's {}: compare the same {what} \
                 (the reference trees are of the chapter's default scene, at its own size)",
                show(mine),
                show(theirs)
            ));
        }
    }
    let mine = primary(yours).ok_or("your tree has no `primary` ray (an object)")?;
    let mut walk = Walk {
        out: Comparison::default(),
        path: vec!["primary".into()],
    };
    walk.ray(primary(reference).expect("a primary ray"), mine, true)?;
    Ok(walk.out)
}

type Node = Map<String, Value>;

/// The comparison under way, and the ray it is at.
struct Walk {
    out: Comparison,
    path: Vec<String>,
}

impl Walk {
    /// The schema error `problem` of `field` at this ray.
    fn schema(&self, field: &str, problem: impl fmt::Display) -> String {
        format!(
            "your tree does not follow the schema: at {}, `{field}` {problem} \
             (book/appendix/ray-tree.md lists what a tree must have)",
            self.path.join(" → ")
        )
    }

    fn differ(&mut self, field: &str, reference: String, yours: String, tolerance: Tolerance) {
        self.out.differences.push(Difference {
            rays: self.path.clone(),
            what: What::Field {
                field: field.to_owned(),
                reference,
                yours,
                tolerance,
            },
        });
    }

    /// Compares the student's value of a field with the reference's;
    /// false if they differ.
    fn value(
        &mut self,
        field: &str,
        reference: &Value,
        yours: &Value,
        tolerance: Tolerance,
    ) -> Result<bool, String> {
        self.out.values += 1;
        match compare(reference, yours, tolerance) {
            Ok(()) => Ok(true),
            Err(Mismatch::Type(expected)) => Err(self.schema(
                field,
                format!("must be {expected}, not {}", shortened(yours)),
            )),
            Err(Mismatch::Differs) => {
                self.differ(field, show(reference), show(yours), tolerance);
                Ok(false)
            }
        }
    }

    /// Compares field `name` of two nodes (`prefix` names the node within
    /// its ray, as `hit.`); false if they differ.
    fn field(
        &mut self,
        reference: &Node,
        yours: &Node,
        prefix: &str,
        field: Field,
    ) -> Result<bool, String> {
        let (name, tolerance, need) = field;
        let full = format!("{prefix}{name}");
        let Some(mine) = yours.get(name) else {
            if need == Required {
                return Err(self.schema(&full, "is missing, and every tree must have it"));
            }
            self.out.left_out.insert(full);
            return Ok(true);
        };
        self.value(
            &full,
            reference.get(name).unwrap_or(&Value::Null),
            mine,
            tolerance,
        )
    }

    fn fields(
        &mut self,
        reference: &Node,
        yours: &Node,
        prefix: &str,
        fields: &[Field],
    ) -> Result<(), String> {
        for &field in fields {
            self.field(reference, yours, prefix, field)?;
        }
        Ok(())
    }

    /// One ray and all that follows it.
    fn ray(&mut self, reference: &Node, yours: &Node, primary: bool) -> Result<(), String> {
        self.out.rays += 1;
        for &field in RAY {
            // The primary ray's weight is 1: it may be left out, unsaid.
            if !(primary && field.0 == "weight" && !yours.contains_key("weight")) {
                self.field(reference, yours, "", field)?;
            }
        }
        // Left out, `traced` is true: a ray the reference does not trace
        // (beyond max_depth, below min_weight) may be left out instead.
        let traced = yours.get("traced").unwrap_or(&Value::Bool(true));
        self.value(
            "traced",
            reference.get("traced").unwrap_or(&Value::Null),
            traced,
            Exact,
        )?;
        if self.hit(reference, yours)? {
            self.lights(reference, yours)?;
            self.field(reference, yours, "", ("local", Colour, Optional))?;
            self.refraction(reference, yours)?;
            self.secondary(reference, yours)?;
        }
        // A ray not traced brings back nothing: its colour may be left out.
        let untraced = yours.get("traced") == Some(&Value::Bool(false));
        match yours.get("color") {
            None if untraced => {
                let theirs = reference.get("color").unwrap_or(&Value::Null);
                self.value("color", theirs, &Value::Null, Colour)?;
            }
            _ => {
                self.field(reference, yours, "", ("color", Colour, Required))?;
            }
        }
        Ok(())
    }

    /// Compares the hits (left out: the ray hits nothing). False if the rays
    /// hit different objects, or one hits nothing: what follows the hit is
    /// then not compared.
    fn hit(&mut self, reference: &Node, yours: &Node) -> Result<bool, String> {
        let theirs = reference.get("hit").unwrap_or(&Value::Null);
        let mine = yours.get("hit").unwrap_or(&Value::Null);
        match (theirs, mine) {
            (Value::Null, Value::Null) => Ok(true),
            (Value::Object(theirs), Value::Object(mine)) => {
                if !self.field(theirs, mine, "hit.", HIT[0])? {
                    return Ok(false);
                }
                self.fields(theirs, mine, "hit.", &HIT[1..])?;
                Ok(true)
            }
            (_, Value::Null | Value::Object(_)) => {
                self.out.values += 1;
                self.differ("hit", hit_summary(theirs), hit_summary(mine), Exact);
                Ok(false)
            }
            (_, other) => Err(self.schema(
                "hit",
                format!("must be an object or null, not {}", shortened(other)),
            )),
        }
    }

    /// The lights at the hit, matched by their index (`lights[2]` is light 2).
    fn lights(&mut self, reference: &Node, yours: &Node) -> Result<(), String> {
        let Some(mine) = yours.get("lights") else {
            self.out.left_out.insert("lights".into());
            return Ok(());
        };
        let mine = mine
            .as_array()
            .ok_or_else(|| self.schema("lights", "must be an array"))?;
        let mut by_index = BTreeMap::new();
        for (i, light) in mine.iter().enumerate() {
            let index = light
                .as_object()
                .and_then(|l| l.get("light"))
                .and_then(Value::as_u64)
                .ok_or_else(|| {
                    self.schema(
                        &format!("lights[{i}]"),
                        "must be an object with the light's index, `light`",
                    )
                })?;
            by_index.insert(index, light.as_object().expect("an object"));
        }
        let none: Vec<Value> = Vec::new();
        let theirs = reference
            .get("lights")
            .and_then(Value::as_array)
            .unwrap_or(&none);
        for light in theirs.iter().filter_map(Value::as_object) {
            let index = light.get("light").and_then(Value::as_u64).unwrap_or(0);
            let field = format!("lights[{index}]");
            match by_index.remove(&index) {
                Some(mine) => self.light(light, mine, &format!("{field}."))?,
                None => {
                    self.out.values += 1;
                    self.differ(
                        &field,
                        light_summary(light),
                        "no entry for this light".into(),
                        Exact,
                    );
                }
            }
        }
        for (index, mine) in by_index {
            self.out.values += 1;
            let field = format!("lights[{index}]");
            self.differ(
                &field,
                "no such light at this hit".into(),
                light_summary(mine),
                Exact,
            );
        }
        Ok(())
    }

    /// One light at a hit. A light that adds nothing either way may be
    /// `adds_nothing` (no shadow ray traced) in one tree and `free` or
    /// `blocked` in the other, as rounding makes its terms exactly zero or
    /// not: its status and shadow ray are then not compared.
    fn light(&mut self, reference: &Node, yours: &Node, prefix: &str) -> Result<(), String> {
        let zero = Value::from(vec![0.0; 3]);
        let adds_nothing = |light: &Node| {
            compare(light.get("adds").unwrap_or(&Value::Null), &zero, Colour).is_ok()
        };
        let status = |light: &Node| {
            light
                .get("status")
                .and_then(Value::as_str)
                .map(str::to_owned)
        };
        let either = [status(reference), status(yours)];
        let lenient = adds_nothing(reference)
            && adds_nothing(yours)
            && either.iter().any(|s| s.as_deref() == Some("adds_nothing"));
        for &field in LIGHT {
            if !(lenient && field.0 == "status") {
                self.field(reference, yours, prefix, field)?;
            }
        }
        if !lenient {
            self.shadow_ray(reference, yours, &format!("{prefix}shadow_ray"))?;
        }
        self.fields(reference, yours, prefix, LIGHT_TERMS)
    }

    fn shadow_ray(&mut self, reference: &Node, yours: &Node, field: &str) -> Result<(), String> {
        let Some(mine) = yours.get("shadow_ray") else {
            self.out.left_out.insert(field.into());
            return Ok(());
        };
        let theirs = reference.get("shadow_ray").unwrap_or(&Value::Null);
        match (theirs, mine) {
            (Value::Null, Value::Null) => Ok(()),
            (Value::Object(theirs), Value::Object(mine)) => {
                let prefix = format!("{field}.");
                self.fields(theirs, mine, &prefix, SHADOW_RAY)?;
                let object = |shadow: &Node| match shadow.get("blocked_by") {
                    Some(Value::Object(by)) => by.get("object").cloned().unwrap_or(Value::Null),
                    _ => Value::Null,
                };
                if mine.contains_key("blocked_by") {
                    self.value(
                        &format!("{prefix}blocked_by.object"),
                        &object(theirs),
                        &object(mine),
                        Exact,
                    )?;
                } else {
                    self.out.left_out.insert(format!("{prefix}blocked_by"));
                }
                Ok(())
            }
            (_, Value::Null | Value::Object(_)) => {
                self.out.values += 1;
                let traced =
                    |v: &Value| if v.is_null() { "none" } else { "a shadow ray" }.to_owned();
                self.differ(field, traced(theirs), traced(mine), Exact);
                Ok(())
            }
            (_, other) => Err(self.schema(
                field,
                format!("must be an object or null, not {}", shortened(other)),
            )),
        }
    }

    fn refraction(&mut self, reference: &Node, yours: &Node) -> Result<(), String> {
        let Some(mine) = yours.get("refraction") else {
            self.out.left_out.insert("refraction".into());
            return Ok(());
        };
        let theirs = reference.get("refraction").unwrap_or(&Value::Null);
        match (theirs, mine) {
            (Value::Null, Value::Null) => Ok(()),
            (Value::Object(theirs), Value::Object(mine)) => {
                self.fields(theirs, mine, "refraction.", REFRACTION)
            }
            (_, Value::Null | Value::Object(_)) => {
                self.out.values += 1;
                let split = |v: &Value| {
                    if v.is_null() {
                        "none"
                    } else {
                        "a split at a transparent surface"
                    }
                    .to_owned()
                };
                self.differ("refraction", split(theirs), split(mine), Exact);
                Ok(())
            }
            (_, other) => Err(self.schema(
                "refraction",
                format!("must be an object or null, not {}", shortened(other)),
            )),
        }
    }

    /// The secondary rays, matched by kind. A reference ray that is not
    /// traced may be left out; any other missing or extra ray is a difference.
    fn secondary(&mut self, reference: &Node, yours: &Node) -> Result<(), String> {
        let none: Vec<Value> = Vec::new();
        let mine = match yours.get("secondary") {
            None => &none,
            Some(rays) => rays
                .as_array()
                .ok_or_else(|| self.schema("secondary", "must be an array of rays"))?,
        };
        let mut unmatched: Vec<(&Node, &str)> = Vec::new();
        for (i, ray) in mine.iter().enumerate() {
            let ray = ray.as_object();
            let kind = ray.and_then(|r| r.get("kind")).and_then(Value::as_str);
            let (Some(ray), Some(kind)) = (ray, kind) else {
                return Err(
                    self.schema(&format!("secondary[{i}]"), "must be a ray with its `kind`")
                );
            };
            unmatched.push((ray, kind));
        }
        for theirs in reference
            .get("secondary")
            .and_then(Value::as_array)
            .unwrap_or(&none)
        {
            let theirs = theirs.as_object().expect("a reference ray is an object");
            let kind = theirs.get("kind").and_then(Value::as_str).unwrap_or("ray");
            self.path.push(kind.to_owned());
            match unmatched.iter().position(|&(_, k)| k == kind) {
                Some(i) => self.ray(theirs, unmatched.remove(i).0, false)?,
                None if theirs.get("traced") == Some(&Value::Bool(false)) => {}
                None => self.ray_difference(What::Missing {
                    summary: ray_summary(theirs),
                }),
            }
            self.path.pop();
        }
        for (mine, kind) in unmatched {
            self.path.push(kind.to_owned());
            self.ray_difference(What::Extra {
                summary: ray_summary(mine),
            });
            self.path.pop();
        }
        Ok(())
    }

    fn ray_difference(&mut self, what: What) {
        self.out.values += 1;
        self.out.differences.push(Difference {
            rays: self.path.clone(),
            what,
        });
    }
}
