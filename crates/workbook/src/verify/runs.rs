//! The rows of the maps beside the references (objects, lights), written
//! as runs of equal values: `-*3 0*5` is three pixels of `-` and five of `0`.

/// A row as runs `VALUE*COUNT` of equal values, each written by `token`.
pub fn encode<T: PartialEq>(row: &[T], token: impl Fn(&T) -> String) -> String {
    let mut runs: Vec<(&T, usize)> = Vec::new();
    for pixel in row {
        match runs.last_mut() {
            Some((value, count)) if *value == pixel => *count += 1,
            _ => runs.push((pixel, 1)),
        }
    }
    let text: Vec<String> = runs
        .iter()
        .map(|(value, count)| format!("{}*{count}", token(value)))
        .collect();
    text.join(" ")
}

/// `7: -*3 0*157`: the runs of one row, which must add up to `width`, each
/// value read by `token` (None: not a value).
pub fn decode<T: Clone>(
    text: &str,
    width: u32,
    token: impl Fn(&str) -> Option<T>,
) -> Result<Vec<T>, String> {
    let bad = || format!("bad row {text:?}");
    let (_, runs) = text.split_once(": ").ok_or_else(bad)?;
    let mut row = Vec::with_capacity(width as usize);
    for run in runs.split(' ') {
        let (value, count) = run.split_once('*').ok_or_else(bad)?;
        let value = token(value).ok_or_else(bad)?;
        let count: usize = count.parse().map_err(|_| bad())?;
        row.extend(std::iter::repeat_n(value, count));
    }
    if row.len() != width as usize {
        return Err(format!(
            "a row of {} pixels, not {width}: {text:?}",
            row.len()
        ));
    }
    Ok(row)
}

/// `160 120`.
pub fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("bad size {text:?}");
    let (w, h) = text.split_once(' ').ok_or_else(bad)?;
    Ok((w.parse().map_err(|_| bad())?, h.parse().map_err(|_| bad())?))
}

/// Checks a map just read: one entry for each pixel of its size, and every
/// index it names among the `listed` things of its kind (`what`: "object",
/// "light"). The object and light maps share it.
pub fn check_map<'a, P: 'a>(
    pixels: &'a [P],
    (width, height): (u32, u32),
    listed: usize,
    what: &str,
) -> Result<(), String>
where
    &'a P: IntoIterator<Item = &'a usize>,
{
    if pixels.len() != (width * height) as usize {
        return Err(format!(
            "{} pixels for a size of {width}×{height}",
            pixels.len()
        ));
    }
    match pixels.iter().flatten().find(|&&i| i >= listed) {
        Some(index) => Err(format!("{what} {index} is not among the {listed} listed")),
        None => Ok(()),
    }
}
