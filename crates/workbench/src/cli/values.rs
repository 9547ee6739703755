//! The values of the options that clap cannot check by itself: a weight
//! and a square number of samples.

/// Parses `--min-weight`: a weight from 0 to 1.
pub(super) fn weight(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(w) if (0.0..=1.0).contains(&w) => Ok(w),
        _ => Err(format!("expected a number from 0 to 1, found {text:?}")),
    }
}

/// Parses `--samples`: a square number from 1 to 1024.
pub(super) fn samples(text: &str) -> Result<u32, String> {
    match text.parse::<u32>() {
        Ok(n) if scene_files::is_square_sample_count(n) => Ok(n),
        _ => Err(format!(
            "expected a square number from 1 to 1024 (1, 4, 9, 16, ...), found {text:?}"
        )),
    }
}
