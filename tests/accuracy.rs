//! `raybook accuracy`: the errors behave, the CSV is complete. Times are
//! measured and reported, never asserted.

use raybook::accuracy::{Knob, all_settings, csv, settings, sweep};
use raybook::toolkit::Scene;

fn scene(path: &str) -> Scene {
    let root = env!("CARGO_MANIFEST_DIR");
    Scene::load(format!("{root}/chapters/{path}"))
        .unwrap()
        .with_size(48, 36)
}

#[test]
fn error_falls_with_depth_in_the_mirror_corridor() {
    let corridor = scene("05-reflection/scenes/corridor.toml");
    let rows = sweep(&corridor, &settings(Knob::Depth, false), 1, || {});
    assert_eq!(rows.len(), 13, "depths 0 to 12");
    for pair in rows.windows(2) {
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
        rows[0].rmse > 10.0 * rows[6].rmse,
        "the corridor needs its bounces"
    );
}

#[test]
fn the_reference_setting_has_zero_error() {
    let showcase = raybook::CHAPTER.default_scene().unwrap().with_size(48, 36);
    let rows = sweep(&showcase, &all_settings(true), 1, || {});
    for knob in [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects] {
        let last = rows.iter().rfind(|r| r.setting.knob == knob).unwrap();
        assert_eq!(last.rmse, 0.0, "{knob:?}");
        assert_eq!(last.max_error, 0.0);
        assert!(last.psnr.is_infinite());
    }
    // And the least accurate setting of each knob is not exact.
    for knob in [Knob::Depth, Knob::Threshold, Knob::Samples, Knob::Effects] {
        let first = rows.iter().find(|r| r.setting.knob == knob).unwrap();
        assert!(first.rmse > 0.0, "{knob:?}");
    }
}

#[test]
fn the_csv_has_one_row_per_setting_and_no_nan() {
    let showcase = raybook::CHAPTER.default_scene().unwrap().with_size(32, 24);
    let all = all_settings(true);
    let rows = sweep(&showcase, &all, 1, || {});
    let text = csv(&rows);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines.len(),
        1 + all.len(),
        "a header and one line per setting"
    );
    let columns = lines[0].split(',').count();
    for line in &lines[1..] {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), columns, "{line}");
        for number in &fields[2..] {
            let value: f64 = number
                .parse()
                .unwrap_or_else(|_| panic!("{number} in {line}"));
            assert!(!value.is_nan(), "{line}");
        }
    }
}
