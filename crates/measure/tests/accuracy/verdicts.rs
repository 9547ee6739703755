//! What the standard errors allow the report to say: "at floor" only where
//! an estimate's SE allows it, and each jittered row judged where its SE is
//! smallest, at its termination's most rays per pixel.

use measure::accuracy::{
    Estimate, Floor, Sampling, Summary, Verdict, bias_cell, judge_at_most_rays,
};

use super::{fixture, small_study};

#[test]
fn a_row_within_the_floor_reads_at_floor_and_shows_no_error_number() {
    let floor = Floor { mse: 1e-6 };
    let mut row = fixture(16, 16, 0.5, 3e-6);
    row.at_floor = floor.judge(row.mse) == Verdict::AtFloor;
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
    row.mse.value = 5e-6;
    assert_ne!(floor.judge(row.mse), Verdict::AtFloor, "5e-6 > 4 × 1e-6");
}

/// The bias² of the same value reads "at floor" with a small standard
/// error, "can't tell" with a large one, and "above" only when even 2 SE
/// below it is above the limit.
#[test]
fn at_floor_is_not_claimed_when_the_standard_error_forbids_it() {
    let floor = Floor { mse: 1e-6 };
    let mut row = fixture(16, 16, 0.5, 1e-3);
    let verdict = |row: &Summary| floor.judge(row.bias2);
    row.bias2 = Estimate {
        value: 1e-6,
        se: 1e-6,
    };
    assert_eq!(verdict(&row), Verdict::AtFloor, "1e-6 + 2e-6 ≤ 4e-6");
    assert!(bias_cell(&row, floor).starts_with("at floor"));
    // The same value, but 2 SE reach past the limit: the seeds cannot tell.
    row.bias2.se = 2e-6;
    assert_eq!(verdict(&row), Verdict::Unresolved);
    let cell = bias_cell(&row, floor);
    assert!(
        cell.contains("can't tell") && !cell.contains("at floor"),
        "{cell}"
    );
    // A negative estimate, as noise can give, is no better evidence: its
    // upper bound 0 is below the limit, but 2 SE are 70 times the room.
    row.bias2 = Estimate {
        value: -2e-4,
        se: 1e-4,
    };
    assert_eq!(
        verdict(&row),
        Verdict::Unresolved,
        "{}",
        bias_cell(&row, floor)
    );
    // With 4 seeds, 2 SE = 2e-4 against room 3e-6: (2e-4/3e-6)² × 12 ≈
    // 53000 = K(K−1), so K ≈ 231.
    let seeds = floor.seeds_to_tell(row.bias2, 4);
    assert!((229..=233).contains(&seeds), "{seeds}");
    row.bias2 = Estimate {
        value: 1e-5,
        se: 1e-6,
    };
    assert_eq!(verdict(&row), Verdict::Above, "1e-5 − 2e-6 > 4e-6");
    // Just above the floor, 2 SE just past the limit (the full study's
    // depth 16 at 4 seeds): the room left is the limit less the estimate,
    // 2.5e-6, which 2 SE fit at K(K−1) ≥ 12 × (3/2.5)² = 17.3, K = 5.
    row.bias2 = Estimate {
        value: 1.5e-6,
        se: 1.5e-6,
    };
    assert_eq!(verdict(&row), Verdict::Unresolved);
    assert_eq!(floor.seeds_to_tell(row.bias2, 4), 5);
    // Above the limit by 1e-6 with 2 SE = 3e-6: telling "above" needs
    // K(K−1) ≥ 12 × 3² = 108, K = 11.
    row.bias2.value = 5e-6;
    assert_eq!(verdict(&row), Verdict::Unresolved);
    assert_eq!(floor.seeds_to_tell(row.bias2, 4), 11);
    // Exactly at the limit: no number of seeds tells which side.
    row.bias2.value = 4e-6;
    assert_eq!(floor.seeds_to_tell(row.bias2, 4), usize::MAX);
    assert!(!bias_cell(&row, floor).contains("seeds would"));
}

/// A termination's bias does not depend on the jittered rays per pixel,
/// so a row of few rays, whose bias² is mostly noise, takes the verdict of
/// its termination's row with the most rays, and says so; centre rows and
/// the most-rays rows are judged on their own.
#[test]
fn jittered_rows_are_judged_at_the_most_rays() {
    let floor = Floor { mse: 1e-6 };
    let mut rows = vec![fixture(6, 1, 0.1, 1e-2), fixture(6, 16, 1.6, 1e-3)];
    let mut centre = fixture(6, 1, 0.1, 1e-2);
    centre.setting.sampling = Sampling::Centre;
    rows.push(centre);
    rows.push(fixture(1, 4, 0.4, 1e-2));
    rows[0].bias2 = Estimate {
        value: -1.5e-4,
        se: 1e-4,
    };
    rows[1].bias2 = Estimate {
        value: 1.5e-6,
        se: 1e-6,
    };
    rows[2].bias2 = Estimate::exact(8e-3);
    rows[3].bias2 = Estimate {
        value: 1e-2,
        se: 1e-4,
    };
    judge_at_most_rays(&mut rows);
    let judged = rows[0].judged_on.expect("1 jittered is judged on 16");
    assert_eq!(judged.samples, 16);
    assert_eq!(rows[0].verdict(floor), Verdict::AtFloor);
    assert_eq!(
        floor.judge(rows[0].bias2),
        Verdict::Unresolved,
        "alone, it can't tell"
    );
    assert!(
        rows[0].agrees_with_judged(),
        "-1.5e-4 is within 2 SE of 1.5e-6"
    );
    let cell = bias_cell(&rows[0], floor);
    assert!(cell.contains("at floor at 16 jittered"), "{cell}");
    assert!(!cell.contains("misses"), "{cell}");
    for (i, why) in [
        (1, "the most rays"),
        (2, "a centre ray"),
        (3, "the only jittered row of depth 1"),
    ] {
        assert_eq!(rows[i].judged_on, None, "{why} is judged on its own");
        assert!(rows[i].agrees_with_judged());
    }
    // An own estimate far from the judged one is flagged: the assumption
    // that bias does not move with N would have failed.
    rows[0].bias2 = Estimate {
        value: 1e-3,
        se: 1e-5,
    };
    assert!(!rows[0].agrees_with_judged());
    assert!(bias_cell(&rows[0], floor).contains("misses it by over 2 SE"));
    // The small study: every jittered row but the 16-ray ones is judged on
    // the 16-ray row of its termination, and agrees with it.
    let study = small_study();
    for r in &study.grid {
        let most = r.setting.sampling == Sampling::Jittered(16);
        let expected = (r.setting.sampling.is_random() && !most).then_some(16);
        assert_eq!(
            r.judged_on.map(|j| j.samples),
            expected,
            "{}",
            r.setting.name()
        );
        assert!(
            r.agrees_with_judged(),
            "{}: {}",
            r.setting.name(),
            bias_cell(r, study.floor)
        );
    }
}
