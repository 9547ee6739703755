//! Reading the bench's Markdown tables.

/// The cells of the table row of `scene` in the bench's output.
pub fn row(stdout: &str, scene: &str) -> Vec<String> {
    let line = stdout
        .lines()
        .find(|l| l.starts_with(&format!("| {scene} ")))
        .unwrap_or_else(|| panic!("no row for {scene} in\n{stdout}"));
    line.trim_matches('|')
        .split('|')
        .map(|c| c.trim().to_owned())
        .collect()
}
