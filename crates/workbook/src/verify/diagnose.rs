//! When a picture fails, which of the usual mistakes explains it.
//!
//! Each mistake is undone on the student's picture (flipped back, decoded,
//! its channels put back in order) or predicted from the reference (a half
//! pixel shift, a zoom), and the picture compared again. A mistake is named
//! when undoing it nearly passes and cuts the differing pixels by a large
//! factor: a correct picture passes before any of this, and an unrelated
//! error survives every undoing. When none fits, [`super::region`] says
//! where the picture differs, what the reference shows there and which
//! lights light it.

use image::{Rgb, RgbImage, imageops};

use super::lights::LightMap;
use super::objects::ObjectMap;
use super::region::{Region, locate};
use crate::workbench::compare::{Tolerance, Verdict, compare};

/// A mistake is named if, undone, at most one pixel in this many still
/// differs (384 of 19 200 at 160×120; the tolerance is 19): a half-pixel
/// shift or a zoom predicted from the reference cannot reproduce detail
/// finer than a pixel, such as a far checkerboard or what a glass sphere
/// shows, and leaves up to 1% of the showcase unexplained...
const NEARLY_PASSES: usize = 50;
/// ...and undoing it divides the number of differing pixels by at least
/// this: an unrelated error survives every undoing (or gets worse).
const LARGE_FACTOR: usize = 8;

/// The usual mistakes of a tracer's first pictures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mistake {
    /// Turned by 180°: upside down and mirrored, the camera's right and up
    /// both reversed (right = up × forward, the cross product's order
    /// swapped, and up worked out from it).
    TurnedHalfway,
    /// Upside down: the top row drawn at the bottom.
    FlippedTopToBottom,
    /// Left and right exchanged.
    MirroredLeftToRight,
    /// Stored through a gamma or sRGB curve instead of as linear values.
    GammaEncoded,
    /// Blue, green, red instead of red, green, blue.
    ChannelsBgr,
    /// Each ray goes through a corner of its pixel instead of its centre.
    HalfPixelShift(Corner),
    /// The scene's fov, which is vertical, used as the horizontal one.
    FovUsedAsHorizontal,
    /// Channels above 1 wrapped around instead of clamped to 1.
    ColoursWrapped,
    /// A picture `height` wide and `width` tall.
    SizeSwapped(Swap),
}

/// Where in each pixel a half-pixel-shifted tracer aims: a corner, or the
/// middle of an edge. A picture that is the same along a row (chapter 1's
/// sky) cannot tell the two corners of an edge apart, so it names the edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    TopLeft,
    TopRight,
    BottomLeft,
    BottomRight,
    Top,
    Bottom,
    Left,
    Right,
}

impl Corner {
    /// The four corners.
    pub const CORNERS: [Corner; 4] = [
        Corner::TopLeft,
        Corner::TopRight,
        Corner::BottomLeft,
        Corner::BottomRight,
    ];

    /// Where it lies from the pixel's centre, in pixels (y down).
    pub fn offset(self) -> (f32, f32) {
        match self {
            Corner::TopLeft => (-0.5, -0.5),
            Corner::TopRight => (0.5, -0.5),
            Corner::BottomLeft => (-0.5, 0.5),
            Corner::BottomRight => (0.5, 0.5),
            Corner::Top => (0.0, -0.5),
            Corner::Bottom => (0.0, 0.5),
            Corner::Left => (-0.5, 0.0),
            Corner::Right => (0.5, 0.0),
        }
    }

    /// The edge that all of `places` lie on, if they share one.
    fn shared_edge(places: &[Corner]) -> Option<Corner> {
        let offsets = || places.iter().map(|place| place.offset());
        let edges = [
            (Corner::Top, offsets().all(|(_, dy)| dy < 0.0)),
            (Corner::Bottom, offsets().all(|(_, dy)| dy > 0.0)),
            (Corner::Left, offsets().all(|(dx, _)| dx < 0.0)),
            (Corner::Right, offsets().all(|(dx, _)| dx > 0.0)),
        ];
        edges
            .into_iter()
            .find(|&(_, shared)| shared)
            .map(|(edge, _)| edge)
    }
}

/// What a picture of swapped size holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Swap {
    /// The reference's pixels in order, in a file whose width and height
    /// are exchanged.
    SizeOnly,
    /// The reference with x and y exchanged (pixel (x, y) stored at (y, x)).
    Transposed,
    /// Some other picture of that size (say, the scene rendered at 120×160).
    Other,
}

/// What `workbook verify` says about a failing picture.
#[derive(Debug, Clone, PartialEq)]
pub enum Diagnosis {
    /// A usual mistake explains the picture.
    Mistake {
        mistake: Mistake,
        /// Pixels that still differ once it is undone, if that was checked.
        remaining: Option<usize>,
        /// How many pixels may differ (the tolerance).
        tolerated: usize,
        /// The reference's width and height.
        size: (u32, u32),
    },
    /// None does: where the picture differs, and what the reference shows there.
    Differs(Region),
}

/// A mistake tried on a picture, and how many pixels still differ when it
/// is undone.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    mistake: Mistake,
    remaining: usize,
}

/// Explains why `actual` fails against `expected`: the usual mistake that
/// fits, else where it differs (with what the reference's maps say of that
/// region). None for a wrong size that is not a swap (the size message
/// says it all).
pub fn diagnose(
    expected: &RgbImage,
    actual: &RgbImage,
    objects: Option<&ObjectMap>,
    lights: Option<&LightMap>,
) -> Option<Diagnosis> {
    let tolerance = Tolerance::for_size(expected.width(), expected.height());
    let named = |mistake, remaining| Diagnosis::Mistake {
        mistake,
        remaining,
        tolerated: tolerance.pixels,
        size: expected.dimensions(),
    };
    if expected.dimensions() != actual.dimensions() {
        let (swap, remaining) = swapped_size(expected, actual, tolerance)?;
        return Some(named(Mistake::SizeSwapped(swap), remaining));
    }
    let differing = differing_pixels(expected, actual, tolerance);
    let best = candidates(expected, actual, tolerance)
        .into_iter()
        .filter(|c| explains(c.remaining, differing, expected))
        .min_by_key(|c| c.remaining);
    Some(match best {
        Some(c) => named(c.mistake, Some(c.remaining)),
        None => Diagnosis::Differs(locate(expected, actual, tolerance, objects, lights)),
    })
}

/// Does a mistake that leaves `remaining` of `differing` pixels explain the
/// picture? Undone, it must nearly pass and fix most of what was wrong.
fn explains(remaining: usize, differing: usize, reference: &RgbImage) -> bool {
    nearly_passes(remaining, reference) && remaining * LARGE_FACTOR <= differing
}

/// Are `remaining` differing pixels few enough to call the picture nearly right?
fn nearly_passes(remaining: usize, reference: &RgbImage) -> bool {
    remaining * NEARLY_PASSES <= reference.pixels().len()
}

/// Every same-size mistake, each with what remains when it is undone.
/// Earlier ones win ties.
fn candidates(expected: &RgbImage, actual: &RgbImage, tolerance: Tolerance) -> Vec<Candidate> {
    let undone = |picture: &RgbImage| differing_pixels(expected, picture, tolerance);
    let mut list = vec![
        Candidate {
            mistake: Mistake::ColoursWrapped,
            remaining: differing_below_saturation(expected, actual, tolerance),
        },
        // Before the flip: in a picture that is the same mirrored, a turn
        // by 180° looks like a flip, and the turn is the commoner mistake
        // (the order of a cross product).
        Candidate {
            mistake: Mistake::TurnedHalfway,
            remaining: undone(&imageops::rotate180(actual)),
        },
        Candidate {
            mistake: Mistake::FlippedTopToBottom,
            remaining: undone(&imageops::flip_vertical(actual)),
        },
        Candidate {
            mistake: Mistake::MirroredLeftToRight,
            remaining: undone(&imageops::flip_horizontal(actual)),
        },
        Candidate {
            mistake: Mistake::ChannelsBgr,
            remaining: undone(&swap_red_and_blue(actual)),
        },
        Candidate {
            mistake: Mistake::GammaEncoded,
            remaining: undone(&decoded(actual, srgb_to_linear))
                .min(undone(&decoded(actual, |v| v.powf(2.2)))),
        },
        Candidate {
            mistake: Mistake::FovUsedAsHorizontal,
            remaining: unexplained_if_zoomed(expected, actual, tolerance),
        },
    ];
    list.extend(half_pixel_shift(expected, actual, tolerance));
    list
}

/// Pixels with some channel off by more than the tolerance.
fn differing_pixels(expected: &RgbImage, actual: &RgbImage, tolerance: Tolerance) -> usize {
    match compare(expected, actual, tolerance) {
        Verdict::Pass(d) | Verdict::Differs(d) => d.pixels_over,
        Verdict::WrongSize { .. } => usize::MAX,
    }
}

/// Wrapped colours are wrong only where a channel went above 1, which the
/// reference clamps to 255: this counts the pixels that differ in a channel
/// the reference does not saturate, which wrapping cannot explain.
fn differing_below_saturation(
    expected: &RgbImage,
    actual: &RgbImage,
    tolerance: Tolerance,
) -> usize {
    expected
        .pixels()
        .zip(actual.pixels())
        .filter(|(e, a)| (0..3).any(|c| e[c] < 255 && e[c].abs_diff(a[c]) > tolerance.channel))
        .count()
}

/// The picture with red and blue exchanged.
fn swap_red_and_blue(picture: &RgbImage) -> RgbImage {
    let mut swapped = picture.clone();
    swapped
        .pixels_mut()
        .for_each(|p| *p = Rgb([p[2], p[1], p[0]]));
    swapped
}

/// The sRGB curve undone: an sRGB-encoded value back to a linear one.
fn srgb_to_linear(s: f32) -> f32 {
    if s <= 0.04045 {
        s / 12.92
    } else {
        ((s + 0.055) / 1.055).powf(2.4)
    }
}

/// The picture with `decode` applied to every channel (values in [0, 1]).
fn decoded(picture: &RgbImage, decode: impl Fn(f32) -> f32) -> RgbImage {
    let table: Vec<u8> = (0..=255u8)
        .map(|b| {
            (decode(f32::from(b) / 255.0) * 255.0)
                .round()
                .clamp(0.0, 255.0) as u8
        })
        .collect();
    let mut out = picture.clone();
    out.pixels_mut()
        .for_each(|p| p.0 = p.0.map(|v| table[usize::from(v)]));
    out
}

/// A tracer that takes the scene's vertical fov as the horizontal one has
/// half_width = tan(fov/2) instead of tan(fov/2)·width/height: its picture
/// is the reference zoomed in about the centre by width/height (4/3), for
/// any fov. Pixel (x, y) then shows the reference at height/width of its
/// distance from the centre.
fn unexplained_if_zoomed(expected: &RgbImage, actual: &RgbImage, tolerance: Tolerance) -> usize {
    let (w, h) = (expected.width() as f32, expected.height() as f32);
    let k = h / w;
    unexplained(expected, actual, tolerance, |x, y| {
        (
            w / 2.0 + k * (x as f32 + 0.5 - w / 2.0) - 0.5,
            h / 2.0 + k * (y as f32 + 0.5 - h / 2.0) - 0.5,
        )
    })
}

/// A tracer aiming at a pixel's corner shows the reference half a pixel
/// off diagonally. A corner is named only if it explains the picture
/// clearly better than the other three (they leave at least twice as many
/// pixels, plus the tolerance). Where two explain it as well, both on one
/// edge, that edge is named: a picture that is the same along its rows
/// (chapter 1's sky) cannot tell left from right, and one merely one pixel
/// off along x is as consistent with both left corners. (The edges' own
/// offsets are not tried: a sample at (x + dx, y) is checked against the
/// reference pixels x + dx to x + dx + 1, so a shift of 0 or of half a
/// pixel fits it alike, and it tells nothing apart.)
fn half_pixel_shift(
    expected: &RgbImage,
    actual: &RgbImage,
    tolerance: Tolerance,
) -> Option<Candidate> {
    let scored: Vec<(usize, Corner)> = Corner::CORNERS
        .iter()
        .map(|&place| {
            let (dx, dy) = place.offset();
            let at = |x: u32, y: u32| (x as f32 + dx, y as f32 + dy);
            (unexplained(expected, actual, tolerance, at), place)
        })
        .collect();
    let best = scored.iter().map(|&(count, _)| count).min()?;
    let as_good: Vec<Corner> = (scored.iter())
        .filter(|&&(count, _)| count < 2 * best + tolerance.pixels)
        .map(|&(_, place)| place)
        .collect();
    let place = match as_good[..] {
        [one] => one,
        _ => {
            Corner::shared_edge(&as_good).filter(|&edge| cannot_tell(expected, edge, tolerance))?
        }
    };
    Some(Candidate {
        mistake: Mistake::HalfPixelShift(place),
        remaining: best,
    })
}

/// Is the reference the same along `edge` (along its rows for the top or
/// bottom edge, down its columns for a side), so that it cannot tell the
/// edge's two corners apart? Every pixel but the tolerance's count within
/// the tolerance of its neighbour that way. (A picture with detail that
/// way, one pixel off along the other, is no half-pixel slip to name.)
fn cannot_tell(expected: &RgbImage, edge: Corner, tolerance: Tolerance) -> bool {
    let (dx, dy) = match edge {
        Corner::Top | Corner::Bottom => (1, 0),
        _ => (0, 1),
    };
    let (width, height) = expected.dimensions();
    let differing = expected
        .enumerate_pixels()
        .filter(|&(x, y, _)| x + dx < width && y + dy < height)
        .filter(|&(x, y, pixel)| {
            let next = expected.get_pixel(x + dx, y + dy);
            (0..3).any(|c| pixel[c].abs_diff(next[c]) > tolerance.channel)
        })
        .count();
    differing <= tolerance.pixels
}

/// Counts the pixels of `actual` that the reference cannot explain if pixel
/// (x, y) shows the scene at `position(x, y)`, a point of the reference's
/// pixel grid (pixel (i, j)'s centre is (i, j)). A sample between pixel
/// centres lies between their colours where shading is smooth and equals
/// one of them at an edge, so each channel must lie within the range of the
/// four reference pixels around the point, give or take the tolerance.
fn unexplained(
    expected: &RgbImage,
    actual: &RgbImage,
    tolerance: Tolerance,
    position: impl Fn(u32, u32) -> (f32, f32),
) -> usize {
    let slack = tolerance.channel;
    actual
        .enumerate_pixels()
        .filter(|&(x, y, pixel)| {
            let (u, v) = position(x, y);
            let xs = either_side(u, expected.width());
            let ys = either_side(v, expected.height());
            (0..3).any(|c| {
                let around = xs.iter().flat_map(|&i| ys.iter().map(move |&j| (i, j)));
                let values = around.map(|(i, j)| expected.get_pixel(i, j)[c]);
                let (low, high) = values.fold((255, 0), |(l, h), v| (l.min(v), h.max(v)));
                pixel[c].saturating_add(slack) < low || pixel[c] > high.saturating_add(slack)
            })
        })
        .count()
}

/// The two pixel indices either side of `u`, kept inside the picture.
fn either_side(u: f32, size: u32) -> [u32; 2] {
    let last = (size - 1) as f32;
    let below = u.floor();
    [
        below.clamp(0.0, last) as u32,
        (below + 1.0).clamp(0.0, last) as u32,
    ]
}

/// A picture `height` wide and `width` tall: what it holds (the reference's
/// pixels under a swapped size, or the reference transposed, or something
/// else) and, for the first two, how many pixels still differ. None if the
/// size is wrong some other way.
fn swapped_size(
    expected: &RgbImage,
    actual: &RgbImage,
    tolerance: Tolerance,
) -> Option<(Swap, Option<usize>)> {
    let (w, h) = expected.dimensions();
    if actual.dimensions() != (h, w) {
        return None;
    }
    let reread = RgbImage::from_raw(w, h, actual.as_raw().clone()).expect("as many pixels");
    let transposed = RgbImage::from_fn(w, h, |x, y| *actual.get_pixel(y, x));
    [(Swap::SizeOnly, reread), (Swap::Transposed, transposed)]
        .into_iter()
        .map(|(swap, picture)| (swap, differing_pixels(expected, &picture, tolerance)))
        .find(|&(_, remaining)| nearly_passes(remaining, expected))
        .map(|(swap, remaining)| (swap, Some(remaining)))
        .or(Some((Swap::Other, None)))
}
