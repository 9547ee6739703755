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

/// The reference picture and the facts are of one render: each pixel of
/// `snapshots/<chapter>/<snapshot>.snap.png` holds the colour that its
/// facts' primary ray brings back, clamped to [0, 1] and times 255, rounded.
/// Both files are committed, and each is checked against the chapter's
/// code only within a tolerance (the picture's snapshot test lets a few
/// pixels differ), so the two could drift apart unseen: a picture kept from
/// before a change that the facts were rewritten after. A student then saw
/// verify and the lab mark a pixel as differing (chapter 7's (94, 50), by
/// 14/255) whose tree the lab said matched. The facts keep 6 significant
/// digits, so a byte at the edge of two is accepted either way.
#[test]
fn reference_facts_agree_with_the_reference_pictures() {
    let mut problems = Vec::new();
    for reference in references() {
        let folder = reference.chapter.folder.as_str();
        let snapshot = &reference.chapter.verify.as_ref().unwrap().snapshot;
        let dir = workspace_root().join("snapshots");
        let facts = std::fs::read(dir.join(facts::facts_path(folder, snapshot))).unwrap();
        let facts = Facts::decode(&facts).unwrap();
        let png = std::fs::read(dir.join(format!("{folder}/{snapshot}.snap.png"))).unwrap();
        let picture = image::load_from_memory(&png).unwrap().to_rgb8();
        assert_eq!(
            picture.dimensions(),
            facts.size(),
            "{folder}: picture and facts sizes"
        );
        let (width, height) = facts.size();
        let differing: Vec<String> = (0..width * height)
            .filter_map(|i| {
                let (x, y) = (i % width, i / width);
                let tree = facts.tree(x, y).unwrap();
                let color = &tree["primary"]["color"];
                let pixel = picture.get_pixel(x, y).0;
                let off = (0..3).any(|c| !byte_of_six_digits(&color[c], pixel[c]));
                off.then(|| format!("({x}, {y}): picture {pixel:?}, facts' colour {color}"))
            })
            .collect();
        if let Some(first) = differing.first() {
            problems.push(format!(
                "{folder}: {} pixels, first {first}",
                differing.len()
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "the reference pictures and the facts disagree:\n  {}\nrender the reference again and \
         accept it (`cargo insta review` after the chapter's snapshot test), or rewrite the facts",
        problems.join("\n  ")
    );
}

/// Is `byte` what the picture stores for `value`, a colour channel written
/// with 6 significant digits (so off by up to 5·10⁻⁶ of itself)?
fn byte_of_six_digits(value: &Value, byte: u8) -> bool {
    let Some(v) = value.as_f64() else {
        return false;
    };
    let to_byte = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
    let margin = 5e-6 * v.abs();
    to_byte(v - margin) <= byte && byte <= to_byte(v + margin)
}
