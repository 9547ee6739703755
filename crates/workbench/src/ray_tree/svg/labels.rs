//! The labels: placed beside their segments, clear of each other and,
//! where they can be, of the rays.

use std::fmt::Write;

use super::geometry::{P2, clip};
use super::layout::{Drawn, Frame};
use super::{FONT, WIDTH, escape};

/// The width of a label, about (DejaVu Sans is among the widest).
pub(super) fn text_width(text: &str) -> f32 {
    0.6 * FONT * text.chars().count() as f32
}

/// Places (middle, baseline) for a label `w` wide beside the segment from
/// `a` to `b`, clear of it: from its middle outwards, on either side.
pub(super) fn along(a: P2, b: P2, w: f32) -> Vec<P2> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = (dx * dx + dy * dy).sqrt().max(1e-3);
    let (nx, ny) = (-dy / len, dx / len);
    // The label's box, 2hw × 2hh, clears the line if its middle is this far.
    let (hw, hh) = (w / 2.0, (FONT + 3.0) / 2.0);
    let clear = hw * nx.abs() + hh * ny.abs() + 3.0;
    let mut places = Vec::new();
    for reach in [clear, clear + FONT, clear + 2.5 * FONT] {
        for f in [0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9] {
            let (x, y) = (a[0] + f * dx, a[1] + f * dy + hh - 3.0);
            places.push([x + reach * nx, y + reach * ny]);
            places.push([x - reach * nx, y - reach * ny]);
        }
    }
    places
}

/// The labels placed so far and the rays drawn, so that a label covers
/// neither another label nor, where it can help it, a ray; and the band
/// of the picture labels go in, from the heading to the legend.
pub(super) struct Labels {
    boxes: Vec<[f32; 4]>,
    rays: Vec<(P2, P2)>,
    band: [f32; 2],
}

impl Labels {
    pub(super) fn new(rays: &[Drawn], frame: &Frame) -> Labels {
        Labels {
            boxes: Vec::new(),
            rays: (rays.iter().filter(|d| d.shown))
                .map(|d| (frame.px(d.a), frame.px(d.b)))
                .collect(),
            band: [frame.top - 4.0, frame.top + frame.height + 6.0],
        }
    }

    /// Writes `text` at the first of `places` (its middle, its baseline)
    /// where it covers no label and no ray, else no label, else at the
    /// first moved into the band; nowhere if there is no place.
    pub(super) fn place(
        &mut self,
        svg: &mut String,
        class: &str,
        text: &str,
        places: &[P2],
    ) -> Option<()> {
        let w = text_width(text);
        let rect = |p: &P2| [p[0] - w / 2.0, p[1] - FONT, p[0] + w / 2.0, p[1] + 3.0];
        let apart = |r: &[f32; 4]| {
            r[0] >= 2.0
                && r[2] <= WIDTH - 2.0
                && r[1] >= self.band[0]
                && r[3] <= self.band[1]
                && self
                    .boxes
                    .iter()
                    .all(|b| r[2] < b[0] || b[2] < r[0] || r[3] < b[1] || b[3] < r[1])
        };
        let clear = |r: &[f32; 4]| {
            let (min, max) = ([r[0] - 3.0, r[1] - 3.0], [r[2] + 3.0, r[3] + 3.0]);
            self.rays
                .iter()
                .all(|&(a, b)| clip(a, b, min, max).is_none())
        };
        let fits = |p: &&P2| apart(&rect(p));
        let at = match places.iter().find(|p| fits(p) && clear(&rect(p))) {
            Some(at) => *at,
            None => match places.iter().find(fits) {
                Some(at) => *at,
                None => self.clamp(places.first().copied()?, w),
            },
        };
        self.boxes.push(rect(&at));
        let _ = writeln!(
            svg,
            r#"<text class="{class}" x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
            at[0],
            at[1],
            escape(text)
        );
        Some(())
    }

    /// `at` moved into the picture and the band, for a label `w` wide.
    fn clamp(&self, at: P2, w: f32) -> P2 {
        let x = at[0].clamp(w / 2.0 + 2.0, (WIDTH - w / 2.0 - 2.0).max(w / 2.0 + 2.0));
        let y = at[1].clamp(self.band[0] + FONT, self.band[1] - 3.0);
        [x, y]
    }
}
