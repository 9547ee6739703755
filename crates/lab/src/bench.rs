//! One chapter's bench: build the chapter, render its default scene with
//! the student's own code, and set the picture beside the reference with a
//! map of where they differ and `workbook verify`'s diagnosis.

use std::path::Path;
use std::process::{Command, Stdio};

use image::{Rgb, RgbImage};
use serde::Serialize;
use workbook::toolkit::image::encode_png;
use workbook::verify::{self, Reference};
use workbook::workbench::chapters::ChapterEntry;
use workbook::workbench::compare::Tolerance;

use crate::chapter;

/// What the bench shows of a chapter.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Bench {
    /// The chapter's folder.
    pub chapter: String,
    /// The compiler's errors, `file:line:column: error: …`, if it does not build.
    pub build_errors: Vec<String>,
    /// The exercise whose `todo!` the render reached: its id and hint.
    pub todo: Option<(String, String)>,
    /// Any other failure of the render.
    pub failure: Option<String>,
    /// verify's verdict, as it prints it (`PASS`/`FAIL` and the sizes).
    pub verdict: Option<String>,
    /// Did the picture pass?
    pub passed: bool,
    /// verify's diagnosis of a failing picture.
    pub diagnosis: Option<String>,
    /// The boxes of the regions that differ: x0, y0, x1, y1 (inclusive).
    pub regions: Vec<[u32; 4]>,
    /// How long the build and the render took, in seconds.
    pub build_seconds: f64,
    pub render_seconds: f64,
    /// From the save that asked for it to the picture, in seconds.
    pub since_save: Option<f64>,
}

/// The pictures of a bench: the student's and the difference map, as PNG.
pub struct Pictures {
    pub student: Option<Vec<u8>>,
    pub difference: Option<Vec<u8>>,
}

/// The reference of a bench chapter (every bench chapter has one).
pub fn reference_of(chapter: &ChapterEntry) -> Result<Reference, String> {
    verify::reference(&chapter.folder)
        .ok_or_else(|| format!("chapter {} has no reference picture", chapter.folder))
}

/// Builds the chapter's binary and renders its picture; `work` is a folder
/// of the lab's own for the files it writes.
pub fn run(root: &Path, chapter: &ChapterEntry, work: &Path) -> (Bench, Pictures) {
    let mut bench = Bench {
        chapter: chapter.folder.clone(),
        ..Bench::default()
    };
    let mut pictures = Pictures {
        student: None,
        difference: None,
    };
    let started = std::time::Instant::now();
    bench.build_errors = match build(root, chapter) {
        Ok(()) => Vec::new(),
        Err(errors) => errors,
    };
    bench.build_seconds = started.elapsed().as_secs_f64();
    if !bench.build_errors.is_empty() {
        return (bench, pictures);
    }
    let started = std::time::Instant::now();
    let folder = work.join(&chapter.folder);
    let _ = std::fs::create_dir_all(&folder);
    let picture = folder.join("yours.png");
    let output = chapter::run(root, chapter, &["-o", &picture.to_string_lossy()]);
    bench.render_seconds = started.elapsed().as_secs_f64();
    match output {
        Err(e) => bench.failure = Some(e),
        Ok(output) if !output.status.success() => {
            let stderr = String::from_utf8_lossy(&output.stderr);
            bench.todo = chapter::todo_reached(&stderr);
            if bench.todo.is_none() {
                bench.failure = Some(chapter::failure(&output));
            }
        }
        Ok(_) => compare(chapter, &picture, &folder, &mut bench, &mut pictures),
    }
    (bench, pictures)
}

/// verify's verdict and diagnosis of the student's `picture`, and the map.
fn compare(
    chapter: &ChapterEntry,
    picture: &Path,
    folder: &Path,
    bench: &mut Bench,
    pictures: &mut Pictures,
) {
    let outcome = reference_of(chapter)
        .and_then(|reference| verify::verify(&reference, picture, &folder.join("diff.png")));
    let outcome = match outcome {
        Ok(outcome) => outcome,
        Err(e) => {
            bench.failure = Some(e);
            return;
        }
    };
    bench.passed = outcome.verdict.passed();
    bench.verdict = Some(format!(
        "{}: {}",
        if bench.passed { "PASS" } else { "FAIL" },
        outcome.verdict
    ));
    bench.diagnosis = outcome.diagnosis.map(|d| d.to_string());
    pictures.student = std::fs::read(picture).ok();
    let expected = reference_of(chapter)
        .ok()
        .and_then(|r| image::load_from_memory(r.png).ok())
        .map(|i| i.to_rgb8());
    let actual = image::open(picture).ok().map(|i| i.to_rgb8());
    if let (Some(expected), Some(actual)) = (expected, actual)
        && expected.dimensions() == actual.dimensions()
    {
        let (map, regions) = difference_map(&expected, &actual);
        pictures.difference = Some(encode_png(&map));
        bench.regions = regions;
    }
}

/// Builds the chapter's binary (the debug build its tests use); Err: the
/// compiler's errors with file and line, as `cargo build` prints them.
pub fn build(root: &Path, chapter: &ChapterEntry) -> Result<(), Vec<String>> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let package = chapter.package();
    let output = Command::new(cargo)
        .args(["build", "-p", &package, "--bin", &package])
        .args(["--message-format", "short", "--color", "never"])
        .current_dir(root)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| vec![format!("cannot run cargo: {e}")])?;
    if output.status.success() {
        return Ok(());
    }
    Err(compiler_errors(&String::from_utf8_lossy(&output.stderr)))
}

/// The error lines of `cargo build --message-format short`
/// (`chapters/02-hits/src/sphere.rs:41:9: error[E0308]: mismatched types`),
/// or its last lines if it printed none.
pub fn compiler_errors(stderr: &str) -> Vec<String> {
    let errors: Vec<String> = stderr
        .lines()
        .filter(|l| l.contains(": error") && !l.starts_with("error"))
        .map(str::to_owned)
        .collect();
    if !errors.is_empty() {
        return errors;
    }
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    vec![lines[lines.len().saturating_sub(6)..].join("\n")]
}

/// The difference map: the reference in grey, each pixel that differs
/// beyond the snapshot tolerance in red (brighter as it differs more), and
/// a yellow box around each region of differing pixels. Also the boxes.
pub fn difference_map(expected: &RgbImage, actual: &RgbImage) -> (RgbImage, Vec<[u32; 4]>) {
    let tolerance = Tolerance::for_size(expected.width(), expected.height());
    let (width, height) = expected.dimensions();
    let mut map = RgbImage::new(width, height);
    let mut differs = vec![false; (width * height) as usize];
    for (x, y, e) in expected.enumerate_pixels() {
        let a = actual.get_pixel(x, y);
        let largest = (0..3).map(|c| e[c].abs_diff(a[c])).max().unwrap_or(0);
        let grey = ((e[0] as u32 + e[1] as u32 + e[2] as u32) / 3 / 3) as u8;
        let pixel = if largest > tolerance.channel {
            differs[(y * width + x) as usize] = true;
            Rgb([128 + largest / 2, 0, 0])
        } else {
            Rgb([grey, grey, grey])
        };
        map.put_pixel(x, y, pixel);
    }
    let boxes = regions(&differs, width, height);
    for &[x0, y0, x1, y1] in &boxes {
        outline(
            &mut map,
            [x0.saturating_sub(1), y0.saturating_sub(1), x1 + 1, y1 + 1],
        );
    }
    (map, boxes)
}

/// The boxes of the groups of differing pixels: pixels within 3 of each
/// other belong to one group, so that a speckled region gets one box.
fn regions(differs: &[bool], width: u32, height: u32) -> Vec<[u32; 4]> {
    const REACH: i64 = 3;
    let mut seen = vec![false; differs.len()];
    let mut boxes = Vec::new();
    for start in 0..differs.len() {
        if !differs[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        let mut stack = vec![start];
        let (mut x0, mut y0, mut x1, mut y1) = (u32::MAX, u32::MAX, 0, 0);
        while let Some(i) = stack.pop() {
            let (x, y) = (i as u32 % width, i as u32 / width);
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
            for dy in -REACH..=REACH {
                for dx in -REACH..=REACH {
                    let (nx, ny) = (x as i64 + dx, y as i64 + dy);
                    if nx < 0 || ny < 0 || nx >= width as i64 || ny >= height as i64 {
                        continue;
                    }
                    let j = (ny * width as i64 + nx) as usize;
                    if differs[j] && !seen[j] {
                        seen[j] = true;
                        stack.push(j);
                    }
                }
            }
        }
        boxes.push([x0, y0, x1, y1]);
    }
    boxes
}

/// Draws a yellow box's edges (clipped to the picture).
fn outline(map: &mut RgbImage, [x0, y0, x1, y1]: [u32; 4]) {
    let (width, height) = map.dimensions();
    let (x1, y1) = (x1.min(width - 1), y1.min(height - 1));
    let yellow = Rgb([255, 220, 0]);
    for x in x0..=x1 {
        map.put_pixel(x, y0, yellow);
        map.put_pixel(x, y1, yellow);
    }
    for y in y0..=y1 {
        map.put_pixel(x0, y, yellow);
        map.put_pixel(x1, y, yellow);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_group_of_differing_pixels_gets_one_box() {
        let expected = RgbImage::new(40, 30);
        let mut actual = expected.clone();
        for (x, y) in [(5, 5), (7, 6), (30, 20), (31, 22)] {
            actual.put_pixel(x, y, Rgb([200, 0, 0]));
        }
        let (map, boxes) = difference_map(&expected, &actual);
        assert_eq!(boxes, [[5, 5, 7, 6], [30, 20, 31, 22]]);
        assert_eq!(map.get_pixel(4, 4), &Rgb([255, 220, 0]), "the outline");
        assert_eq!(map.get_pixel(5, 5)[0], 228, "the differing pixel, in red");
        assert_eq!(
            map.get_pixel(20, 15),
            &Rgb([0, 0, 0]),
            "the same: the grey reference"
        );
    }

    #[test]
    fn compiler_errors_keep_file_and_line() {
        let stderr = "   Compiling ch02-hits v0.1.0\n\
                      chapters/02-hits/src/sphere.rs:41:9: error[E0308]: mismatched types\n\
                      chapters/02-hits/src/sphere.rs:50:1: warning: unused\n\
                      error: could not compile `ch02-hits` (lib) due to 1 previous error\n";
        assert_eq!(
            compiler_errors(stderr),
            ["chapters/02-hits/src/sphere.rs:41:9: error[E0308]: mismatched types"]
        );
    }
}
