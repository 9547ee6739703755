//! Chapter 7's page: what accuracy costs, live. The student picks a
//! maximum depth, a weight threshold, the rays per pixel and a seed; their
//! own chapter-7 binary renders the showcase at the study's size with
//! `--linear`, and the page gets the error against the converged reference
//! that travels with the handout (`accuracy/reference.pfm.gz`), the rays
//! traced and the time, to set beside the study's own curves (read from
//! its `accuracy.csv`).
//!
//! The error is the study's: the root of `raybook accuracy`'s MSE, on the
//! unclamped linear values (`crates/measure/src/accuracy/metrics.rs`), so
//! that a point of the page and a row of the study mean the same thing
//! (`crates/measure/tests/lab_accuracy.rs` checks that they agree).
//!
//! A render runs on a thread of its own: the page asks, polls, and is
//! never blocked by a slow setting.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use serde::Serialize;
use workbook::toolkit::{Color, Image};
use workbook::workbench::chapters::ChapterEntry;

use crate::chapter;

mod runs;
mod study;

pub use runs::Runs;
pub use study::study;

/// The chapter whose page this is.
pub const CHAPTER: &str = "07-termination";

/// The study's folder in the workspace: its `accuracy.csv` and the
/// reference it measured against.
pub const STUDY: &str = "chapters/07-termination/accuracy";

/// The most rays per pixel the page renders: 64 jittered rays take about
/// 10 s in a debug build on two cores, the largest the study's quick look
/// measures is 16.
pub const MOST_RAYS: u32 = 64;

/// How long a render may take before it is stopped.
const PATIENCE: Duration = Duration::from_secs(120);

/// The rays per pixel: one through the centre, or N jittered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Rays {
    Centre,
    Jittered(u32),
}

/// A setting of the page, as the study names its rows.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Settings {
    pub max_depth: u32,
    pub min_weight: f32,
    pub rays: Rays,
    /// The seed of the jittered rays' positions (unused by the centre ray).
    pub seed: u64,
}

impl Settings {
    /// The settings in the page's query (`max_depth`, `min_weight`,
    /// `rays` = `centre` or a square N up to [`MOST_RAYS`], `seed`), or a
    /// message that says which is wrong and what would do.
    pub fn parse<'a>(get: impl Fn(&str) -> Option<&'a str>) -> Result<Settings, String> {
        let text = |key: &str| get(key).map(str::trim).filter(|t| !t.is_empty());
        let max_depth = match text("max_depth").map(str::parse::<u32>) {
            Some(Ok(d)) if d <= 64 => d,
            _ => return Err("the maximum depth is a whole number from 0 to 64".into()),
        };
        let min_weight = match text("min_weight").map(str::parse::<f32>) {
            // `-0` is in range: as 0, not as `-0`, which reads as an option.
            Some(Ok(w)) if (0.0..=1.0).contains(&w) => w.abs(),
            _ => return Err("the weight threshold is a number from 0 to 1 (0: none)".into()),
        };
        let rays = match text("rays") {
            Some("centre") => Rays::Centre,
            Some(n) => match n.parse::<u32>() {
                Ok(n) if (1..=MOST_RAYS).contains(&n) && is_square(n) => Rays::Jittered(n),
                _ => {
                    return Err(format!(
                        "the rays per pixel are \"centre\" or a square number of jittered rays \
                         from 1 to {MOST_RAYS} (1, 4, 9, 16, …), not {n:?}"
                    ));
                }
            },
            None => return Err("how many rays per pixel? \"centre\" or 1, 4, 16, …".into()),
        };
        let seed = match text("seed").map(str::parse::<u64>) {
            None if rays == Rays::Centre => 0,
            Some(Ok(seed)) => seed,
            _ => return Err("the seed is a whole number from 0 to 2⁶⁴ − 1".into()),
        };
        Ok(Settings {
            max_depth,
            min_weight,
            rays,
            seed,
        })
    }

    /// The chapter binary's options for this setting: the study's rows
    /// (`crates/measure/src/accuracy/measure.rs`, `scene_for`): one ray
    /// through the centre has no seed; N jittered rays have theirs. Each
    /// as `--option=value`, so that no value is ever read as an option.
    pub fn args(&self) -> Vec<String> {
        let mut args = vec![
            format!("--max-depth={}", self.max_depth),
            format!("--min-weight={}", self.min_weight),
        ];
        match self.rays {
            Rays::Centre => args.push("--samples=1".to_owned()),
            Rays::Jittered(n) => {
                args.push(format!("--samples={n}"));
                args.push(format!("--seed={}", self.seed));
            }
        }
        args
    }

    /// As the study names a setting: `depth 6, threshold 0.001, 16 jittered`.
    pub fn name(&self) -> String {
        let rays = match self.rays {
            Rays::Centre => "centre".to_owned(),
            Rays::Jittered(n) => format!("{n} jittered, seed {}", self.seed),
        };
        format!(
            "depth {}, threshold {}, {rays}",
            self.max_depth, self.min_weight
        )
    }
}

fn is_square(n: u32) -> bool {
    (1..=n).take_while(|k| k * k <= n).any(|k| k * k == n)
}

/// One render of the page: its setting, its error and what it cost.
#[derive(Debug, Clone, Serialize)]
pub struct Point {
    pub settings: Settings,
    pub name: String,
    /// √MSE against the reference, on the linear values.
    pub rmse: f64,
    pub mse: f64,
    /// Rays of every kind traced, as the binary counts them.
    pub rays: u64,
    /// The render's own time, as the binary reports it (what the study
    /// times), and the whole request: start the binary, render, write,
    /// read back, compare.
    pub seconds: f64,
    pub wall_seconds: f64,
}

/// The most bytes the reference may unpack to: the study's is 128×96
/// (147 kB); a file of a few kB may unpack to gigabytes (all zeros).
const MOST_REFERENCE_BYTES: u64 = 64 << 20;

/// The reference the study measured against, carried with the handout:
/// `accuracy/reference.pfm.gz` (gzipped PFM, linear values).
pub fn reference(root: &Path) -> Result<Image, String> {
    let path = root.join(STUDY).join("reference.pfm.gz");
    let file = std::fs::File::open(&path).map_err(|e| {
        format!(
            "{}: {e} (made by `cargo run --release -- accuracy --quick --reference-only \
             --out {STUDY}` in the reference workspace)",
            path.display()
        )
    })?;
    let mut bytes = Vec::new();
    flate2::read::GzDecoder::new(file)
        .take(MOST_REFERENCE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{}: not gzip: {e}", path.display()))?;
    if bytes.len() as u64 > MOST_REFERENCE_BYTES {
        return Err(format!(
            "{}: unpacks to more than {MOST_REFERENCE_BYTES} bytes: not the study's reference",
            path.display()
        ));
    }
    workbook::workbench::pfm::decode(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The study's MSE (`metrics::mse` in `crates/measure`): the mean over
/// every channel of every pixel of (x − r)², in f64, on the unclamped
/// linear values, summed in the same order so that both give the same
/// number.
pub fn mse(image: &Image, reference: &Image) -> f64 {
    let channels = |c: Color| [c.x, c.y, c.z].map(f64::from);
    let sum: f64 = image
        .pixels
        .iter()
        .zip(&reference.pixels)
        .flat_map(|(&x, &r)| channels(x).into_iter().zip(channels(r)))
        .map(|(x, r)| (x - r) * (x - r))
        .sum();
    sum / (3 * image.pixels.len()).max(1) as f64
}

/// Renders `settings` with the student's chapter-7 binary (the debug
/// build, built first if missing) at the reference's size, into `work`,
/// and measures it against the reference.
pub fn measure(root: &Path, settings: &Settings, work: &Path) -> Result<Point, String> {
    measure_telling(root, settings, work, &|_| {})
}

/// [`measure`], telling `phase` what it does: `building` (when a file under
/// `chapters/` is newer than the binary: the point is of the student's
/// code as it is now), then `rendering`.
pub fn measure_telling(
    root: &Path,
    settings: &Settings,
    work: &Path,
    phase: &dyn Fn(&'static str),
) -> Result<Point, String> {
    let started = Instant::now();
    let entry = chapter::bench_chapter(CHAPTER)?;
    if is_stale(root, &chapter::binary(root, entry)) {
        phase("building");
        crate::bench::build(root, entry)
            .map_err(|errors| format!("your chapter 7 does not build:\n{}", errors.join("\n")))?;
    }
    phase("rendering");
    let reference = reference(root)?;
    let output = render(root, entry, settings, &reference, work)?;
    let image = std::fs::read(&output.pfm)
        .map_err(|e| format!("{}: {e}", output.pfm.display()))
        .and_then(|bytes| workbook::workbench::pfm::decode(&bytes))?;
    if (image.width, image.height) != (reference.width, reference.height) {
        return Err("your binary wrote a picture of another size than asked".into());
    }
    let mse = mse(&image, &reference);
    Ok(Point {
        settings: *settings,
        name: settings.name(),
        rmse: mse.sqrt(),
        mse,
        rays: output.rays,
        seconds: output.seconds,
        wall_seconds: started.elapsed().as_secs_f64(),
    })
}

/// Is the binary missing, or older than a file under `chapters/` (the
/// chapter and those it stands on)? A look at modification times, so that
/// a point of unchanged code does not wait for cargo (nor for its lock,
/// which `progress` may hold).
fn is_stale(root: &Path, binary: &Path) -> bool {
    let Ok(built) = std::fs::metadata(binary).and_then(|m| m.modified()) else {
        return true;
    };
    fn newer(folder: &Path, than: std::time::SystemTime) -> bool {
        let Ok(entries) = std::fs::read_dir(folder) else {
            return false;
        };
        entries.flatten().any(|entry| match entry.file_type() {
            Ok(t) if t.is_dir() => newer(&entry.path(), than),
            Ok(_) => entry
                .metadata()
                .and_then(|m| m.modified())
                .is_ok_and(|m| m > than),
            Err(_) => false,
        })
    }
    newer(&root.join("chapters"), built)
}

/// What a render of the page wrote and reported.
struct Rendered {
    pfm: PathBuf,
    rays: u64,
    seconds: f64,
}

/// Runs the binary on its default scene at the reference's size.
fn render(
    root: &Path,
    entry: &ChapterEntry,
    settings: &Settings,
    reference: &Image,
    work: &Path,
) -> Result<Rendered, String> {
    let folder = work.join(CHAPTER);
    std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    let (png, pfm) = (folder.join("accuracy.png"), folder.join("accuracy.pfm"));
    let (width, height) = (reference.width.to_string(), reference.height.to_string());
    let mut args = vec!["--width", &width, "--height", &height, "--quiet"];
    let (png_arg, pfm_arg) = (png.to_string_lossy(), pfm.to_string_lossy());
    args.extend(["-o", &png_arg, "--linear", &pfm_arg]);
    let setting_args = settings.args();
    args.extend(setting_args.iter().map(String::as_str));
    let output = chapter::run_with(root, entry, &args, PATIENCE)?;
    if !output.status.success() {
        return Err(chapter::failure(&output));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    let (rays, seconds) = reported(&stdout).ok_or_else(|| {
        let lines: Vec<&str> = stdout.lines().collect();
        let last = lines[lines.len().saturating_sub(8)..].join("\n");
        format!("your binary did not report its rays and time; its output ends:\n{last}")
    })?;
    Ok(Rendered { pfm, rays, seconds })
}

/// The rays and seconds in the report every chapter binary prints
/// (`wrote … in 0.123 s` and `29062 rays: …`).
fn reported(stdout: &str) -> Option<(u64, f64)> {
    let seconds = stdout
        .lines()
        .find_map(|l| {
            l.strip_prefix("wrote ")?
                .rsplit_once(" in ")?
                .1
                .strip_suffix(" s")
        })?
        .parse()
        .ok()?;
    let rays = stdout
        .lines()
        .find_map(|l| l.split_once(" rays: ")?.0.parse().ok())?;
    Some((rays, seconds))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    fn parse(pairs: &[(&str, &str)]) -> Result<Settings, String> {
        let map: BTreeMap<&str, &str> = pairs.iter().copied().collect();
        Settings::parse(|k| map.get(k).copied())
    }

    #[test]
    fn settings_name_the_binarys_options() {
        let s = parse(&[
            ("max_depth", "6"),
            ("min_weight", "0.001"),
            ("rays", "16"),
            ("seed", "3"),
        ])
        .unwrap();
        assert_eq!(
            s.args().join(" "),
            "--max-depth=6 --min-weight=0.001 --samples=16 --seed=3"
        );
        let centre = parse(&[("max_depth", "1"), ("min_weight", "0"), ("rays", "centre")]);
        assert_eq!(
            centre.unwrap().args().join(" "),
            "--max-depth=1 --min-weight=0 --samples=1"
        );
    }

    #[test]
    fn no_value_reaches_the_binary_as_an_option() {
        // `-0` parses as an f32 in 0..=1; passed on as `-0` it was taken by
        // the binary's parser for an option ("unexpected argument '-0'").
        let s = parse(&[("max_depth", "3"), ("min_weight", "-0"), ("rays", "centre")]).unwrap();
        assert!(s.min_weight.is_sign_positive());
        assert_eq!(s.name(), "depth 3, threshold 0, centre");
        for arg in s.args() {
            assert!(arg.starts_with("--") && arg.contains('='), "{arg}");
        }
    }

    #[test]
    fn bad_settings_say_what_would_do() {
        let good = [
            ("max_depth", "6"),
            ("min_weight", "0.001"),
            ("rays", "4"),
            ("seed", "1"),
        ];
        let with = |key: &str, value: &'static str| {
            let pairs: Vec<(&str, &str)> = good
                .iter()
                .map(|&(k, v)| (k, if k == key { value } else { v }))
                .collect();
            parse(&pairs).unwrap_err()
        };
        assert!(with("max_depth", "65").contains("0 to 64"));
        assert!(with("max_depth", "-1").contains("0 to 64"));
        assert!(with("min_weight", "NaN").contains("0 to 1"));
        assert!(with("min_weight", "2").contains("0 to 1"));
        assert!(with("rays", "5").contains("square"));
        assert!(with("rays", "256").contains("from 1 to 64"));
        assert!(with("seed", "x").contains("seed"));
    }

    #[test]
    fn the_report_gives_rays_and_seconds() {
        let stdout = "chapter 07-termination (T): rendered x\nwrote a.png (8×6 pixels) in 0.125 s\n\
                      29062 rays: 12288 primary, 1 shadow\npaths ended: 3 by no hit\n";
        assert_eq!(reported(stdout), Some((29062, 0.125)));
        assert_eq!(reported("nothing"), None);
    }

    #[test]
    fn a_binary_older_than_a_chapter_file_is_built_again() {
        let root = std::env::temp_dir().join(format!("lab-stale-{}", std::process::id()));
        let source = root.join("chapters/07-termination/src/lib.rs");
        std::fs::create_dir_all(source.parent().unwrap()).unwrap();
        let binary = root.join("ch07");
        assert!(is_stale(&root, &binary), "no binary yet");
        let at = |file: &Path, seconds: u64| {
            let time = std::time::UNIX_EPOCH + Duration::from_secs(seconds);
            let file = std::fs::File::create(file).unwrap();
            file.set_modified(time).unwrap();
        };
        at(&source, 1_000);
        at(&binary, 2_000);
        assert!(!is_stale(&root, &binary), "built after the last edit");
        at(&source, 3_000);
        assert!(is_stale(&root, &binary), "edited since");
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_reference_that_unpacks_to_gigabytes_is_refused() {
        use std::io::Write;
        let root = std::env::temp_dir().join(format!("lab-bomb-{}", std::process::id()));
        std::fs::create_dir_all(root.join(STUDY)).unwrap();
        let file = std::fs::File::create(root.join(STUDY).join("reference.pfm.gz")).unwrap();
        let mut gz = flate2::write::GzEncoder::new(file, flate2::Compression::fast());
        let zeros = vec![0u8; 1 << 20];
        for _ in 0..=(MOST_REFERENCE_BYTES >> 20) {
            gz.write_all(&zeros).unwrap();
        }
        gz.finish().unwrap();
        let error = reference(&root).map(|_| ()).unwrap_err();
        assert!(error.contains("unpacks to more than"), "{error}");
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn the_mse_is_the_mean_square_over_channels() {
        let image = |v: f32| Image {
            width: 2,
            height: 1,
            pixels: vec![Color::splat(v), Color::splat(2.0)],
        };
        assert_eq!(mse(&image(1.5), &image(0.5)), 0.5);
    }
}
