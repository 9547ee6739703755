//! Comparing two pictures pixel for pixel, with a message a student can
//! read: `assert_eq!` on two pictures prints every pixel of both (hundreds
//! of kilobytes) and says neither how many differ nor where.

use ch00_toolkit::{Color, Image};

/// How many differing pixels the message lists.
const SHOWN: usize = 4;

/// One pixel where two pictures differ: its place and both colours.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Differs {
    pub x: u32,
    pub y: u32,
    pub got: Color,
    pub want: Color,
}

/// The pixels where `got` and `want` (of one size) differ, in reading
/// order: row by row from the top, each row from the left.
pub fn differing(got: &Image, want: &Image) -> Vec<Differs> {
    let width = got.width as usize;
    (got.pixels.iter().zip(&want.pixels).enumerate())
        .filter(|(_, (g, w))| g != w)
        .map(|(i, (&got, &want))| Differs {
            x: (i % width) as u32,
            y: (i / width) as u32,
            got,
            want,
        })
        .collect()
}

/// Panics unless `got` and `want` are equal pixel for pixel. The message
/// says what was compared (`what`), how many pixels differ and by how much
/// at most (the largest difference of one channel), the first few as
/// (x, y): got …, want …, and then `hint`: what such a difference suggests.
/// A few pixels off by little and many pixels off by much are different
/// slips, and the numbers tell them apart.
#[track_caller]
pub fn assert_same_pixels(got: &Image, want: &Image, what: &str, hint: &str) {
    assert_eq!(
        (got.width, got.height),
        (want.width, want.height),
        "{what}: the two pictures are not of one size (width, height)"
    );
    let differ = differing(got, want);
    if differ.is_empty() {
        return;
    }
    let first: Vec<String> = (differ.iter().take(SHOWN))
        .map(|d| format!("({}, {}): got {}, want {}", d.x, d.y, d.got, d.want))
        .collect();
    let largest = (differ.iter())
        .map(|d| (d.got - d.want).abs().max_element())
        .fold(0.0, f32::max);
    panic!(
        "{what}: {} of {} pixels ({}×{}) differ, by at most {largest} in a channel; the \
         first {}: {}. {hint}",
        differ.len(),
        got.pixels.len(),
        got.width,
        got.height,
        first.len(),
        first.join("; ")
    );
}
