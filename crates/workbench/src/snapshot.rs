//! Image snapshots: every chapter's reference pictures, checked with insta.
//!
//! References live in `snapshots/<chapter>/<name>.snap.png` (beside insta's
//! `<name>.snap` metadata) and are ordinary PNGs you can open. A test renders
//! its picture and calls [`assert_image`]:
//!
//! * within the [`Tolerance`], insta is handed the reference's own bytes, so it
//!   sees no change (encoder versions and last-bit differences never matter);
//! * beyond it, the actual picture and a three-panel diff are written to
//!   `target/snapshot-failures/<chapter>/`, their paths and the size of the
//!   difference are printed, and the test fails. In the reference workspace
//!   insta is handed the new picture too, so that `cargo insta review` shows
//!   the change to accept or reject; in a student's handout it is not: the
//!   reference is right there, and a student who "accepted" their own
//!   picture would lose the check.

use std::path::{Path, PathBuf};

use crate::compare::{Tolerance, compare, diff_image};
use ch00_toolkit::Image;
use ch00_toolkit::image::{encode_png, write_atomically};

/// The workspace root (this crate lives in `crates/workbench`).
pub fn workspace_root() -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    root.canonicalize().unwrap_or(root)
}

/// Where a chapter's references are kept.
pub fn snapshot_dir(chapter: &str) -> PathBuf {
    workspace_root().join("snapshots").join(chapter)
}

/// The reference PNG of snapshot `name` of `chapter`.
pub fn reference_path(chapter: &str, name: &str) -> PathBuf {
    snapshot_dir(chapter).join(format!("{name}.snap.png"))
}

/// Where failed comparisons leave their pictures (git-ignored).
pub fn failure_dir(chapter: &str) -> PathBuf {
    workspace_root()
        .join("target")
        .join("snapshot-failures")
        .join(chapter)
}

/// Asserts that `image` matches the reference picture `name` of `chapter`,
/// within the snapshot tolerance for its size.
pub fn assert_image(chapter: &str, name: &str, image: &Image) {
    assert_image_beside(chapter, name, image, &[]);
}

/// A test of a chapter whose message names a mistake more precisely than a
/// picture can: its name, and the test's function.
pub type Precise = (&'static str, fn());

/// [`assert_image`], and when the picture differs, the precise tests
/// `beside` are run again here, each caught if it panics: the message
/// names those that fail, with what they say, before the count of pixels.
/// A count of pixels says that something is wrong; their messages say
/// what, and libtest's order of reports is not ours to set.
pub fn assert_image_beside(chapter: &str, name: &str, image: &Image, beside: &[Precise]) {
    let actual = image.to_rgb8();
    let reference = std::fs::read(reference_path(chapter, name)).ok();
    let explained = |report: String| match failing_beside(beside) {
        failing if failing.is_empty() => report,
        failing => format!("{}\n{report}", failing.join("\n")),
    };
    let bytes = match reference
        .as_deref()
        .map(|r| check(chapter, name, r, &actual).map_err(explained))
    {
        Some(Ok(())) => reference.expect("read above"),
        Some(Err(report)) if !is_reference() => panic!(
            "{report}\nyour picture differs from the chapter's reference picture: fix the code \
             until it matches (the reference is right; do not update it)"
        ),
        Some(Err(report)) => {
            eprintln!("{report}");
            encode_png(&actual)
        }
        None => encode_png(&actual),
    };
    insta::with_settings!({
        snapshot_path => snapshot_dir(chapter),
        prepend_module_to_snapshot => false,
        omit_expression => true,
    }, {
        insta::assert_binary_snapshot!(&format!("{name}.png"), bytes);
    });
}

/// The tests of `beside` that fail, each as a line that names it and
/// what it says (its panic message's first line).
fn failing_beside(beside: &[Precise]) -> Vec<String> {
    let mut failing = Vec::new();
    for (test, run) in beside {
        let Err(panic) = std::panic::catch_unwind(run) else {
            continue;
        };
        let message = (panic.downcast_ref::<String>().map(String::as_str))
            .or_else(|| panic.downcast_ref::<&str>().copied())
            .unwrap_or("(no message)");
        failing.push(format!(
            "the test {test} fails beside this picture, and says what is wrong (read it first): {}",
            message.lines().next().unwrap_or("")
        ));
    }
    failing
}

/// Is this the reference workspace, which holds the teacher's files (the
/// chapters' `mistakes.toml`), rather than a student's handout?
fn is_reference() -> bool {
    workspace_root()
        .join("chapters/01-rays/mistakes.toml")
        .is_file()
}

/// Compares with the reference PNG; on failure writes the actual and diff
/// pictures to [`failure_dir`] and returns a report naming them.
pub fn check(
    chapter: &str,
    name: &str,
    reference: &[u8],
    actual: &image::RgbImage,
) -> Result<(), String> {
    let expected = match image::load_from_memory(reference) {
        Ok(img) => img.to_rgb8(),
        Err(e) => {
            return Err(format!(
                "snapshot {chapter}/{name}: cannot decode the reference: {e}"
            ));
        }
    };
    let tolerance = Tolerance::for_size(actual.width(), actual.height());
    let verdict = compare(&expected, actual, tolerance);
    let dir = failure_dir(chapter);
    let actual_path = dir.join(format!("{name}.actual.png"));
    let diff_path = dir.join(format!("{name}.diff.png"));
    if verdict.passed() {
        // A picture that passes again leaves no old diff to mislead.
        let _ = std::fs::remove_file(&actual_path);
        let _ = std::fs::remove_file(&diff_path);
        return Ok(());
    }
    let diff = diff_image(&expected, actual, tolerance);
    let written = write_atomically(&actual_path, &encode_png(actual))
        .and_then(|()| write_atomically(&diff_path, &encode_png(&diff)));
    let files = match written {
        Ok(()) => format!(
            "  actual: {}\n  diff (expected | mask | actual): {}",
            actual_path.display(),
            diff_path.display()
        ),
        Err(e) => format!("  (could not write the failure pictures: {e})"),
    };
    Err(format!(
        "snapshot {chapter}/{name} differs from its reference: {verdict}\n\
         (tolerance: {} steps per channel, {} pixels)\n{files}",
        tolerance.channel, tolerance.pixels
    ))
}
