//! The one truth every row is measured against: the scene rendered far
//! more accurately than any row, twice with independent seeds, and the
//! error it still has, estimated from the two. Kept on disk, since it is
//! the dearest render of the study.

use std::path::{Path, PathBuf};

use raybook::toolkit::image::write_atomically;
use raybook::toolkit::{Color, Image, Scene};

use super::measure::render_timed;
use super::metrics;
use super::settings::Setting;

/// The seeds of the reference's two renders: none of them is a row's seed
/// (rows use 1, 2, 3, ...), so the rows' noise and the reference's are
/// independent.
pub const REFERENCE_SEEDS: [u64; 2] = [1_000_001, 1_000_002];

/// Bumped when the file format or the way the reference is made changes,
/// so that an old file is not read as a new one.
const FORMAT: u32 = 1;

/// The reference picture and how good it is.
#[derive(Debug, Clone)]
pub struct Reference {
    /// The mean of the two renders: the picture rows are compared with.
    pub image: Image,
    /// The reference's own error, estimated from its two renders R₁, R₂:
    /// each has a variance σ² per value, so E[(R₁ − R₂)²] = 2σ², and their
    /// mean has σ²/2. Its MSE against the truth is therefore about
    /// mean((R₁ − R₂)²) / 4.
    pub floor_mse: f64,
    /// The same estimate for the relative MSE.
    pub floor_relative_mse: f64,
    /// The setting of each render (depth, threshold, rays per pixel).
    pub setting: Setting,
    /// Seconds its two renders took when it was made.
    pub seconds: f64,
    /// Rays traced by its two renders.
    pub rays: u64,
    /// Where it is cached, and whether it was read from there.
    pub cache: PathBuf,
    pub from_cache: bool,
}

/// The reference for `scene` (already at the study's size), read from
/// `cache_dir` if it holds one made from the same scene, setting and
/// version of raybook, else rendered (calling `on_row` per row rendered)
/// and written there.
pub fn reference(
    scene: &Scene,
    setting: &Setting,
    cache_dir: &Path,
    on_row: &(dyn Fn() + Sync),
) -> Reference {
    let key = cache_key(scene, setting);
    let cache = cache_dir.join(format!("reference-{:016x}.bin", fnv1a(key.as_bytes())));
    if let Some((halves, seconds, rays)) = read_cached(&cache, &key) {
        return from_halves(halves, *setting, seconds, rays, cache, true);
    }
    let renders = REFERENCE_SEEDS.map(|seed| render_timed(scene, setting, Some(seed), on_row));
    let seconds = renders.iter().map(|r| r.seconds).sum();
    let rays = renders.iter().map(|r| r.rays).sum();
    let halves = renders.map(|r| r.image);
    if let Err(e) = write_atomically(&cache, &encode(&key, &halves, seconds, rays)) {
        eprintln!(
            "note: cannot cache the reference in {}: {e}",
            cache.display()
        );
    }
    from_halves(halves, *setting, seconds, rays, cache, false)
}

/// The reference from its two renders.
fn from_halves(
    halves: [Image; 2],
    setting: Setting,
    seconds: f64,
    rays: u64,
    cache: PathBuf,
    from_cache: bool,
) -> Reference {
    let [a, b] = &halves;
    let pixels = a.pixels.iter().zip(&b.pixels);
    let image = Image {
        width: a.width,
        height: a.height,
        pixels: pixels.map(|(&p, &q)| (p + q) * 0.5).collect(),
    };
    Reference {
        floor_mse: metrics::mse(a, b) / 4.0,
        floor_relative_mse: halves_relative(a, b, &image) / 4.0,
        image,
        setting,
        seconds,
        rays,
        cache,
        from_cache,
    }
}

/// mean((R₁ − R₂)² / (R² + ε)) over every channel, R the mean picture.
fn halves_relative(a: &Image, b: &Image, mean: &Image) -> f64 {
    let mut sum = 0.0;
    for ((&p, &q), &r) in a.pixels.iter().zip(&b.pixels).zip(&mean.pixels) {
        let d = (p - q) * (p - q) / (r * r + Color::splat(metrics::RELATIVE_EPSILON as f32));
        sum += f64::from(d.x) + f64::from(d.y) + f64::from(d.z);
    }
    sum / (3 * a.pixels.len()).max(1) as f64
}

/// What the cached file must have been made from: raybook's version, this
/// format, the whole scene (size included), the setting and the seeds.
fn cache_key(scene: &Scene, setting: &Setting) -> String {
    format!(
        "raybook {} reference format {FORMAT}\n{setting:?}\nseeds {REFERENCE_SEEDS:?}\n{scene:?}",
        env!("CARGO_PKG_VERSION")
    )
}

/// The 64-bit FNV-1a hash of `bytes`: a file name for a key, the same in
/// every build (unlike std's hasher).
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// The file's bytes: the key's length and text, the seconds and rays, then
/// each picture's width, height and channels, little-endian.
fn encode(key: &str, halves: &[Image; 2], seconds: f64, rays: u64) -> Vec<u8> {
    let mut bytes = Vec::new();
    bytes.extend((key.len() as u64).to_le_bytes());
    bytes.extend(key.as_bytes());
    bytes.extend(seconds.to_le_bytes());
    bytes.extend(rays.to_le_bytes());
    for image in halves {
        bytes.extend(image.width.to_le_bytes());
        bytes.extend(image.height.to_le_bytes());
        for c in &image.pixels {
            for v in [c.x, c.y, c.z] {
                bytes.extend(v.to_le_bytes());
            }
        }
    }
    bytes
}

/// The two pictures, seconds and rays cached in `path` under `key`; `None`
/// if there is no such file, or it was made from anything else, or is cut.
fn read_cached(path: &Path, key: &str) -> Option<([Image; 2], f64, u64)> {
    let bytes = std::fs::read(path).ok()?;
    let mut reader = Reader(&bytes);
    let length = reader.u64()? as usize;
    if reader.take(length)? != key.as_bytes() {
        return None;
    }
    let seconds = f64::from_le_bytes(reader.take(8)?.try_into().ok()?);
    let rays = reader.u64()?;
    let mut image = || -> Option<Image> {
        let width = reader.u32()?;
        let height = reader.u32()?;
        let count = width as usize * height as usize;
        let mut pixels = Vec::with_capacity(count);
        for _ in 0..count {
            pixels.push(Color::new(reader.f32()?, reader.f32()?, reader.f32()?));
        }
        Some(Image {
            width,
            height,
            pixels,
        })
    };
    let halves = [image()?, image()?];
    reader.0.is_empty().then_some((halves, seconds, rays))
}

/// Reads little-endian numbers off the front of a byte slice.
struct Reader<'a>(&'a [u8]);

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let (head, rest) = self.0.split_at_checked(n)?;
        self.0 = rest;
        Some(head)
    }
    fn u32(&mut self) -> Option<u32> {
        Some(u32::from_le_bytes(self.take(4)?.try_into().ok()?))
    }
    fn u64(&mut self) -> Option<u64> {
        Some(u64::from_le_bytes(self.take(8)?.try_into().ok()?))
    }
    fn f32(&mut self) -> Option<f32> {
        Some(f32::from_le_bytes(self.take(4)?.try_into().ok()?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture(values: &[f32]) -> Image {
        Image {
            width: values.len() as u32,
            height: 1,
            pixels: values
                .iter()
                .map(|&v| Color::new(v, 2.0 * v, 0.5))
                .collect(),
        }
    }

    #[test]
    fn a_cached_reference_reads_back_only_under_its_own_key() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("r.bin");
        let halves = [picture(&[0.1, 0.2]), picture(&[0.3, 4.0])];
        std::fs::write(&path, encode("key", &halves, 1.5, 42)).unwrap();
        let (read, seconds, rays) = read_cached(&path, "key").unwrap();
        assert_eq!((read, seconds, rays), (halves, 1.5, 42));
        assert!(read_cached(&path, "another key").is_none());
        let bytes = std::fs::read(&path).unwrap();
        std::fs::write(&path, &bytes[..bytes.len() - 1]).unwrap();
        assert!(read_cached(&path, "key").is_none(), "a cut file");
    }

    #[test]
    fn the_floor_is_a_quarter_of_the_halves_mse() {
        let halves = [picture(&[0.0, 0.2]), picture(&[0.2, 0.2])];
        let setting = super::super::settings::reference_setting(4);
        let r = from_halves(halves, setting, 0.0, 0, PathBuf::new(), false);
        // Differences 0.2, 0.4, 0 in the first pixel, none in the second.
        let halves_mse = (0.04 + 0.16) / 6.0;
        assert!(
            (r.floor_mse - halves_mse / 4.0).abs() < 1e-9,
            "{}",
            r.floor_mse
        );
        assert_eq!(r.image.pixels[0], Color::new(0.1, 0.2, 0.5));
    }
}
