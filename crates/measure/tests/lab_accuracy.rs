//! The lab's chapter-7 page and `raybook accuracy` give the same error for
//! the same setting and seed: the page runs the chapter-7 binary with
//! `--linear` and measures it against the carried reference
//! (`accuracy/reference.pfm.gz`); the study renders with chapter 7's
//! tracer in this process and measures with its own `metrics`. Both are
//! the root of one MSE on the linear values: they agree to 1e-12.

use measure::accuracy::{
    REFERENCE_PFM_GZ, Sampling, Setting, Tracer, errors, read_pfm_gz, render_timed,
};
use raybook::toolkit::scene::Effects;
use raybook::tracer::Termination;
use raybook::workbench::snapshot::workspace_root;

/// The page's settings and the study's, side by side.
fn settings() -> Vec<(lab::accuracy::Settings, Setting, Option<u64>)> {
    use lab::accuracy::{Rays, Settings};
    let study = |max_depth, min_weight, sampling| Setting {
        termination: Termination {
            max_depth,
            min_weight,
        },
        sampling,
        effects: Effects::ALL,
        tracer: Tracer::Chapter7,
    };
    vec![
        (
            Settings {
                max_depth: 6,
                min_weight: 0.001,
                rays: Rays::Centre,
                seed: 0,
            },
            study(6, 0.001, Sampling::Centre),
            None,
        ),
        (
            Settings {
                max_depth: 2,
                min_weight: 0.01,
                rays: Rays::Jittered(4),
                seed: 3,
            },
            study(2, 0.01, Sampling::Jittered(4)),
            Some(3),
        ),
    ]
}

#[test]
fn the_lab_page_and_the_study_measure_the_same_error() {
    let root = workspace_root();
    let entry = lab::chapter::bench_chapter(lab::accuracy::CHAPTER).unwrap();
    // The binary as this source builds it, not a stale one.
    lab::bench::build(&root, entry).unwrap_or_else(|e| panic!("{}", e.join("\n")));
    let reference = read_pfm_gz(&root.join(lab::accuracy::STUDY).join(REFERENCE_PFM_GZ)).unwrap();
    let showcase = raybook::CHAPTER.default_scene().unwrap();
    let scene = showcase.with_size(reference.width, reference.height);
    let work = tempfile::tempdir().unwrap();
    for (page, study, seed) in settings() {
        let point = lab::accuracy::measure(&root, &page, work.path()).unwrap();
        let rendered = render_timed(&scene, &study, seed, &|| {});
        let rmse = errors(&rendered.image, &reference).mse.sqrt();
        let relative = (point.rmse - rmse).abs() / rmse;
        assert!(
            relative < 1e-12,
            "{}: the page's RMSE {} and the study's {rmse} differ by {relative:e}",
            point.name,
            point.rmse
        );
        assert_eq!(point.rays, rendered.rays, "{}: rays", point.name);
        assert!(rmse > 1e-3, "{}: an error to compare", point.name);
    }
}
