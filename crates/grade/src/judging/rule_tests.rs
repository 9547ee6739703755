//! The rule on verdicts: pictures that differ, and the contradictions the
//! teacher is told of.
use super::*;

fn verdict(id: &str, passed: bool) -> Verdict {
    Verdict {
        id: id.to_owned(),
        passed,
        judged_by: JUDGED_BY_VALUES.to_owned(),
        ..Verdict::default()
    }
}

fn picture(uses: &[&str], shade: u8) -> Picture {
    Picture {
        name: "03-lambert seeded scene 1".to_owned(),
        uses: uses.iter().map(|s| s.to_string()).collect(),
        width: 8,
        height: 8,
        rgb: vec![shade; 8 * 8 * 3],
    }
}

#[test]
fn a_differing_scene_costs_its_exercises_unless_one_drawing_it_lost_already() {
    let uses = ["ch02-closest", "ch03-lambert", "ch03-spot"];
    let ours = [picture(&uses, 100)];
    let differs = || Ok(vec![picture(&uses, 200)]);
    let same = || Ok(vec![picture(&uses, 101)]);

    let mut verdicts = [verdict("ch03-lambert", true), verdict("ch03-spot", true)];
    pictures(
        &ours,
        same(),
        &mut verdicts,
        &[verdict("ch02-closest", true)],
    );
    assert!(verdicts.iter().all(|v| v.passed), "within the tolerance");

    pictures(
        &ours,
        differs(),
        &mut verdicts,
        &[verdict("ch02-closest", true)],
    );
    assert!(
        verdicts.iter().all(|v| !v.passed),
        "values agree, picture not"
    );
    assert!(verdicts[0].message.as_ref().unwrap().contains("differs"));

    let mut verdicts = [verdict("ch03-lambert", true), verdict("ch03-spot", false)];
    pictures(
        &ours,
        differs(),
        &mut verdicts,
        &[verdict("ch02-closest", true)],
    );
    assert!(verdicts[0].passed, "explained by ch03-spot's values");

    let mut verdicts = [verdict("ch03-lambert", true), verdict("ch03-spot", true)];
    pictures(
        &ours,
        differs(),
        &mut verdicts,
        &[verdict("ch02-closest", false)],
    );
    assert!(verdicts[0].passed, "explained by an earlier chapter's");

    let mut verdicts = [verdict("ch03-lambert", true)];
    pictures(&ours, Err("timed out".into()), &mut verdicts, &[]);
    assert!(!verdicts[0].passed, "a scene not drawn differs");
}

/// Values that agree while the exercise's own tests reach its `todo!`
/// (code that knows when it is graded), a forged record, and tests that
/// never finish are flagged; an honest `todo!` (its values disagree
/// too) and honest failures are not.
#[test]
fn contradictions_are_flagged_for_the_teacher_and_honest_work_is_not() {
    let todo = |id: &str| Some(format!("test t: not yet implemented: {id}: hint"));
    let mut knows = verdict("ch01-at", true);
    knows.feedback = todo("ch01-at");
    let mut honest_todo = verdict("ch01-frame", false);
    honest_todo.feedback = todo("ch01-frame");
    let mut forged = verdict("ch01-ray-through", false);
    forged.forged = true;
    let mut failing = verdict("ch02-plane", true);
    failing.feedback = Some("test u: expected 1, found 2".to_owned());
    let endless = ChapterRun {
        folder: "03-lambert".to_owned(),
        compiled: true,
        trouble: Some("the tests timed out after 60 s (an endless loop?): killed".to_owned()),
        ..ChapterRun::default()
    };
    let finished = ChapterRun {
        folder: "01-rays".to_owned(),
        compiled: true,
        ..ChapterRun::default()
    };
    let flags = contradictions(&[knows, honest_todo, forged, failing], &[endless, finished]);
    assert_eq!(flags.len(), 3, "{flags:?}");
    assert!(
        flags[0].starts_with("ch01-at: its values agree"),
        "{flags:?}"
    );
    assert!(
        flags[1].starts_with("ch01-ray-through: its probe's record"),
        "{flags:?}"
    );
    assert_eq!(flags[2], "03-lambert: its tests never finished");
}
