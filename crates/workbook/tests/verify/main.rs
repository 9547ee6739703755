//! `workbook verify` accepts a correct picture and names what is wrong with
//! a mistaken one.
//!
//! One test target (`cargo test -p workbook --test verify`), in modules:
//!
//! * `verdicts`: which pictures pass and which fail;
//! * `command`: `workbook verify` run as a command, its output and exit status;
//! * `writing`: mistakes in writing the picture that verify names (upside
//!   down, mirrored, gamma-encoded, BGR, wrapped colours);
//! * `camera`: mistakes of the camera that verify names (rays through pixel
//!   corners, the fov taken as horizontal, a swapped size);
//! * `unnamed`: wrong pictures that name no mistake, and what verify says instead;
//! * `object_maps`: the object maps beside the references are current;
//! * `lights`: so are the light maps, and verify names the light of a
//!   region (a wrong spot ramp);
//! * `trees`: `verify --tree`: the reference trees are current, and a
//!   student's tree that differs is named ray by ray and field by field;
//! * `facts`: the reference's facts of every pixel, which the lab shows, are current;
//! * `chapters`: each chapter's ray tree, as its binary builds it.
//!
//! Here: verifying a picture, and chapter 3's scene, which several use.

mod camera;
mod chapters;
mod command;
mod facts;
mod lights;
mod object_maps;
mod trees;
mod unnamed;
mod verdicts;
mod writing;

use std::path::PathBuf;

use workbook::toolkit::Scene;
use workbook::verify::{Diagnosis, Mistake, reference, verify};

/// A file of this run's temporary folder.
fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raybook-verify-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// A chapter's reference picture.
pub(crate) fn reference_image(chapter: &str) -> image::RgbImage {
    image::load_from_memory(reference(chapter).unwrap().png)
        .unwrap()
        .to_rgb8()
}

/// Saves `picture` as the temporary file `name`, and returns its path.
pub(crate) fn save(name: &str, picture: &image::RgbImage) -> PathBuf {
    let path = temp(name);
    picture.save(&path).unwrap();
    path
}

/// Whether verify passes `picture` against `chapter`'s reference.
pub(crate) fn passes(chapter: &str, picture: &image::RgbImage, name: &str) -> bool {
    let path = save(name, picture);
    let outcome = verify(
        &reference(chapter).unwrap(),
        &path,
        &temp(&format!("{name}.diff.png")),
    )
    .unwrap();
    println!("{name}: {}", outcome.verdict);
    outcome.verdict.passed()
}

/// Verifies a picture that must fail and returns what verify says about it
/// (printed, with the picture's path, to look at with `--nocapture`).
pub(crate) fn diagnosis(chapter: &str, picture: &image::RgbImage, name: &str) -> Diagnosis {
    let path = save(name, picture);
    let diff = temp(&format!("{name}.diff.png"));
    let outcome = verify(&reference(chapter).unwrap(), &path, &diff).unwrap();
    assert!(!outcome.verdict.passed(), "{name} passes");
    let diagnosis = outcome.diagnosis.expect("a failing picture is diagnosed");
    println!("{}: {}\n{diagnosis}", path.display(), outcome.verdict);
    diagnosis
}

/// The usual mistake a diagnosis names, if any.
pub(crate) fn named(diagnosis: &Diagnosis) -> Option<Mistake> {
    match diagnosis {
        Diagnosis::Mistake { mistake, .. } => Some(*mistake),
        Diagnosis::Differs(_) => None,
    }
}

/// Asserts that verify names `mistake` for `picture`, in words that contain `words`.
pub(crate) fn assert_named(
    chapter: &str,
    picture: &image::RgbImage,
    name: &str,
    mistake: Mistake,
    words: &str,
) {
    let diagnosis = diagnosis(chapter, picture, name);
    assert_eq!(named(&diagnosis), Some(mistake), "{diagnosis}");
    assert!(diagnosis.to_string().contains(words), "{diagnosis}");
}

/// Chapter 3's default scene at the reference size.
pub(crate) fn chapter3_scene() -> Scene {
    ch03_lambert::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(160, 120)
}
