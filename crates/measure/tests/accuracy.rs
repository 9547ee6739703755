//! `raybook accuracy`: the errors behave, the table and the CSV are
//! complete. Times are measured and reported, never asserted.

use measure::accuracy::{Knob, Measurement, all_settings, csv, pareto, settings, sweep, table};
use raybook::scene_files;
use raybook::toolkit::Scene;

fn scene(path: &str) -> Scene {
    let root = raybook::workbench::snapshot::workspace_root();
    scene_files::load(root.join("chapters").join(path))
        .unwrap()
        .with_size(48, 36)
}

/// Every setting of the quick sweeps, measured once on a small showcase.
fn quick_showcase(width: u32, height: u32) -> Vec<Measurement> {
    let showcase = raybook::CHAPTER
        .default_scene()
        .unwrap()
        .with_size(width, height);
    sweep(&showcase, &all_settings(true), 1, || {})
}

#[test]
fn error_falls_with_depth_in_the_mirror_corridor() {
    let corridor = scene("05-reflection/scenes/corridor.toml");
    let measured = sweep(&corridor, &settings(Knob::Depth, false), 1, || {});
    assert_eq!(measured.len(), 13, "depths 0 to 12");
    for pair in measured.windows(2) {
        assert!(
            pair[1].rmse <= pair[0].rmse,
            "depth {} has RMSE {} but depth {} has {}",
            pair[1].setting.value,
            pair[1].rmse,
            pair[0].setting.value,
            pair[0].rmse
        );
    }
    assert!(
        measured[0].rmse > 10.0 * measured[6].rmse,
        "the corridor needs its bounces"
    );
}

#[test]
fn the_least_accurate_setting_of_each_knob_is_not_exact() {
    let measured = quick_showcase(48, 36);
    for knob in Knob::ALL {
        let first = measured.iter().find(|m| m.setting.knob == knob).unwrap();
        assert!(first.rmse > 0.0, "{knob:?}");
    }
}

#[test]
fn the_csv_has_one_record_per_setting_and_no_nan() {
    let measured = quick_showcase(32, 24);
    let text = csv(&measured);
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header = reader.headers().unwrap().clone();
    assert_eq!(
        header.iter().collect::<Vec<_>>(),
        [
            "knob",
            "value",
            "seconds",
            "rays",
            "rmse",
            "psnr_db",
            "max_error",
            "share_off_1_255"
        ]
    );
    let records: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    assert_eq!(records.len(), all_settings(true).len(), "one per setting");
    for (record, m) in records.iter().zip(&measured) {
        assert_eq!(record.len(), header.len(), "{record:?}");
        assert_eq!(&record[0], m.setting.knob.name());
        assert_eq!(&record[1], m.setting.value);
        for number in record.iter().skip(2) {
            let value: f64 = number
                .parse()
                .unwrap_or_else(|_| panic!("{number} in {record:?}"));
            assert!(!value.is_nan(), "{record:?}");
        }
    }
    // The references match exactly: an infinite PSNR, written so.
    assert!(records.iter().any(|r| &r[5] == "inf"));
}

#[test]
fn the_table_has_a_line_per_setting_with_its_numbers_right_aligned() {
    let measured = quick_showcase(32, 24);
    let text = table(&measured);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2 + measured.len(), "header, rule, settings");
    let rule: Vec<&str> = lines[1].trim_matches('|').split('|').collect();
    assert_eq!(rule.len(), 8, "{}", lines[1]);
    assert!(rule[..2].iter().all(|c| !c.ends_with(':')), "names left");
    assert!(rule[2..].iter().all(|c| c.ends_with(':')), "numbers right");
    for (line, m) in lines[2..].iter().zip(&measured) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        assert_eq!(cells[..2], [m.setting.knob.name(), &m.setting.value]);
        assert_eq!(cells[3], m.rays.to_string());
    }
}

#[test]
fn nothing_on_the_pareto_front_is_beaten_on_both_counts() {
    let measured = quick_showcase(32, 24);
    let front = pareto(&measured);
    assert!(!front.is_empty());
    for pair in front.windows(2) {
        assert!(pair[0].seconds <= pair[1].seconds, "fastest first");
    }
    for m in &front {
        let beaten = measured
            .iter()
            .any(|o| o.seconds < m.seconds && o.rmse < m.rmse);
        assert!(!beaten, "{:?} {}", m.setting.knob, m.setting.value);
    }
}
