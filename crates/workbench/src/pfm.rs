//! A picture's linear values as a PFM file (Portable Float Map): the
//! colours the tracer computed, as f32, before the PNG clamps them to
//! [0, 1] and rounds them to 8 bits.
//!
//! Error is measured on these values (`raybook accuracy` compares the
//! unclamped linear pictures), so a tool that measures a chapter binary's
//! picture asks for it with `--linear FILE.pfm` rather than reading the PNG.
//!
//! The format: the text header `PF\n<width> <height>\n-1.0\n` (`PF` for
//! colour, a negative scale for little-endian), then width × height RGB
//! triples of f32, **bottom row first**, as the format's authors had it.

use std::path::Path;

use ch00_toolkit::image::write_atomically;
use ch00_toolkit::{Color, Image};

/// The PFM bytes of `image`.
pub fn encode(image: &Image) -> Vec<u8> {
    let header = format!("PF\n{} {}\n-1.0\n", image.width, image.height);
    let mut bytes = Vec::with_capacity(header.len() + 12 * image.pixels.len());
    bytes.extend(header.as_bytes());
    let width = image.width.max(1) as usize;
    for row in image.pixels.chunks(width).rev() {
        for c in row {
            for v in [c.x, c.y, c.z] {
                bytes.extend(v.to_le_bytes());
            }
        }
    }
    bytes
}

/// Writes `image` as PFM to `path`, atomically.
pub fn save(image: &Image, path: &Path) -> std::io::Result<()> {
    write_atomically(path, &encode(image))
}

/// The picture in PFM `bytes` (colour, little- or big-endian), or what is
/// wrong with them.
pub fn decode(bytes: &[u8]) -> Result<Image, String> {
    let (header, body) = split_header(bytes)?;
    let [kind, size, scale] = header;
    if kind != "PF" {
        return Err(format!(
            "not a colour PFM: it starts with {kind:?}, not \"PF\""
        ));
    }
    let numbers: Vec<u32> = size
        .split_whitespace()
        .filter_map(|n| n.parse().ok())
        .collect();
    let [width, height] = numbers[..] else {
        return Err(format!("a PFM's size is \"WIDTH HEIGHT\", not {size:?}"));
    };
    let scale: f32 = scale
        .parse()
        .map_err(|_| format!("a PFM's scale is a number, not {scale:?}"))?;
    // Three f32s a pixel: 12 bytes. The size is the file's word, so the
    // product is checked (4294967295² × 12 overflows a 64-bit usize).
    let expected = (width as usize)
        .checked_mul(height as usize)
        .and_then(|count| count.checked_mul(12));
    if expected != Some(body.len()) {
        let expected = expected.map_or("more than 2⁶⁴".to_owned(), |n| n.to_string());
        return Err(format!(
            "a {width}×{height} PFM holds {expected} bytes of pixels, this one {}",
            body.len()
        ));
    }
    let value = |b: &[u8]| {
        let b: [u8; 4] = b.try_into().expect("four bytes");
        if scale < 0.0 {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        }
    };
    let mut rows: Vec<Vec<Color>> = body
        .chunks_exact(12 * width.max(1) as usize)
        .map(|row| {
            row.chunks_exact(12)
                .map(|c| Color::new(value(&c[0..4]), value(&c[4..8]), value(&c[8..12])))
                .collect()
        })
        .collect();
    rows.reverse();
    Ok(Image {
        width,
        height,
        pixels: rows.into_iter().flatten().collect(),
    })
}

/// The three header lines and the bytes after them.
fn split_header(bytes: &[u8]) -> Result<([&str; 3], &[u8]), String> {
    let mut lines = [""; 3];
    let mut rest = bytes;
    for line in &mut lines {
        let end = rest
            .iter()
            .position(|&b| b == b'\n')
            .filter(|&end| end < 64)
            .ok_or("not a PFM: its header is not three short lines")?;
        *line = std::str::from_utf8(&rest[..end])
            .map_err(|_| "not a PFM: its header is not text")?
            .trim();
        rest = &rest[end + 1..];
    }
    Ok((lines, rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture() -> Image {
        Image {
            width: 2,
            height: 2,
            pixels: vec![
                Color::new(0.0, 1.5, -0.25),
                Color::new(1e-8, 2.0, 3.0),
                Color::new(4.0, 5.0, 6.0),
                Color::new(7.0, 8.0, 9.0),
            ],
        }
    }

    #[test]
    fn a_picture_reads_back_bit_for_bit_unclamped() {
        assert_eq!(decode(&encode(&picture())).unwrap(), picture());
    }

    #[test]
    fn the_bottom_row_comes_first_little_endian() {
        let bytes = encode(&picture());
        let header = b"PF\n2 2\n-1.0\n";
        assert_eq!(&bytes[..header.len()], header);
        let first = f32::from_le_bytes(bytes[header.len()..header.len() + 4].try_into().unwrap());
        assert_eq!(first, 4.0, "the bottom-left pixel's red");
    }

    #[test]
    fn a_cut_or_foreign_file_is_refused() {
        let bytes = encode(&picture());
        assert!(
            decode(&bytes[..bytes.len() - 1])
                .unwrap_err()
                .contains("holds")
        );
        assert!(
            decode(b"Pf\n1 1\n-1.0\n0000")
                .unwrap_err()
                .contains("colour")
        );
        assert!(
            decode(b"PF\n1\n-1.0\n")
                .unwrap_err()
                .contains("WIDTH HEIGHT")
        );
        assert!(decode(b"P6 2 2 255").is_err());
        // A size whose byte count overflows is refused, not a panic.
        assert!(
            decode(b"PF\n4294967295 4294967295\n-1.0\n0000")
                .unwrap_err()
                .contains("more than")
        );
    }
}
