//! The reference that travels with the handout,
//! `chapters/07-termination/accuracy/reference.pfm.gz` (chapter 7's lab
//! page measures a student's render against it), is the quick study's:
//! its size, and the very picture whose PNG the study wrote beside it.
//! Remade with `cargo run --release -- accuracy --quick --reference-only
//! --out chapters/07-termination/accuracy`.

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
