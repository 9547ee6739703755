//! The reference's `--svg` drawing of a pixel, for a handout that has no
//! reference code to trace it: drawn by the workbench's own `to_svg` from
//! the facts carried beside the snapshots. The facts keep a shortened tree
//! (`workbook::verify::tree::facts`), so the drawing shows the primary ray
//! and its secondary rays one level deep, and says so in its legend.

use std::path::Path;

use serde_json::{Map, Value, json};
use workbook::toolkit::Scene;
use workbook::verify::tree::facts::SIZE;
use workbook::workbench::chapters::ChapterEntry;
use workbook::workbench::ray_tree::{Fold, RayTree, TracerInfo, shape_name, to_svg_noted};

/// The note the drawing carries.
pub const NOTE: &str = "The reference's rays, drawn from the facts that travel with the \
    workbook: a shortened tree (the primary ray and its secondary rays one level deep).";

/// The drawing of the reference's facts `tree` (as `Facts::tree` gives
/// it) of pixel (x, y) of `chapter`'s default scene.
pub fn reference_svg(root: &Path, chapter: &ChapterEntry, tree: &Value) -> Result<String, String> {
    let path = chapter.default_scene_path();
    let scene = workbook::workbench::scene_files::load(root.join(&path))
        .map_err(|e| e.to_string())?
        .with_size(SIZE.0, SIZE.1);
    let primary = tree.get("primary").ok_or("the facts hold no primary ray")?;
    let whole = json!({
        "chapter": chapter.folder,
        "scene": path,
        "pixel": tree.get("pixel").cloned().unwrap_or(json!([0, 0])),
        "image": [SIZE.0, SIZE.1],
        "samples": 1,
        // Not drawn: the tracer's description.
        "tracer": serde_json::to_value(TracerInfo::default()).unwrap_or_default(),
        "primary": complete(primary, [1.0; 3], &scene),
    });
    let tree: RayTree = serde_json::from_value(whole)
        .map_err(|e| format!("the reference's facts do not make a ray tree: {e}"))?;
    Ok(to_svg_noted(&tree, &scene, Fold::DEFAULT, Some(NOTE)))
}

/// A ray of the facts with what they leave out filled in as a tree needs
/// it: its path weight (the product of the weights from the eye), no
/// lights (the drawing shows none), the hit's shape and material from the
/// scene. `parent` is the path weight of the ray it leaves.
fn complete(ray: &Value, parent: [f32; 3], scene: &Scene) -> Value {
    let number = |v: &Value| v.as_f64().unwrap_or(1.0) as f32;
    let weight: Vec<f32> = (ray.get("weight").and_then(Value::as_array))
        .map(|w| w.iter().map(number).collect())
        .unwrap_or_else(|| vec![1.0; 3]);
    let path_weight: Vec<f32> = (0..3)
        .map(|i| parent[i] * weight.get(i).copied().unwrap_or(1.0))
        .collect();
    let mut out = Map::new();
    for (key, default) in [
        ("weight", json!([1.0, 1.0, 1.0])),
        ("traced", json!(true)),
        ("end", Value::Null),
        ("local", Value::Null),
        ("refraction", Value::Null),
        ("color", Value::Null),
    ] {
        out.insert(key.into(), ray.get(key).cloned().unwrap_or(default));
    }
    for key in ["kind", "depth", "origin", "direction"] {
        out.insert(key.into(), ray.get(key).cloned().unwrap_or(Value::Null));
    }
    out.insert("path_weight".into(), json!(path_weight));
    out.insert("lights".into(), json!([]));
    out.insert(
        "hit".into(),
        ray.get("hit").map_or(Value::Null, |h| hit(h, scene)),
    );
    let path: [f32; 3] = [path_weight[0], path_weight[1], path_weight[2]];
    let secondary: Vec<Value> = (ray.get("secondary").and_then(Value::as_array))
        .map(|rays| rays.iter().map(|r| complete(r, path, scene)).collect())
        .unwrap_or_default();
    out.insert("secondary".into(), Value::Array(secondary));
    Value::Object(out)
}

/// A hit of the facts with its shape and material named from the scene.
fn hit(hit: &Value, scene: &Scene) -> Value {
    if hit.is_null() {
        return Value::Null;
    }
    let mut out = hit.as_object().cloned().unwrap_or_default();
    let object =
        (out.get("object").and_then(Value::as_u64)).and_then(|i| scene.objects.get(i as usize));
    if let Some(object) = object {
        out.insert("shape".into(), json!(shape_name(&object.shape)));
        out.insert("material".into(), json!(scene.material(object).name));
    }
    let normal = out.get("normal").cloned().unwrap_or(json!([0.0, 1.0, 0.0]));
    out.entry("facing_normal").or_insert(normal);
    out.entry("roots").or_insert(Value::Null);
    Value::Object(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_is_drawn_from_its_facts_and_says_it_is_shortened() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let chapter = crate::chapter::bench_chapter("07-termination").unwrap();
        let facts = crate::pixel::facts_of(&chapter.folder).unwrap();
        // A pixel of the glass sphere: a reflected and a refracted ray leave it.
        let tree = facts.tree(94, 50).unwrap();
        let secondary = tree["primary"]["secondary"].as_array().unwrap().len();
        assert!(secondary >= 1, "a pixel whose ray goes on");
        let svg = reference_svg(&root, chapter, &tree).unwrap();
        assert!(svg.starts_with("<svg") || svg.contains("<svg"), "{svg}");
        assert!(
            svg.contains("a shortened tree"),
            "the note is on the drawing"
        );
        let rays = svg.matches("<line class=\"ray").count();
        assert_eq!(
            rays,
            1 + secondary,
            "the primary ray and each secondary ray"
        );
    }
}
