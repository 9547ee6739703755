//! `raybook accuracy`: every row is measured against one reference whose
//! own error is known, no row reads as exact, the error splits into bias²
//! and variance, and the report's rankings follow from its numbers. Times
//! are measured and reported, never asserted.

use std::path::PathBuf;
use std::sync::OnceLock;

use indicatif::ProgressBar;
use measure::accuracy::{
    Estimate, FLOOR_FACTOR, Floor, Plan, Sampling, Setting, Spread, Study, Summary, Tracer,
    Verdict, best_within, bias_cell, by_efficiency, csv, page, pareto, reference, study,
};
use raybook::scene_files;
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Effects;
use raybook::tracer::Termination;

#[path = "accuracy/verdicts.rs"]
mod verdicts;

/// A folder of its own for this test binary's cached references.
fn cache() -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("accuracy-{}", std::process::id()))
}

/// A small study of the showcase: 32×24 pixels, depths 1 and 16,
/// thresholds 0.01 and 0, the centre ray and 1, 4 and 16 jittered rays,
/// against a reference of 2 × 256 rays per pixel.
fn small_study() -> &'static Study {
    static STUDY: OnceLock<Study> = OnceLock::new();
    STUDY.get_or_init(|| {
        let showcase = raybook::CHAPTER.default_scene().unwrap();
        let mut plan = Plan::new(true, Termination::of(&showcase));
        (plan.width, plan.height) = (32, 24);
        plan.depths = vec![1, 16];
        plan.thresholds = vec![0.01, 0.0];
        plan.samplings = [1, 4, 16].map(Sampling::Jittered).to_vec();
        plan.samplings.insert(0, Sampling::Centre);
        plan.reference_samples = 256;
        plan.seeds = 4;
        study(&showcase, plan, &cache(), |_, _, _| ProgressBar::hidden()).0
    })
}

/// Every row of a study: the grid's and the effects'.
fn every_row(study: &Study) -> impl Iterator<Item = &Summary> {
    study
        .grid
        .iter()
        .chain(study.effects.iter().map(|(_, r)| r))
}

#[test]
fn every_row_is_above_the_references_own_error_or_marked_at_its_floor() {
    let study = small_study();
    assert!(study.floor.mse > 0.0, "two independent renders differ");
    for r in every_row(study) {
        let name = r.setting.name();
        assert!(
            r.mse.value > study.floor.mse || r.at_floor,
            "{name}: {} ≤ the floor {}",
            r.mse.value,
            study.floor.mse
        );
        assert_eq!(
            r.at_floor,
            r.mse.value + 2.0 * r.mse.se <= FLOOR_FACTOR * study.floor.mse,
            "{name}"
        );
    }
    let report = page(study);
    assert!(!report.contains('∞') && !report.contains("inf"), "{report}");
}

/// A study's every "at floor" is backed by its standard error: no bias²
/// reads "at floor" unless 2 SE above it is within the limit, and every
/// row whose SE is too large says it cannot tell.
#[test]
fn no_at_floor_contradicts_its_standard_error() {
    let study = small_study();
    let floor = study.floor;
    for r in every_row(study) {
        let cell = bias_cell(r, floor);
        let upper = r.bias2.value + 2.0 * r.bias2.se;
        let room = floor.limit() - floor.mse;
        assert_eq!(
            cell.starts_with("at floor"),
            upper <= floor.limit() && 2.0 * r.bias2.se <= room,
            "{}: {cell}",
            r.setting.name()
        );
        if r.setting.sampling.is_random() {
            assert!(r.bias2.se > 0.0, "{}: seeds differ", r.setting.name());
            assert!(cell.contains('±'), "{}: {cell}", r.setting.name());
        }
    }
}

#[test]
fn no_rmse_reads_zero_and_no_psnr_is_infinite() {
    let study = small_study();
    for r in every_row(study) {
        assert!(r.rmse > 0.0, "{}", r.setting.name());
        assert!(!r.psnr.to_string().contains("inf"), "{}", r.setting.name());
    }
}

#[test]
fn the_mean_mse_splits_into_bias_squared_and_variance() {
    for r in every_row(small_study()) {
        let name = r.setting.name();
        assert!(
            (r.bias2.value + r.variance.value - r.mse.value).abs() <= 1e-9 * r.mse.value,
            "{name}"
        );
        assert_eq!(r.renders, 4, "{name}: four seeds");
        match r.setting.sampling {
            Sampling::Centre => {
                assert_eq!(
                    r.variance,
                    Estimate::exact(0.0),
                    "{name}: no seed, no variance"
                );
                assert_eq!(r.bias2.se, 0.0, "{name}: known exactly");
            }
            Sampling::Jittered(_) => assert!(r.variance.value > 0.0, "{name}: seeds differ"),
        }
    }
}

#[test]
fn jittered_error_falls_with_samples_and_one_sample_is_mostly_variance() {
    let study = small_study();
    let curve = study.curve(study.most_accurate());
    assert_eq!(curve.len(), 3);
    for pair in curve.windows(2) {
        assert!(
            pair[1].mse.value < pair[0].mse.value,
            "{} then {}",
            pair[0].setting.name(),
            pair[1].setting.name()
        );
    }
    assert!(
        curve[0].variance.value > 10.0 * curve[0].bias2.value.max(0.0),
        "{:?}",
        curve[0]
    );
}

#[test]
fn a_cached_reference_is_read_back_and_another_size_is_not() {
    let showcase = raybook::CHAPTER.default_scene().unwrap().with_size(16, 12);
    let folder = tempfile::tempdir().unwrap();
    let setting = measure::accuracy::reference_setting(16);
    let made = reference(&showcase, &setting, folder.path(), &|| {});
    let read = reference(&showcase, &setting, folder.path(), &|| {});
    assert!(!made.from_cache && read.from_cache);
    assert_eq!((made.image, made.floor_mse), (read.image, read.floor_mse));
    let other = reference(&showcase.with_size(12, 9), &setting, folder.path(), &|| {});
    assert!(!other.from_cache, "another size is another reference");
}

#[test]
fn error_falls_with_depth_in_the_mirror_corridor() {
    let root = raybook::workbench::snapshot::workspace_root();
    let corridor: Scene =
        scene_files::load(root.join("chapters/05-reflection/scenes/corridor.toml")).unwrap();
    let mut plan = Plan::new(true, Termination::of(&corridor));
    (plan.width, plan.height) = (24, 18);
    plan.depths = vec![0, 1, 2, 4, 8];
    plan.thresholds = vec![0.0];
    plan.samplings = vec![Sampling::Jittered(1)];
    plan.reference_samples = 16;
    let (study, _) = study(&corridor, plan, &cache(), |_, _, _| ProgressBar::hidden());
    let tolerance = study.floor.limit();
    for pair in study.grid.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        assert!(
            b.mse.value <= a.mse.value + tolerance,
            "{} has MSE {} but {} has {}",
            b.setting.name(),
            b.mse.value,
            a.setting.name(),
            a.mse.value
        );
    }
    // One jittered ray's noise is the same at every depth; what depth 0
    // leaves out shows in the bias².
    let (shallow, deep) = (&study.grid[0], &study.grid[4]);
    assert!(
        shallow.bias2.value > 10.0 * deep.bias2.value.max(tolerance),
        "the corridor needs its bounces: bias² {} at depth 0, {} at depth 8",
        shallow.bias2,
        deep.bias2
    );
    assert_eq!(
        study.floor.judge(shallow.bias2),
        Verdict::Above,
        "{}",
        shallow.bias2
    );
}

#[test]
fn the_csv_has_a_record_per_row_and_no_nan_or_infinity() {
    let study = small_study();
    let rows = study.grid.iter().map(|r| ("grid", r));
    let text = csv(
        rows.chain(study.effects.iter().map(|(_, r)| ("effects", r))),
        study.floor,
    );
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header = reader.headers().unwrap().clone();
    for field in [
        "group",
        "max_depth",
        "min_weight",
        "sampling",
        "rays",
        "seconds_median",
        "mse",
        "mse_se",
        "bias2",
        "bias2_se",
        "bias2_verdict",
        "variance",
        "variance_se",
        "relative_mse",
        "psnr_8bit_db",
        "at_floor",
        "efficiency",
    ] {
        assert!(header.iter().any(|h| h == field), "{field} in {header:?}");
    }
    let records: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(records.len(), every_row(study).count());
    for record in &records {
        assert!(
            !record
                .iter()
                .any(|c| c.contains("NaN") || c.contains("inf")),
            "{record:?}"
        );
    }
}

/// A row of a fixture table: its setting, seconds (and a million rays a
/// second) and MSE, all of it variance (no spread, no bias).
fn fixture(depth: u32, samples: u32, seconds: f64, mse: f64) -> Summary {
    Summary {
        setting: Setting {
            termination: Termination {
                max_depth: depth,
                min_weight: 0.0,
            },
            sampling: Sampling::Jittered(samples),
            effects: Effects::ALL,
            tracer: Tracer::Complete,
        },
        rays: (seconds * 1e6) as u64,
        time: Spread {
            median: seconds,
            min: seconds,
            max: seconds,
        },
        renders: 4,
        mse: Estimate {
            value: mse,
            se: 0.0,
        },
        rmse: mse.sqrt(),
        rmse_sd: 0.0,
        bias2: Estimate {
            value: 0.0,
            se: 0.0,
        },
        variance: Estimate {
            value: mse,
            se: 0.0,
        },
        relative_mse: mse,
        psnr: measure::accuracy::Psnr::of(mse * 65025.0, 100),
        pixels_off: 0.0,
        flip: None,
        at_floor: false,
        judged_on: None,
    }
}

/// The depths of `rows`, in order: each fixture row has its own depth.
fn depths(rows: &[&Summary]) -> Vec<u32> {
    rows.iter()
        .map(|r| r.setting.termination.max_depth)
        .collect()
}

/// The depth of the best row within `rays`.
fn best_depth(rows: &[Summary], floor: Floor, rays: f64) -> u32 {
    best_within(rows, floor, rays)
        .unwrap()
        .setting
        .termination
        .max_depth
}

#[test]
fn the_rankings_follow_the_numbers_of_the_table() {
    let floor = Floor { mse: 1e-7 };
    let mut rows = vec![
        fixture(1, 1, 0.01, 1e-2),
        fixture(2, 4, 0.05, 4e-3),
        fixture(3, 16, 0.2, 1e-3),
        fixture(4, 4, 0.1, 5e-3),
    ];
    assert_eq!(
        depths(&pareto(&rows, floor)),
        [1, 2, 3],
        "4 traces more rays and is worse than 2"
    );
    assert_eq!(best_depth(&rows, floor, 1e5), 2);
    assert_eq!(depths(&by_efficiency(&rows, floor))[0], 1);
    // One number changed: row 4's MSE. It now beats row 3 and leads.
    rows[3].mse.value = 5e-4;
    assert_eq!(depths(&pareto(&rows, floor)), [1, 2, 4]);
    assert_eq!(best_depth(&rows, floor, 1e5), 4);
    assert_eq!(depths(&by_efficiency(&rows, floor))[0], 4);
    // Time plays no part: row 4 slower than every other, the same ranks.
    rows[3].time.median = 100.0;
    assert_eq!(depths(&pareto(&rows, floor)), [1, 2, 4]);
}

#[test]
fn efficiency_is_shown_only_where_the_bias_is_negligible() {
    let floor = Floor { mse: 1e-7 };
    let mut row = fixture(1, 16, 0.1, 1e-3);
    assert!(row.efficiency(floor).is_some(), "all variance");
    // A bias² of a fifth of the MSE: more rays buy nothing against it.
    row.bias2 = Estimate {
        value: 2e-4,
        se: 1e-6,
    };
    assert!(row.efficiency(floor).is_none());
    // Small, but its SE lets it be large: not shown either.
    row.bias2 = Estimate {
        value: 1e-5,
        se: 1e-4,
    };
    assert!(row.efficiency(floor).is_none());
    assert!(by_efficiency(&[row.clone()], floor).is_empty());
    // One centre ray is all bias, whatever its numbers.
    row.bias2 = Estimate::exact(0.0);
    row.setting.sampling = Sampling::Centre;
    assert!(row.efficiency(floor).is_none());
}

#[test]
fn errors_closer_than_the_floor_rank_as_equal_and_the_cheaper_wins() {
    let floor = Floor { mse: 1e-4 };
    let rows = vec![fixture(1, 4, 0.10, 2.0e-3), fixture(2, 4, 0.12, 1.9e-3)];
    // 1.9e-3 is within 4 × 1e-4 of 2.0e-3: no better, and dearer.
    assert_eq!(depths(&pareto(&rows, floor)), [1]);
    assert_eq!(best_depth(&rows, floor, 1e6), 1);
    let sharp = Floor { mse: 1e-6 };
    assert_eq!(depths(&pareto(&rows, sharp)), [1, 2]);
    assert_eq!(best_depth(&rows, sharp, 1e6), 2);
}
