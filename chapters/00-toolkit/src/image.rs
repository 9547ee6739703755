//! The image buffer: linear RGB pixels, rendered in parallel, written as PNG.

use std::io::Write;
use std::path::Path;

use rayon::prelude::*;

use crate::{Color, Stats};

/// A picture in linear RGB, row by row from the top left.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Color>,
}

impl Image {
    /// Computes every pixel with `pixel(x, y, stats)`, rows in parallel.
    ///
    /// Each pixel depends only on its own (x, y), so the picture is the same
    /// bytes whatever the number of threads; the statistics are sums of
    /// per-row counts, which do not depend on the order either. `on_row` is
    /// called once per finished row (for a progress bar).
    pub fn render(
        width: u32,
        height: u32,
        pixel: impl Fn(u32, u32, &mut Stats) -> Color + Sync,
        on_row: impl Fn() + Sync,
    ) -> (Image, Stats) {
        // Zeroed by the system (bytemuck's zeroed_vec: calloc), not cleared
        // one by one on this thread as vec![Color::ZERO; n] would be: each
        // page is first touched by the thread that renders into it. (Plain
        // f32 arrays, converted to Color afterwards, took tinyraytracer's
        // scene 1.06 times as long, 2 threads, whole process.)
        let mut pixels: Vec<Color> = bytemuck::zeroed_vec(width as usize * height as usize);
        let render_row = |y: usize, row: &mut [Color]| {
            let mut stats = Stats::default();
            for (x, out) in row.iter_mut().enumerate() {
                *out = pixel(x as u32, y as u32, &mut stats);
            }
            on_row();
            stats
        };
        // The first row on this thread, before the others start: an exercise
        // not written yet (its `todo!()`) panics here, once, rather than once
        // in every thread that reaches it at the same time.
        let first_row = (width as usize).min(pixels.len());
        let (first, rest) = pixels.split_at_mut(first_row);
        let first = render_row(0, first);
        let stats = rest
            .par_chunks_mut(width as usize)
            .enumerate()
            // Every row a task of its own, which an idle thread can take.
            // Left to split as it likes, rayon hands each thread a run of
            // rows to render in turn, and a thread whose run is the costly
            // part of the picture works on alone at the end while the other
            // waits: mount-3 at 1024², 2 threads, the last 0.31 s of 0.79
            // (book/appendix/performance.md, "Two threads").
            .with_max_len(1)
            .map(|(y, row)| render_row(y + 1, row))
            .reduce(Stats::default, |a, b| a + b);
        let stats = first + stats;
        let image = Image {
            width,
            height,
            pixels,
        };
        (image, stats)
    }

    /// The pixel at (x, y).
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Clamps each channel to [0, 1] and maps it linearly to 0..=255.
    ///
    /// The transfer function is the identity: a stored byte b means the linear
    /// value b/255. No sRGB curve is applied, so pixel values read straight
    /// off the lecture's formulas (half the light gives half the byte).
    pub fn to_rgb8(&self) -> ::image::RgbImage {
        let mut bytes = vec![0u8; 3 * self.pixels.len()];
        let row = 3 * self.width.max(1) as usize;
        let rows = bytes
            .par_chunks_mut(row)
            .zip(self.pixels.par_chunks(row / 3));
        rows.for_each(|(bytes, pixels)| {
            for (rgb, color) in bytes.chunks_exact_mut(3).zip(pixels) {
                rgb[0] = to_byte(color.x);
                rgb[1] = to_byte(color.y);
                rgb[2] = to_byte(color.z);
            }
        });
        ::image::RgbImage::from_raw(self.width, self.height, bytes).expect("buffer size")
    }

    /// The picture encoded as PNG bytes.
    pub fn to_png(&self) -> Vec<u8> {
        encode_png(&self.to_rgb8())
    }

    /// Writes a PNG atomically (see [`write_atomically`]).
    pub fn save_png(&self, path: &Path) -> std::io::Result<()> {
        write_atomically(path, &self.to_png())
    }
}

/// A linear value clamped to [0, 1], times 255, rounded half away from zero:
/// `(v.clamp(0, 1) * 255).round()`, spelt out because on baseline x86-64
/// `f32::round` is a call into libm, and this runs three times a pixel.
/// For 0 ≤ x < 2²³, x − ⌊x⌋ is exact, so comparing it with ½ rounds exactly
/// as `round` does.
fn to_byte(v: f32) -> u8 {
    let x = v.clamp(0.0, 1.0) * 255.0;
    let whole = x as u8; // truncates: x ≥ 0
    whole + u8::from(x - f32::from(whole) >= 0.5)
}

/// Encodes an 8-bit RGB image as PNG.
pub fn encode_png(image: &::image::RgbImage) -> Vec<u8> {
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            ::image::ImageFormat::Png,
        )
        .expect("encoding a PNG in memory cannot fail");
    bytes
}

/// Writes `bytes` to a temporary file beside `path`, then renames it into
/// place: a reader sees the old file or the new one, never half of one, and an
/// interrupted render leaves the old picture intact.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir)?;
    let mut file = tempfile::NamedTempFile::new_in(dir)?;
    file.write_all(bytes)?;
    file.as_file().sync_all()?;
    // A temporary file is private (0600); the picture should not be.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        file.as_file()
            .set_permissions(std::fs::Permissions::from_mode(0o644))?;
    }
    file.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::to_byte;

    /// Every f32 from −0.5 to 1.5 in steps of 2⁻²⁴ near the rounding points
    /// and beyond: the spelt-out rounding equals `f32::round`'s.
    #[test]
    fn to_byte_rounds_as_round_does() {
        let round = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        let mut v = -0.5f32;
        while v < 1.5 {
            assert_eq!(to_byte(v), round(v), "at {v:e}");
            v = v.next_up().max(v + 1e-7);
        }
        for b in 0..255u8 {
            // The values just around each half-way point b + ½.
            let half = (f32::from(b) + 0.5) / 255.0;
            for v in [half.next_down(), half, half.next_up()] {
                assert_eq!(to_byte(v), round(v), "at {v:e}");
            }
        }
        assert_eq!(to_byte(f32::NAN), round(f32::NAN));
    }
}
