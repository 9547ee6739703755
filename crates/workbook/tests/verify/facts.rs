//! The reference's facts of every pixel (`snapshots/<chapter>/<snapshot>.facts.gz`,
//! which the lab shows beside a student's tree) are current: each pixel's
//! tree, as the chapter's binary builds it at the snapshot size, compares
//! equal with them under `verify --tree`'s own comparison. Rewritten with
//! `RAYBOOK_WRITE_FACTS=1 cargo test -p workbook --test verify facts`.

use rayon::prelude::*;
use serde_json::{Value, json};
use workbook::verify::references;
use workbook::verify::tree::facts::{self, DEPTH, Facts, SIZE, compare_with_facts};
use workbook::verify::tree::reference_facts;
use workbook::workbench::snapshot::workspace_root;

use super::chapters::{assert_known_arguments, chapter, default_scene, tree};

#[test]
fn reference_facts_are_current() {
    let write = std::env::var_os("RAYBOOK_WRITE_FACTS").is_some();
    let mut stale = Vec::new();
    let mut total = 0;
    for reference in references() {
        let folder = reference.chapter.folder.as_str();
        assert_known_arguments(reference.chapter);
        let (chapter, explain) = chapter(folder);
        let (scene, name) = default_scene(&chapter, Some(SIZE));
        let (width, height) = SIZE;
        let trees: Vec<Value> = (0..width * height)
            .into_par_iter()
            .map(|i| {
                let computed = tree(&chapter, explain, &scene, &name, i % width, i / width);
                serde_json::to_value(&computed).expect("a tree is JSON")
            })
            .collect();
        let snapshot = &reference.chapter.verify.as_ref().unwrap().snapshot;
        let path = workspace_root()
            .join("snapshots")
            .join(facts::facts_path(folder, snapshot));
        if write {
            let head =
                json!({"chapter": folder, "scene": name, "image": [width, height], "depth": DEPTH});
            let bytes = facts::encode(&head, trees);
            std::fs::write(&path, &bytes).unwrap();
            total += bytes.len();
            continue;
        }
        let Ok(bytes) = std::fs::read(&path) else {
            stale.push(format!("{} is missing", path.display()));
            continue;
        };
        total += bytes.len();
        let committed = Facts::decode(&bytes).unwrap();
        let differing: Vec<String> = (0..width * height)
            .into_par_iter()
            .filter_map(|i| {
                let (x, y) = (i % width, i / width);
                // The same line, or else the same within verify's tolerances.
                let line = facts::pixel_line(&trees[i as usize]).to_string();
                if committed.line(x, y) == Some(line.as_str()) {
                    return None;
                }
                let reference = committed.tree(x, y).ok()?;
                let comparison = compare_with_facts(&reference, &trees[i as usize]);
                match comparison {
                    Ok(c) if c.differences.is_empty() => None,
                    Ok(c) => Some(format!("({x}, {y}): {}", c.differences[0])),
                    Err(e) => Some(format!("({x}, {y}): {e}")),
                }
            })
            .collect();
        if let Some(first) = differing.first() {
            stale.push(format!(
                "{}: {} pixels differ, first {first}",
                path.display(),
                differing.len()
            ));
        } else {
            assert!(
                reference_facts(folder) == Some(bytes.as_slice()),
                "the workbook binary embeds older facts of {folder}: rebuild it (touch crates/workbook/src/verify/mod.rs)"
            );
        }
    }
    assert!(
        stale.is_empty(),
        "stale or missing reference facts:\n  {}\nregenerate them with\n  \
         RAYBOOK_WRITE_FACTS=1 cargo test -p workbook --test verify facts",
        stale.join("\n  ")
    );
    // The budget the lab was given: every chapter's facts within 10 MB.
    assert!(total < 10_000_000, "the facts take {total} bytes");
}
