//! The study's own numbers for the page's plots: its `accuracy.csv`, read
//! (not copied), so that the curves are the study's whatever it last
//! measured.

use std::path::Path;

use serde_json::{Value, json};

use super::STUDY;

/// The study's rows, from its `accuracy.csv`: each grid row's setting, its
/// rays, its median time and its √MSE (the mean MSE over its seeds).
pub fn study(root: &Path) -> Result<Value, String> {
    let path = root.join(STUDY).join("accuracy.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut lines = text.lines();
    let header = csv_fields(lines.next().unwrap_or(""));
    let column = |name: &str| {
        (header.iter().position(|h| h == name))
            .ok_or_else(|| format!("{}: no column {name:?}", path.display()))
    };
    let wanted = [
        "group",
        "max_depth",
        "min_weight",
        "sampling",
        "samples",
        "rays",
        "seconds_median",
        "mse",
    ];
    let columns = wanted.map(column);
    let mut rows = Vec::new();
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let fields = csv_fields(line);
        let mut row = serde_json::Map::new();
        for (name, index) in wanted.iter().zip(&columns) {
            let field = fields.get(*index.as_ref().map_err(Clone::clone)?);
            let field = field.map(String::as_str).unwrap_or("");
            let value = match field.parse::<f64>() {
                Ok(number) => json!(number),
                Err(_) => json!(field),
            };
            row.insert((*name).to_owned(), value);
        }
        let mse = row.get("mse").and_then(Value::as_f64).unwrap_or(f64::NAN);
        row.insert("rmse".into(), json!(mse.sqrt()));
        rows.push(Value::Object(row));
    }
    Ok(json!({"file": path.strip_prefix(root).unwrap_or(&path), "rows": rows}))
}

/// The fields of one CSV line (RFC 4180: a field in double quotes may hold
/// commas, and `""` inside it is one quote).
fn csv_fields(line: &str) -> Vec<String> {
    let mut fields = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        let field = fields.last_mut().expect("one field at least");
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(String::new()),
            _ => field.push(c),
        }
    }
    fields
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_csv_fields_keep_their_commas() {
        assert_eq!(
            csv_fields(r#"grid,1,"lambert, spot",8,"say ""hi""""#),
            ["grid", "1", "lambert, spot", "8", "say \"hi\""]
        );
    }
}
