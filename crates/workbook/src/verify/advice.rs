//! The words of a diagnosis: what each usual mistake looks like and how to
//! fix it, in a line each.

use std::fmt;

use super::diagnose::{Corner, Diagnosis, Mistake, Swap};

impl Mistake {
    /// What is wrong with the picture, for a reference of `size`.
    pub fn what(&self, (width, height): (u32, u32)) -> String {
        match self {
            Mistake::TurnedHalfway => {
                "your picture is turned by 180° (upside down and mirrored left to right)".into()
            }
            Mistake::FlippedTopToBottom => "your picture is upside down (flipped top to bottom)".into(),
            Mistake::MirroredLeftToRight => "your picture is mirrored left to right".into(),
            Mistake::GammaEncoded => {
                "your picture is gamma-encoded (sRGB or a 1/2.2 power), not linear: its mid-tones are too bright".into()
            }
            Mistake::ChannelsBgr => "red and blue are swapped: your channels are in BGR order".into(),
            Mistake::HalfPixelShift(place) => format!(
                "your picture is shifted by half a pixel: each ray goes through {}",
                place.name()
            ),
            Mistake::FovUsedAsHorizontal => format!(
                "your picture is zoomed in by {}: the scene's fov was used as the horizontal field of view",
                ratio(width, height)
            ),
            Mistake::ColoursWrapped => "your picture differs only where the reference is at full brightness (255): \
                 colours above 1 wrapped around instead of being clamped"
                .into(),
            Mistake::SizeSwapped(swap) => format!(
                "width and height are swapped: your picture is {height} wide and {width} tall{}",
                match swap {
                    Swap::SizeOnly => ", but its pixels, row by row, are the reference's",
                    Swap::Transposed => ", the reference with x and y exchanged",
                    Swap::Other => "",
                }
            ),
        }
    }

    /// How to fix it.
    pub fn fix(&self, (width, height): (u32, u32)) -> String {
        match self {
            Mistake::TurnedHalfway => "the camera's right is forward × up₀, not up₀ × forward: the swapped \
                 order makes right point left, and up = right × forward then points down, so the picture \
                 turns by 180°. (A picture that looks the same mirrored shows the turn as upside down \
                 only: check the flip of y too, v = (1 − 2(y + 0.5)/height)·half_height.)"
                .into(),
            Mistake::FlippedTopToBottom => "row 0 is the top of the picture: the ray of pixel row y goes up by \
                 v = (1 − 2(y + 0.5)/height)·half_height, positive in the top half, and rows are written top first"
                .into(),
            Mistake::MirroredLeftToRight => "pixel column x looks right by u = (2(x + 0.5)/width − 1)·half_width, \
                 along the camera's right = forward × up₀ (with up = right × forward, the swapped order \
                 turns the picture by 180° instead)"
                .into(),
            Mistake::GammaEncoded => "store each channel clamped to [0, 1] as round(255·v), with no gamma or sRGB curve \
                 (turn off any conversion your image library makes)"
                .into(),
            Mistake::ChannelsBgr => "write each pixel's channels in the order red, green, blue".into(),
            Mistake::HalfPixelShift(_) => {
                "aim the ray of pixel (x, y) at its centre, (x + 0.5, y + 0.5) pixels from the image's top-left corner".into()
            }
            Mistake::FovUsedAsHorizontal => "fov is the vertical field of view: half_height = tan(fov/2), \
                 half_width = half_height·width/height"
                .into(),
            Mistake::ColoursWrapped => "clamp each channel to [0, 1] before converting, round(255·min(max(v, 0), 1)); \
                 a cast such as (v*255) as u8 in C or C++ overflows above 1"
                .into(),
            Mistake::SizeSwapped(Swap::SizeOnly) => {
                format!("write the file as {width} wide and {height} tall (the width comes first)")
            }
            Mistake::SizeSwapped(Swap::Transposed) => {
                format!("store pixel (x, y) at index y·width + x, in a picture {width} wide and {height} tall")
            }
            Mistake::SizeSwapped(Swap::Other) => {
                format!("render {width} pixels across and {height} rows down (the width comes first)")
            }
        }
    }
}

impl Corner {
    /// "its pixel's top-left corner" and so on.
    fn name(&self) -> &'static str {
        match self {
            Corner::TopLeft => "its pixel's top-left corner",
            Corner::TopRight => "its pixel's top-right corner",
            Corner::BottomLeft => "its pixel's bottom-left corner",
            Corner::BottomRight => "its pixel's bottom-right corner",
            Corner::Top => {
                "its pixel's top edge (the middle or a top corner: the picture cannot tell which)"
            }
            Corner::Bottom => {
                "its pixel's bottom edge (the middle or a bottom corner: the picture cannot tell which)"
            }
            Corner::Left => {
                "its pixel's left edge (the middle or a left corner: the picture cannot tell which)"
            }
            Corner::Right => {
                "its pixel's right edge (the middle or a right corner: the picture cannot tell which)"
            }
        }
    }
}

/// width/height as a fraction in lowest terms: 4/3 for 160×120.
fn ratio(width: u32, height: u32) -> String {
    let gcd = (1..=width.min(height))
        .rev()
        .find(|&d| width.is_multiple_of(d) && height.is_multiple_of(d))
        .unwrap_or(1);
    format!("{}/{}", width / gcd, height / gcd)
}

/// The end of a mistake's line: how much of the difference it explains
/// (undone, the picture passes, or only `remaining` pixels still differ).
fn when_undone(remaining: Option<usize>, tolerated: usize) -> String {
    match remaining {
        None => String::new(),
        Some(n) if n <= tolerated => "; that explains the whole difference".into(),
        Some(n) => format!("; that explains all but {n} of the differing pixels"),
    }
}

impl fmt::Display for Diagnosis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Diagnosis::Mistake {
                mistake,
                remaining,
                tolerated,
                size,
            } => write!(
                f,
                "likely mistake: {}{}.\nfix: {}.",
                mistake.what(*size),
                when_undone(*remaining, *tolerated),
                mistake.fix(*size)
            ),
            Diagnosis::Differs(region) => write!(
                f,
                "none of the usual mistakes fits (turned 180°, flipped, mirrored, gamma, BGR, \
                 half-pixel shift, field of view, wrapped colours, swapped size).\n{region}"
            ),
        }
    }
}
