//! `workbook verify --tree`: the committed reference trees are current (and
//! rewritten with `RAYBOOK_WRITE_RAY_TREES=1`), and a student's tree that
//! differs in a field, or misses a ray, is named so.

use std::path::PathBuf;

use serde_json::{Value, json};
use workbook::verify::tree::{
    TREE_PIXELS, TreeOutcome, What, compare_trees, reference_tree, tree_path, verify_tree,
};
use workbook::workbench::ray_tree::RayTree;
use workbook::workbench::snapshot::workspace_root;

use super::chapters::{chapter, default_scene, tree};
use super::temp;

#[test]
fn reference_trees_are_current() {
    let write = std::env::var_os("RAYBOOK_WRITE_RAY_TREES").is_some();
    let mut stale = Vec::new();
    for &(folder, pixels) in TREE_PIXELS {
        let (chapter, explain) = chapter(folder);
        let (scene, name) = default_scene(&chapter, None);
        let dir = workspace_root()
            .join("snapshots")
            .join(folder)
            .join("trees");
        let mut listed = Vec::new();
        for p in pixels {
            let computed = tree(&chapter, explain, &scene, &name, p.x, p.y);
            let text = computed.to_json() + "\n";
            let path = workspace_root()
                .join("snapshots")
                .join(tree_path(folder, p.x, p.y));
            listed.push(path.clone());
            if write {
                std::fs::create_dir_all(&dir).unwrap();
                std::fs::write(&path, &text).unwrap();
                continue;
            }
            match std::fs::read_to_string(&path) {
                Err(_) => stale.push(format!("{} is missing", path.display())),
                Ok(committed) => match differs(&committed, &computed) {
                    Some(why) => stale.push(format!("{}: {why}", path.display())),
                    None => assert_eq!(
                        reference_tree(folder, p.x, p.y),
                        Some(committed.as_str()),
                        "the workbook binary embeds an older {}: rebuild it (touch crates/workbook/src/verify/mod.rs)",
                        path.display()
                    ),
                },
            }
        }
        for entry in std::fs::read_dir(&dir).into_iter().flatten() {
            let path = entry.unwrap().path();
            if !listed.contains(&path) {
                if write {
                    std::fs::remove_file(&path).unwrap();
                } else {
                    stale.push(format!("{} is not in TREE_PIXELS", path.display()));
                }
            }
        }
    }
    assert!(
        stale.is_empty(),
        "stale, missing or unlisted reference trees:\n  {}\nregenerate them with\n  \
         RAYBOOK_WRITE_RAY_TREES=1 cargo test -p workbook --test verify reference_trees",
        stale.join("\n  ")
    );
}

/// Why a committed tree is not the computed one: not a valid tree, other
/// facts about the picture, or values beyond verify's own tolerances.
fn differs(committed: &str, computed: &RayTree) -> Option<String> {
    let parsed: RayTree = match serde_json::from_str(committed) {
        Ok(tree) => tree,
        Err(e) => return Some(format!("not a ray tree: {e}")),
    };
    let facts = |t: &RayTree| {
        (
            t.chapter.clone(),
            t.scene.clone(),
            t.pixel,
            t.image,
            t.samples,
            t.tracer,
        )
    };
    if facts(&parsed) != facts(computed) {
        return Some(format!("{:?} is now {:?}", facts(&parsed), facts(computed)));
    }
    let now: Value = serde_json::from_str(&computed.to_json()).unwrap();
    let comparison = compare_trees(&serde_json::from_str(committed).unwrap(), &now).unwrap();
    assert!(comparison.left_out.is_empty(), "{:?}", comparison.left_out);
    comparison.differences.first().map(|d| format!("{d}"))
}

#[test]
fn every_chapter_with_a_ray_tree_has_reference_trees() {
    let folders: Vec<&str> = TREE_PIXELS.iter().map(|(folder, _)| *folder).collect();
    let expected: Vec<&str> = workbook::workbench::chapters::all()
        .iter()
        .filter(|c| c.number() >= 1 && !c.companion)
        .map(|c| c.folder.as_str())
        .collect();
    assert_eq!(folders, expected);
    let glass = TREE_PIXELS
        .iter()
        .find(|(f, _)| *f == "06-refraction")
        .unwrap()
        .1;
    assert!(
        glass.iter().any(|p| (p.x, p.y) == (160, 110)),
        "the glass pixel"
    );
}

/// The reference tree of chapter 6's glass pixel.
fn glass() -> Value {
    serde_json::from_str(reference_tree("06-refraction", 160, 110).unwrap()).unwrap()
}

/// Verifies `mine` as the student's tree of a pixel.
fn verify(
    chapter: &str,
    pixel: (u32, u32),
    mine: &Value,
    name: &str,
) -> Result<TreeOutcome, String> {
    let path = save(mine, name);
    let outcome = verify_tree(chapter, pixel, &path, None);
    match &outcome {
        Ok(outcome) => println!("{name}:\n{outcome}"),
        Err(e) => println!("{name}: error: {e}"),
    }
    outcome
}

fn save(tree: &Value, name: &str) -> PathBuf {
    let path = temp(name);
    std::fs::write(&path, serde_json::to_string_pretty(tree).unwrap()).unwrap();
    path
}

/// Changes the glass pixel's tree at a JSON pointer and returns verify's
/// first difference: its rays and its field (or "missing"/"extra"), and
/// the whole message.
fn first_difference(change: impl FnOnce(&mut Value), name: &str) -> (String, String, String) {
    let mut mine = glass();
    change(&mut mine);
    let outcome = verify("6", (160, 110), &mine, name).unwrap();
    assert!(!outcome.passed());
    let first = &outcome.comparison.differences[0];
    let field = match &first.what {
        What::Field { field, .. } => field.clone(),
        What::Missing { .. } => "missing".into(),
        What::Extra { .. } => "extra".into(),
    };
    (first.rays.join(" → "), field, outcome.to_string())
}

fn scale(value: &mut Value, factor: f64) {
    *value = json!(value.as_f64().unwrap() * factor);
}

#[test]
fn the_reference_tree_passes() {
    let outcome = verify("06-refraction", (160, 110), &glass(), "same.json").unwrap();
    assert!(outcome.passed(), "{outcome}");
    assert!(outcome.comparison.left_out.is_empty());
    assert!(outcome.to_string().starts_with("PASS"), "{outcome}");
}

#[test]
fn a_changed_t_is_named_with_its_ray() {
    let (rays, field, text) = first_difference(
        |tree| {
            scale(
                tree.pointer_mut("/primary/secondary/1/secondary/0/hit/t")
                    .unwrap(),
                1.001,
            )
        },
        "t.json",
    );
    assert_eq!(
        (rays.as_str(), field.as_str()),
        ("primary → refraction → reflection", "hit.t")
    );
    assert!(
        text.contains("first difference, at primary → refraction → reflection: hit.t differs"),
        "{text}"
    );
    assert!(text.contains("tolerance: within 1e-4 relative"), "{text}");
}

#[test]
fn a_changed_normal_is_named() {
    let (rays, field, _) = first_difference(
        |tree| {
            *tree
                .pointer_mut("/primary/secondary/1/hit/normal/1")
                .unwrap() = json!(0.3)
        },
        "normal.json",
    );
    assert_eq!(
        (rays.as_str(), field.as_str()),
        ("primary → refraction", "hit.normal")
    );
}

#[test]
fn a_changed_weight_is_named() {
    let (rays, field, text) = first_difference(
        |tree| {
            *tree.pointer_mut("/primary/secondary/1/weight").unwrap() = json!([0.95, 0.95, 0.95])
        },
        "weight.json",
    );
    assert_eq!(
        (rays.as_str(), field.as_str()),
        ("primary → refraction", "weight")
    );
    assert!(text.contains("within 1/255"), "{text}");
}

#[test]
fn a_changed_origin_direction_or_colour_is_named() {
    let cases: [(&str, Value, &str, &str); 3] = [
        (
            "/primary/secondary/0/origin/2",
            json!(1.2),
            "primary → reflection",
            "origin",
        ),
        ("/primary/direction/0", json!(0.01), "primary", "direction"),
        (
            "/primary/secondary/0/color",
            json!([0.5, 0.7, 0.9]),
            "primary → reflection",
            "color",
        ),
    ];
    for (pointer, value, rays, field) in cases {
        let found = first_difference(
            |tree| *tree.pointer_mut(pointer).unwrap() = value,
            "field.json",
        );
        assert_eq!(
            (found.0.as_str(), found.1.as_str()),
            (rays, field),
            "{}",
            found.2
        );
    }
}

#[test]
fn a_missing_ray_is_named() {
    let (rays, field, text) = first_difference(
        |tree| {
            let rays = tree
                .pointer_mut("/primary/secondary")
                .unwrap()
                .as_array_mut()
                .unwrap();
            rays.remove(0);
        },
        "missing.json",
    );
    assert_eq!(
        (rays.as_str(), field.as_str()),
        ("primary → reflection", "missing")
    );
    assert!(
        text.contains("a ray is missing: the reference traces a reflection ray here"),
        "{text}"
    );
}

#[test]
fn an_extra_ray_is_named() {
    let (rays, field, text) = first_difference(
        |tree| {
            let mirror = tree.pointer("/primary/secondary/0").unwrap().clone();
            let sky = tree.pointer_mut("/primary/secondary/0/secondary").unwrap();
            sky.as_array_mut().unwrap().push(mirror);
        },
        "extra.json",
    );
    assert_eq!(
        (rays.as_str(), field.as_str()),
        ("primary → reflection → reflection", "extra")
    );
    assert!(text.contains("that the reference does not trace"), "{text}");
}

#[test]
fn a_light_is_named_by_its_index() {
    // Chapter 4's pixel in the red sphere's shadow, with the point light free.
    let mut mine: Value =
        serde_json::from_str(reference_tree("04-shadows", 110, 150).unwrap()).unwrap();
    *mine.pointer_mut("/primary/lights/1/status").unwrap() = json!("free");
    let outcome = verify("4", (110, 150), &mine, "light.json").unwrap();
    let text = outcome.to_string();
    assert!(text.contains("primary: lights[1].status differs"), "{text}");
    assert!(text.contains("reference: blocked"), "{text}");
}

/// The tree with only the fields a tree must have (book/appendix/ray-tree.md).
fn required_only(ray: &Value, primary: bool) -> Value {
    let mut kept = json!({});
    let mut fields = vec!["kind", "origin", "direction", "color"];
    if !primary {
        fields.push("weight");
    }
    for field in fields {
        kept[field] = ray[field].clone();
    }
    if let Some(hit) = ray["hit"].as_object() {
        kept["hit"] = json!({"t": hit["t"], "point": hit["point"], "normal": hit["normal"]});
    }
    let traced = ray["secondary"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| r["traced"] == json!(true));
    kept["secondary"] = traced.map(|r| required_only(r, false)).collect();
    kept
}

#[test]
fn a_tree_of_the_required_fields_only_passes() {
    for (chapter, pixel) in [
        ("6", (160, 110)),
        ("7", (380, 220)),
        ("4", (110, 150)),
        ("1", (0, 0)),
    ] {
        let (entry, _) = workbook::verify::tree::tree_chapter(chapter).unwrap();
        let reference: Value =
            serde_json::from_str(reference_tree(&entry.folder, pixel.0, pixel.1).unwrap()).unwrap();
        let mine = json!({"primary": required_only(&reference["primary"], true)});
        let outcome = verify(chapter, pixel, &mine, "required.json").unwrap();
        assert!(outcome.passed(), "{outcome}");
        assert!(outcome.comparison.left_out.contains("hit.roots") || chapter == "1");
        assert!(
            outcome
                .to_string()
                .contains("not compared, as your tree leaves them out: ")
        );
    }
}

#[test]
fn a_tree_without_a_required_field_is_refused_with_the_field() {
    let mut mine = glass();
    mine.pointer_mut("/primary/secondary/1")
        .unwrap()
        .as_object_mut()
        .unwrap()
        .remove("direction");
    let error = verify("6", (160, 110), &mine, "no-direction.json")
        .err()
        .unwrap();
    assert!(
        error.contains("at primary → refraction, `direction` is missing"),
        "{error}"
    );
    let mut mine = glass();
    *mine.pointer_mut("/primary/hit/t").unwrap() = json!("5.4");
    let error = verify("6", (160, 110), &mine, "text-t.json").err().unwrap();
    assert!(
        error.contains("`hit.t` must be a number, not \"5.4\""),
        "{error}"
    );
}

#[test]
fn another_pixel_or_size_is_refused() {
    let mut mine = glass();
    mine["pixel"] = json!([10, 10]);
    let error = verify("6", (160, 110), &mine, "other-pixel.json")
        .err()
        .unwrap();
    assert!(
        error.contains("your tree's pixel is (10, 10), the reference's (160, 110)"),
        "{error}"
    );
    let error = verify("6", (1, 2), &glass(), "unknown.json").err().unwrap();
    assert!(
        error.contains("no reference tree of pixel (1, 2)"),
        "{error}"
    );
    assert!(error.contains("\n  160,110  the glass sphere"), "{error}");
}

/// The example of book/appendix/ray-tree.md, which a student in another
/// language can copy, passes as it is written there.
#[test]
fn the_books_minimal_example_passes() {
    let page = std::fs::read_to_string(workspace_root().join("book/appendix/ray-tree.md")).unwrap();
    let (_, after) = page
        .split_once("<!-- verify-example: ")
        .expect("the example's marker");
    let (args, after) = after.split_once(" -->").unwrap();
    let (chapter, pixel) = args.split_once(' ').unwrap();
    let (x, y) = pixel.split_once(',').unwrap();
    let (_, block) = after.split_once("```json\n").unwrap();
    let (example, _) = block.split_once("```").unwrap();
    let mine: Value = serde_json::from_str(example).unwrap();
    let outcome = verify(
        chapter,
        (x.parse().unwrap(), y.parse().unwrap()),
        &mine,
        "book.json",
    )
    .unwrap();
    assert!(outcome.passed(), "{outcome}");
}

/// The page's table of reference pixels lists those of `TREE_PIXELS`.
#[test]
fn the_book_lists_the_reference_pixels() {
    let page = std::fs::read_to_string(workspace_root().join("book/appendix/ray-tree.md")).unwrap();
    for &(folder, pixels) in TREE_PIXELS {
        let number = folder[..2].parse::<u32>().unwrap();
        let row = page
            .lines()
            .find(|l| l.starts_with(&format!("| {number} | ")))
            .unwrap_or_else(|| panic!("no row for chapter {number}"));
        let listed: Vec<&str> = row.split(" | ").nth(1).unwrap().split(" · ").collect();
        let expected: Vec<String> = pixels.iter().map(|p| format!("{},{}", p.x, p.y)).collect();
        assert_eq!(listed, expected, "{row}");
    }
}
