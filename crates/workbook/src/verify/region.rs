//! Where a picture that no usual mistake explains differs from the
//! reference, which of the scene's objects the reference shows there and
//! which lights light it: a student then knows which intersection, which
//! material or which light to look at.

use std::fmt;

use image::RgbImage;

use super::lights::LightMap;
use super::objects::{ObjectMap, ObjectName};
use crate::workbench::compare::Tolerance;

/// Differing pixels spread over a box larger than this share of the
/// picture are reported by their worst grid cell instead.
const SPREAD: f64 = 0.25;
/// The grid has this many cells across the picture's longer side.
const CELLS_ACROSS: u32 = 8;

/// A box of pixels: columns `x.0..=x.1`, rows `y.0..=y.1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Area {
    pub x: (u32, u32),
    pub y: (u32, u32),
}

/// Where a picture differs.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    /// The box of the differing pixels reported.
    pub area: Area,
    /// When the differences spread wide: the box of them all (`area` is then
    /// the part of them in the grid cell holding the most).
    pub spread: Option<Area>,
    /// How many pixels in `area` differ by more than the tolerance...
    pub differing: usize,
    /// ...and their mean largest channel difference, in 8-bit steps.
    pub mean: f64,
    /// What the reference shows at those pixels, the most first; None
    /// without an object map.
    pub shown: Option<Vec<Shown>>,
    /// The lights that light those pixels in the reference, the light
    /// most particular to them first; None without a light map.
    pub lit: Option<Vec<Lit>>,
}

/// A light and the share of the differing pixels it lights.
#[derive(Debug, Clone, PartialEq)]
pub struct Lit {
    /// Its index in the scene.
    pub light: usize,
    /// `point` or `spot` (ambient light is never listed).
    pub kind: String,
    /// The share of the differing pixels it lights, from 0 to 1...
    pub share: f64,
    /// ...and of the whole picture.
    pub overall: f64,
}

/// An object (or the background) and the share of the differing pixels it covers.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    /// The object's index in the scene and its name; None for the background.
    pub object: Option<(usize, ObjectName)>,
    /// Its share of the pixels, from 0 to 1.
    pub share: f64,
}

/// A pixel off by more than the tolerance, and its largest channel difference.
type Differing = (u32, u32, u8);

/// Finds where `actual` differs from `expected`: the box of the differing
/// pixels, or their worst grid cell when they spread over the picture.
pub fn locate(
    expected: &RgbImage,
    actual: &RgbImage,
    tolerance: Tolerance,
    objects: Option<&ObjectMap>,
    lights: Option<&LightMap>,
) -> Region {
    let all: Vec<Differing> = expected
        .enumerate_pixels()
        .zip(actual.pixels())
        .map(|((x, y, e), a)| (x, y, (0..3).map(|c| e[c].abs_diff(a[c])).max().unwrap_or(0)))
        .filter(|&(_, _, d)| d > tolerance.channel)
        .collect();
    let whole = bounding_box(&all);
    let picture = f64::from(expected.width()) * f64::from(expected.height());
    let (pixels, spread) = match whole {
        Some(area) if area.pixels() as f64 > SPREAD * picture => (
            worst_cell(&all, expected.width().max(expected.height()) / CELLS_ACROSS),
            Some(area),
        ),
        _ => (all, None),
    };
    let sum: f64 = pixels.iter().map(|&(_, _, d)| f64::from(d)).sum();
    Region {
        area: bounding_box(&pixels).unwrap_or(Area {
            x: (0, 0),
            y: (0, 0),
        }),
        spread,
        differing: pixels.len(),
        mean: sum / pixels.len().max(1) as f64,
        shown: objects.map(|map| shown(map, &pixels)),
        lit: lights.map(|map| lit(map, &pixels)),
    }
}

impl Area {
    /// How many pixels the box holds.
    fn pixels(&self) -> u64 {
        u64::from(self.x.1 - self.x.0 + 1) * u64::from(self.y.1 - self.y.0 + 1)
    }
}

/// The smallest box holding all the pixels, if there are any.
fn bounding_box(pixels: &[Differing]) -> Option<Area> {
    let first = pixels.first()?;
    let start = Area {
        x: (first.0, first.0),
        y: (first.1, first.1),
    };
    Some(pixels.iter().fold(start, |a, &(x, y, _)| Area {
        x: (a.x.0.min(x), a.x.1.max(x)),
        y: (a.y.0.min(y), a.y.1.max(y)),
    }))
}

/// The differing pixels of the `cell` × `cell` grid square that holds the
/// most, or of those holding as many, the one where they differ most.
fn worst_cell(pixels: &[Differing], cell: u32) -> Vec<Differing> {
    let cell = cell.max(1);
    let key = |&(x, y, _): &Differing| (x / cell, y / cell);
    let mut cells = std::collections::BTreeMap::new();
    for p in pixels {
        let (count, sum) = cells.entry(key(p)).or_insert((0usize, 0u64));
        *count += 1;
        *sum += u64::from(p.2);
    }
    let worst = cells
        .iter()
        .max_by_key(|&(k, score)| (*score, std::cmp::Reverse(*k)))
        .map(|(k, _)| *k);
    pixels
        .iter()
        .copied()
        .filter(|p| Some(key(p)) == worst)
        .collect()
}

/// What the reference shows at the pixels, by object, the largest share first.
fn shown(map: &ObjectMap, pixels: &[Differing]) -> Vec<Shown> {
    let mut counts = std::collections::BTreeMap::new();
    for &(x, y, _) in pixels {
        *counts.entry(map.at(x, y)).or_insert(0usize) += 1;
    }
    let mut shown: Vec<(Option<usize>, usize)> = counts.into_iter().collect();
    shown.sort_by_key(|&(object, count)| (std::cmp::Reverse(count), object));
    shown
        .into_iter()
        .map(|(object, count)| Shown {
            object: object.map(|i| (i, map.objects[i].clone())),
            share: count as f64 / pixels.len().max(1) as f64,
        })
        .collect()
}

/// The lights that light at least 1% of the pixels in the reference, the
/// one most particular to them first: the largest ratio of its share of
/// them to its share of the whole picture (a spot's cone before the point
/// light that lights everything).
fn lit(map: &LightMap, pixels: &[Differing]) -> Vec<Lit> {
    let overall = map.shares();
    let here = map.shares_of(pixels.iter().map(|&(x, y, _)| map.at(x, y)));
    let mut lit: Vec<Lit> = here
        .iter()
        .enumerate()
        .filter(|&(_, &share)| share >= 0.01)
        .map(|(light, &share)| Lit {
            light,
            kind: map.lights[light].clone(),
            share,
            overall: overall[light],
        })
        .collect();
    let lift = |l: &Lit| l.share / l.overall.max(f64::MIN_POSITIVE);
    lit.sort_by(|a, b| lift(b).total_cmp(&lift(a)).then(a.light.cmp(&b.light)));
    lit
}

/// "lit by light 2 (spot) in 85% of it (14% of the whole picture), by
/// light 1 (point) in 97% of it (81%)".
fn lights_lit(lit: &[Lit]) -> String {
    if lit.is_empty() {
        return "only ambient light lights it".into();
    }
    let percent = |v: f64| (100.0 * v).round();
    let listed: Vec<String> = lit
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let whole = if i == 0 {
                "% of the whole picture"
            } else {
                "%"
            };
            format!(
                "light {} ({}) in {}% of it ({}{whole})",
                l.light,
                l.kind,
                percent(l.share),
                percent(l.overall)
            )
        })
        .collect();
    format!("ambient light aside, it is lit by {}", listed.join(", by "))
}

impl fmt::Display for Area {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "x {}..{}, y {}..{}",
            self.x.0, self.x.1, self.y.0, self.y.1
        )
    }
}

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let percent = (100.0 * self.share).round();
        match &self.object {
            Some((index, name)) => write!(f, "object {index} ({name}) {percent}%"),
            None => write!(f, "no object (the background) {percent}%"),
        }
    }
}

/// At most this many objects are listed, each covering at least 1% of the
/// pixels; the rest are summed up.
const LISTED: usize = 4;

/// "object 1 (sphere, material red) 97%, no object (the background) 3%".
fn objects_shown(shown: &[Shown]) -> String {
    let count = shown
        .iter()
        .take(LISTED)
        .take_while(|s| s.share >= 0.01)
        .count()
        .max(shown.len().min(1)); // the largest share, however small
    let mut listed: Vec<String> = shown[..count].iter().map(|s| s.to_string()).collect();
    let others: f64 = shown[count..].iter().map(|s| s.share).sum();
    if (100.0 * others).round() >= 1.0 {
        let n = shown.len() - count;
        listed.push(format!("{n} others {}%", (100.0 * others).round()));
    }
    listed.join(", ")
}

impl fmt::Display for Region {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.spread {
            Some(all) => write!(f, "it differs all over {all}, most in {}", self.area)?,
            None => write!(f, "it differs in {}", self.area)?,
        }
        write!(
            f,
            ": {} pixels, by {:.0}/255 on average",
            self.differing, self.mean
        )?;
        match &self.shown {
            Some(shown) => write!(f, "; the reference shows {} there.", objects_shown(shown))?,
            None => write!(f, ".")?,
        }
        match &self.lit {
            Some(lit) => write!(f, "\nIn the reference, {}.", lights_lit(lit)),
            None => Ok(()),
        }
    }
}
