//! A clicked pixel: the student's ray tree, from their chapter's binary
//! (`--pixel X,Y --json`), beside the reference's from its facts
//! (`workbook::verify::tree::facts`), and the first difference as
//! `verify --tree` finds it.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::{Arc, Mutex, OnceLock};

use serde_json::{Value, json};
use workbook::verify::tree::facts::{self, Facts, SIZE, compare_with_facts};
use workbook::verify::tree::reference_facts;
use workbook::verify::tree::{Difference, What};
use workbook::workbench::chapters::ChapterEntry;

use crate::chapter;

/// Reads `x` and `y` of a query as a pixel of the bench's pictures.
pub fn parse_pixel(x: Option<&str>, y: Option<&str>) -> Result<(u32, u32), String> {
    let (width, height) = SIZE;
    let coordinate = |name: &str, value: Option<&str>, size: u32| -> Result<u32, String> {
        let value = value.ok_or_else(|| format!("the pixel's {name} is missing"))?;
        let n: u32 = value.trim().parse().map_err(|_| {
            format!(
                "the pixel's {name} must be a whole number from 0 to {}, not {value:?}",
                size - 1
            )
        })?;
        if n >= size {
            return Err(format!(
                "pixel {name} = {n} is outside the picture, which is {width}×{height}: {name} goes from 0 to {}",
                size - 1
            ));
        }
        Ok(n)
    };
    Ok((coordinate("x", x, width)?, coordinate("y", y, height)?))
}

/// The reference's facts of a chapter, read once.
pub(crate) fn facts_of(folder: &str) -> Result<Arc<Facts>, String> {
    static READ: OnceLock<Mutex<BTreeMap<String, Arc<Facts>>>> = OnceLock::new();
    let read = READ.get_or_init(Default::default);
    let mut read = read.lock().map_err(|_| "the facts' cache broke")?;
    if let Some(facts) = read.get(folder) {
        return Ok(facts.clone());
    }
    let bytes = reference_facts(folder)
        .ok_or_else(|| format!("chapter {folder} has no reference facts"))?;
    let facts = Arc::new(Facts::decode(bytes)?);
    read.insert(folder.to_owned(), facts.clone());
    Ok(facts)
}

/// Both trees of pixel (x, y) and their first difference, as the page shows
/// them. The student's side holds an error instead where their binary has
/// none to give (not built, a `todo!` reached).
pub fn trees(root: &Path, chapter: &ChapterEntry, (x, y): (u32, u32)) -> Value {
    let reference = facts_of(&chapter.folder).and_then(|f| f.tree(x, y));
    let work = root.join("target/lab").join(&chapter.folder);
    let _ = std::fs::create_dir_all(&work);
    let svg = work.join(format!("pixel-{x}-{y}.svg"));
    let _ = std::fs::remove_file(&svg);
    let pixel = format!("{x},{y}");
    let started = std::time::Instant::now();
    let yours = chapter::run(
        root,
        chapter,
        &["--pixel", &pixel, "--json", "--svg", &svg.to_string_lossy()],
    )
    .and_then(|output| {
        if !output.status.success() {
            return Err(chapter::failure(&output));
        }
        serde_json::from_slice::<Value>(&output.stdout)
            .map_err(|e| format!("your binary's --json is not a ray tree: {e}"))
    });
    let seconds = started.elapsed().as_secs_f64();
    let comparison = match (&reference, &yours) {
        (Ok(reference), Ok(yours)) => match compare_with_facts(reference, yours) {
            Ok(c) => json!({
                "values": c.values,
                "differences": c.differences.len(),
                "first": c.differences.first().map(difference),
            }),
            Err(e) => json!({"error": e}),
        },
        _ => Value::Null,
    };
    let drawing = std::fs::read_to_string(&svg).ok();
    let _ = std::fs::remove_file(&svg);
    // The student's tree cut as the reference's is, so that the two line up.
    let yours_short = yours.as_ref().ok().map(facts::shorten);
    let reference_svg = match &reference {
        Ok(tree) => crate::reference_svg::reference_svg(root, chapter, tree),
        Err(e) => Err(e.clone()),
    };
    json!({
        "chapter": chapter.folder,
        "reference_svg": reference_svg.ok(),
        "pixel": [x, y],
        "yours_short": yours_short,
        "yours": result(yours),
        "svg": drawing,
        "reference": result(reference),
        "shortened": facts::SHORTENED,
        "comparison": comparison,
        "seconds": seconds,
    })
}

fn result(tree: Result<Value, String>) -> Value {
    match tree {
        Ok(tree) => json!({"tree": tree}),
        Err(e) => json!({"error": e}),
    }
}

/// A difference as the page highlights it: the rays from the eye (by
/// kind), the field if one differs, and verify's own words.
fn difference(difference: &Difference) -> Value {
    let field = match &difference.what {
        What::Field { field, .. } => Some(field.clone()),
        What::Missing { .. } | What::Extra { .. } => None,
    };
    json!({
        "rays": difference.rays,
        "field": field,
        "text": difference.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pixel_outside_the_picture_or_not_a_number_is_refused() {
        assert_eq!(parse_pixel(Some("0"), Some("119")), Ok((0, 119)));
        let outside = parse_pixel(Some("160"), Some("0")).unwrap_err();
        assert!(
            outside.contains("outside the picture, which is 160×120"),
            "{outside}"
        );
        let word = parse_pixel(Some("-1"), Some("0")).unwrap_err();
        assert!(word.contains("whole number from 0 to 159"), "{word}");
        assert!(
            parse_pixel(None, Some("0"))
                .unwrap_err()
                .contains("missing")
        );
    }
}
