//! The reference that travels with the handout,
//! `chapters/07-termination/accuracy/reference.pfm.gz` (chapter 7's lab
//! page measures a student's render against it), is the quick study's:
//! its size, and the very picture whose PNG the study wrote beside it.
//! Remade with `cargo run --release -- accuracy --quick --reference-only
//! --out chapters/07-termination/accuracy`.

mod common;

use measure::accuracy::{Plan, REFERENCE_PFM_GZ, read_pfm_gz};
use raybook::tracer::Termination;
use raybook::workbench::snapshot::workspace_root;

#[test]
fn the_carried_reference_is_the_quick_studys_picture() {
    let folder = workspace_root().join("chapters/07-termination/accuracy");
    let linear = read_pfm_gz(&folder.join(REFERENCE_PFM_GZ)).unwrap();
    let showcase = raybook::CHAPTER.default_scene().unwrap();
    let plan = Plan::new(true, Termination::of(&showcase));
    assert_eq!((linear.width, linear.height), (plan.width, plan.height));
    // The study's reference.png is this picture clamped and rounded: a
    // reference.pfm.gz left over from another scene, size or tracer fails.
    let png = image::open(folder.join("reference.png")).unwrap().to_rgb8();
    assert_eq!(
        linear.to_rgb8(),
        png,
        "reference.png and reference.pfm.gz differ"
    );
    assert!(linear.pixels.iter().all(|c| c.is_finite()));
    let steps = |v: f32| (v * 255.0 - (v * 255.0).round()).abs();
    assert!(
        linear.pixels.iter().filter(|c| steps(c.y) > 0.01).count() > linear.pixels.len() / 2,
        "linear values between the 8-bit steps, not the PNG read back"
    );
}

#[test]
fn reference_only_writes_the_reference_and_no_study() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "accuracy",
        "--quick",
        "--reference-only",
        "--width",
        "8",
        "--height",
        "6",
        "--out",
        "out",
        "--cache",
        "cache",
    ];
    let run = common::raybook(dir.path(), &args);
    assert!(run.success, "{}", run.stderr);
    assert!(run.stdout.contains("made in"), "{}", run.stdout);
    let out = dir.path().join("out");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["reference.pfm.gz", "reference.png"], "no study");
    let linear = read_pfm_gz(&out.join(REFERENCE_PFM_GZ)).unwrap();
    assert_eq!((linear.width, linear.height), (8, 6));
    let png = image::open(out.join("reference.png")).unwrap().to_rgb8();
    assert_eq!(linear.to_rgb8(), png);
    // Again: read from the cache, the same bytes.
    let first = std::fs::read(out.join(REFERENCE_PFM_GZ)).unwrap();
    let again = common::raybook(dir.path(), &args);
    assert!(again.stdout.contains("read from"), "{}", again.stdout);
    assert_eq!(std::fs::read(out.join(REFERENCE_PFM_GZ)).unwrap(), first);
}
