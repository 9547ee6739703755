//! `raybook accuracy`: every row is measured against one reference whose
//! own error is known, no row reads as exact, the error splits into bias²
//! and variance, and the report's rankings follow from its numbers. Times
//! are measured and reported, never asserted.

use std::path::PathBuf;
use std::sync::OnceLock;

use indicatif::ProgressBar;
use measure::accuracy::{
    Cost, FLOOR_FACTOR, Floor, Plan, Sampling, Setting, Spread, Study, Summary, Tracer,
    best_within, by_efficiency, csv, page, pareto, reference, study,
};
use raybook::scene_files;
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Effects;
use raybook::tracer::Termination;

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
            r.mse > study.floor.mse || r.at_floor,
            "{name}: {} ≤ the floor {}",
            r.mse,
            study.floor.mse
        );
        assert_eq!(
            r.at_floor,
            r.mse <= FLOOR_FACTOR * study.floor.mse,
            "{name}"
        );
    }
    // At 16 jittered rays and depth 16, the mean of the seeds is as close
    // to the reference as the reference lets anyone see: its bias² reads
    // "at floor", not a number.
    let best = study.curve(study.most_accurate());
    let best = best.last().unwrap();
    assert!(study.floor.holds(best.bias2), "{best:?}");
    let report = page(study);
    assert!(!report.contains('∞') && !report.contains("inf"), "{report}");
    assert!(report.contains("at floor"), "{report}");
}

#[test]
fn a_row_within_the_floor_reads_at_floor_and_shows_no_error_number() {
    let floor = Floor { mse: 1e-6 };
    let mut row = fixture(16, 16, 0.5, 3e-6);
    row.at_floor = floor.holds(row.mse);
    assert!(row.at_floor, "3e-6 is within 4 × 1e-6");
    let text = measure::accuracy::table([("near".to_owned(), &row)], floor);
    let cells: Vec<&str> = text
        .lines()
        .nth(2)
        .unwrap()
        .split('|')
        .map(str::trim)
        .collect();
    assert_eq!(cells[4], "at floor", "RMSE: {text}");
    assert_eq!(cells[8], "at floor", "PSNR: {text}");
    assert!(
        cells[10].starts_with('≥'),
        "efficiency is a lower bound: {text}"
    );
    row.mse = 5e-6;
    row.at_floor = floor.holds(row.mse);
    assert!(!row.at_floor, "5e-6 is not within 4 × 1e-6");
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
            (r.bias2 + r.variance - r.mse).abs() <= 1e-9 * r.mse,
            "{name}"
        );
        assert_eq!(r.renders, 4, "{name}: four seeds");
        match r.setting.sampling {
            Sampling::Centre => assert_eq!(r.variance, 0.0, "{name}: no seed, no variance"),
            Sampling::Jittered(_) => assert!(r.variance > 0.0, "{name}: seeds differ"),
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
            pair[1].mse < pair[0].mse,
            "{} then {}",
            pair[0].setting.name(),
            pair[1].setting.name()
        );
    }
    assert!(
        curve[0].variance > 10.0 * curve[0].bias2.max(0.0),
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
            b.mse <= a.mse + tolerance,
            "{} has MSE {} but {} has {}",
            b.setting.name(),
            b.mse,
            a.setting.name(),
            a.mse
        );
    }
    // One jittered ray's noise is the same at every depth; what depth 0
    // leaves out shows in the bias².
    let (shallow, deep) = (&study.grid[0], &study.grid[4]);
    assert!(
        shallow.bias2 > 10.0 * deep.bias2.max(tolerance),
        "the corridor needs its bounces: bias² {} at depth 0, {} at depth 8",
        shallow.bias2,
        deep.bias2
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
        "bias2",
        "variance",
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

/// A row of a fixture table: its setting, seconds and MSE (no spread).
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
        mse,
        rmse: mse.sqrt(),
        rmse_sd: 0.0,
        bias2: 0.0,
        variance: mse,
        relative_mse: mse,
        psnr: measure::accuracy::Psnr::of(mse * 65025.0, 100),
        pixels_off: 0.0,
        flip: None,
        at_floor: false,
    }
}

/// The depths of `rows`, in order: each fixture row has its own depth.
fn depths(rows: &[&Summary]) -> Vec<u32> {
    rows.iter()
        .map(|r| r.setting.termination.max_depth)
        .collect()
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
        depths(&pareto(&rows, floor, Cost::Time)),
        [1, 2, 3],
        "4 is slower and worse than 2"
    );
    assert_eq!(
        best_within(&rows, floor, 0.1)
            .unwrap()
            .setting
            .termination
            .max_depth,
        2
    );
    assert_eq!(depths(&by_efficiency(&rows, floor))[0], 1);
    // One number changed: row 4's MSE. It now beats row 3 and leads.
    rows[3].mse = 5e-4;
    assert_eq!(depths(&pareto(&rows, floor, Cost::Time)), [1, 2, 4]);
    assert_eq!(
        best_within(&rows, floor, 0.1)
            .unwrap()
            .setting
            .termination
            .max_depth,
        4
    );
    assert_eq!(depths(&by_efficiency(&rows, floor))[0], 4);
    // By rays (here a million per second), the same front.
    assert_eq!(depths(&pareto(&rows, floor, Cost::Rays)), [1, 2, 4]);
}

#[test]
fn errors_closer_than_the_floor_rank_as_equal_and_the_cheaper_wins() {
    let floor = Floor { mse: 1e-4 };
    let rows = vec![fixture(1, 4, 0.10, 2.0e-3), fixture(2, 4, 0.12, 1.9e-3)];
    // 1.9e-3 is within 4 × 1e-4 of 2.0e-3: no better, and dearer.
    assert_eq!(depths(&pareto(&rows, floor, Cost::Time)), [1]);
    assert_eq!(
        best_within(&rows, floor, 1.0)
            .unwrap()
            .setting
            .termination
            .max_depth,
        1
    );
    let sharp = Floor { mse: 1e-6 };
    assert_eq!(depths(&pareto(&rows, sharp, Cost::Time)), [1, 2]);
    assert_eq!(
        best_within(&rows, sharp, 1.0)
            .unwrap()
            .setting
            .termination
            .max_depth,
        2
    );
}
