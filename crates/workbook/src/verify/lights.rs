//! Which lights light each pixel of a reference picture: a small text file
//! beside the reference and its object map
//! (`snapshots/<chapter>/<snapshot>.lights.txt`), so that `workbook verify`
//! can say which lights light a wrong region without depending on a
//! chapter's tracer.
//!
//! A light *lights* a pixel when it adds a non-zero contribution to the
//! pixel's colour in the chapter's tracer: summed over the ray through the
//! pixel's centre and every ray that follows it, the ray's path weight
//! times what the light adds at its hit (its `adds` in the ray tree). A
//! light seen in a mirror or through glass lights the pixel too. Ambient
//! light, which lights every hit alike, is never listed.
//!
//! The maps are written and kept current by
//! crates/workbook/tests/verify/lights.rs, which asks each chapter's ray
//! tree (`RAYBOOK_WRITE_LIGHT_MAPS=1 cargo test -p workbook --test verify
//! light_maps` rewrites them). Only chapters whose tracer lights (3 on)
//! have one.
//!
//! The format, one item a line (`#` starts a comment):
//!
//! ```text
//! size 160 120
//! light 0: ambient
//! light 1: point
//! light 2: spot
//! row 0: -*160
//! row 1: -*70 1*20 1+2*70
//! ```
//!
//! Each row is a list of runs `LIGHTS*COUNT`, LIGHTS being the indices of
//! the lights joined by `+`, or `-` for none.

use super::runs;

/// For each pixel of a reference picture, the lights that light it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LightMap {
    pub width: u32,
    pub height: u32,
    /// The kind of each light of the scene (`ambient`, `point`, `spot`), by
    /// index (the order of its `[[lights]]`).
    pub lights: Vec<String>,
    /// Row by row from the top left: the indices of the lights that light
    /// the pixel, in increasing order.
    pub pixels: Vec<Vec<usize>>,
}

impl LightMap {
    /// The lights that light pixel (x, y).
    pub fn at(&self, x: u32, y: u32) -> &[usize] {
        &self.pixels[(y * self.width + x) as usize]
    }

    /// The map as text (the format of this module's documentation), with a
    /// header saying what it is and how to regenerate it.
    pub fn to_text(&self, picture: &str) -> String {
        let mut text = format!(
            "# Which lights light each pixel of {picture}: those that add a non-zero\n\
             # contribution to its colour in the chapter's tracer (path weight × what the\n\
             # light adds, summed over the pixel's ray tree, mirrors and glass included).\n\
             # Ambient light is never listed. Lights are numbered from 0 in the order of\n\
             # the scene file's [[lights]]. Rows are runs LIGHTS*COUNT: 1+2 for lights 1\n\
             # and 2, - for none.\n\
             # Written by crates/workbook/tests/verify/lights.rs: RAYBOOK_WRITE_LIGHT_MAPS=1 cargo test -p workbook --test verify light_maps\n\
             size {} {}\n",
            self.width, self.height
        );
        for (index, kind) in self.lights.iter().enumerate() {
            text += &format!("light {index}: {kind}\n");
        }
        for (y, row) in self.pixels.chunks(self.width as usize).enumerate() {
            text += &format!(
                "row {y}: {}\n",
                runs::encode(row, |lights| set_text(lights))
            );
        }
        text
    }

    /// Reads a map written by [`LightMap::to_text`].
    pub fn parse(text: &str) -> Result<LightMap, String> {
        let mut map = LightMap {
            width: 0,
            height: 0,
            lights: Vec::new(),
            pixels: Vec::new(),
        };
        for line in text
            .lines()
            .filter(|l| !l.is_empty() && !l.starts_with('#'))
        {
            let (key, rest) = line.split_once(' ').unwrap_or((line, ""));
            match key {
                "size" => (map.width, map.height) = runs::parse_size(rest)?,
                "light" => {
                    let (_, kind) = rest
                        .split_once(": ")
                        .ok_or_else(|| format!("bad light {rest:?}"))?;
                    map.lights.push(kind.to_owned());
                }
                "row" => map.pixels.extend(runs::decode(rest, map.width, parse_set)?),
                _ => return Err(format!("unknown line {line:?}")),
            }
        }
        let size = (map.width, map.height);
        runs::check_map(&map.pixels, size, map.lights.len(), "light")?;
        Ok(map)
    }

    /// The share of the whole picture that each light lights, by index.
    pub fn shares(&self) -> Vec<f64> {
        self.shares_of(self.pixels.iter().map(Vec::as_slice))
    }

    /// The share of `pixels` (sets of lights) that each light lights, by index.
    pub fn shares_of<'a>(&self, pixels: impl Iterator<Item = &'a [usize]>) -> Vec<f64> {
        let mut counts = vec![0usize; self.lights.len()];
        let mut total = 0usize;
        for lights in pixels {
            total += 1;
            for &light in lights {
                counts[light] += 1;
            }
        }
        counts
            .iter()
            .map(|&n| n as f64 / total.max(1) as f64)
            .collect()
    }
}

/// `1+2`, or `-` for no light.
fn set_text(lights: &[usize]) -> String {
    if lights.is_empty() {
        return "-".into();
    }
    let indices: Vec<String> = lights.iter().map(usize::to_string).collect();
    indices.join("+")
}

/// Reads `1+2` or `-`.
fn parse_set(text: &str) -> Option<Vec<usize>> {
    if text == "-" {
        return Some(Vec::new());
    }
    text.split('+').map(|i| i.parse().ok()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small_map() -> LightMap {
        LightMap {
            width: 3,
            height: 2,
            lights: vec!["ambient".into(), "point".into(), "spot".into()],
            pixels: vec![vec![], vec![1], vec![1, 2], vec![1, 2], vec![1, 2], vec![2]],
        }
    }

    #[test]
    fn a_map_reads_back_as_written() {
        let text = small_map().to_text("x.png");
        assert!(text.contains("light 2: spot\n"), "{text}");
        assert!(
            text.contains("row 0: -*1 1*1 1+2*1\nrow 1: 1+2*2 2*1\n"),
            "{text}"
        );
        assert_eq!(LightMap::parse(&text), Ok(small_map()));
    }

    #[test]
    fn a_damaged_map_is_refused() {
        let text = small_map().to_text("x.png");
        for (from, to) in [("2*1\n", "2*2\n"), ("1+2*2", "1+3*2"), ("1+2*2", "1+x*2")] {
            let damaged = text.replace(from, to);
            assert!(LightMap::parse(&damaged).is_err(), "{damaged}");
        }
    }

    #[test]
    fn shares_count_each_light() {
        let shares = small_map().shares();
        assert_eq!(shares[0], 0.0);
        assert!((shares[1] - 4.0 / 6.0).abs() < 1e-12);
        assert!((shares[2] - 4.0 / 6.0).abs() < 1e-12);
    }
}
