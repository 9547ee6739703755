use super::*;
use crate::progress::parse;
use crate::progress::parse::tests::FAILING;

fn row(folder: &str, output: Option<&str>, exercises: &str) -> ChapterResult {
    let source = format!("fn f() {{\n{exercises}}}\n");
    let regions = crate::regions::regions(&source).unwrap();
    ChapterResult {
        chapter: crate::workbench::chapters::find(folder).unwrap(),
        output: output.map(parse),
        exercises: regions
            .into_iter()
            .map(|r| {
                (
                    PathBuf::from(format!("chapters/{folder}/src/lib.rs")),
                    r.start + 1,
                    r,
                )
            })
            .collect(),
        reused: false,
    }
}

#[test]
fn the_report_marks_the_first_failing_chapter_and_names_the_next_exercise() {
    let ok = "test result: ok. 5 passed; 0 failed; 0 ignored\n";
    let open = "    // EXERCISE(ch03-lambert): the cosine law: what a matte surface of this albedo sends back of the incoming light\n    todo!(\"...\")\n    // END EXERCISE\n";
    let rows = [
        row("02-hits", Some(ok), ""),
        row("03-lambert", Some(FAILING), open),
        row("04-shadows", None, ""),
    ];
    let text = report(&rows, Path::new("/w"));
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].contains("chapter") && lines[0].contains("first failure"));
    assert!(lines[1].starts_with("   02-hits") && lines[1].trim_end().ends_with('-'));
    assert!(lines[2].starts_with("→  03-lambert"), "{text}");
    assert!(lines[2].contains(" 0/1 "), "{text}");
    // The column leads with the failure the advice explains: a test
    // whose own message says what is wrong comes before a picture.
    assert!(
        lines[2].ends_with("  test cosine_law_head_on_versus_sixty_degrees"),
        "{text}"
    );
    assert!(lines[3].contains("not run"));
    assert!(
        text.contains("next: chapter 3: exercise ch03-lambert in chapters/03-lambert/src/lib.rs:2"),
        "{text}"
    );
    assert!(text.contains("`cargo test -p ch03-lambert`"));
}

#[test]
fn a_precise_message_leads_before_a_snapshot_and_a_whole_picture() {
    // libtest names a test by its module: `pictures::…` sorts before
    // `triangles::…`, but a count of pixels, or a whole picture's
    // test, explains less than the test of one function.
    let written = "    // EXERCISE(ch02-triangle): x\n    None\n    // END EXERCISE\n";
    let mut chapter = row("02-hits", None, written);
    chapter.output = Some(TestOutput {
        failed: 3,
        failed_tests: vec![
            "pictures::snapshot_flat".into(),
            "pictures::the_flat_view_shows_each_object".into(),
            "triangles::barycentric_weights".into(),
        ],
        snapshots: vec![("02-hits/flat".into(), None)],
        panics: vec![
            (
                "pictures::snapshot_flat".into(),
                "snapshot 02-hits/flat differs: 812 pixels".into(),
            ),
            (
                "pictures::the_flat_view_shows_each_object".into(),
                "the triangle's pixels differ".into(),
            ),
            (
                "triangles::barycentric_weights".into(),
                "β is not divided by |N|".into(),
            ),
        ],
        ..TestOutput::default()
    });
    let text = report(&[chapter], Path::new("/w"));
    let row = text.lines().nth(1).unwrap();
    assert!(
        row.ends_with("  test triangles::barycentric_weights"),
        "{text}"
    );
    assert!(text.contains("β is not divided by |N|"), "{text}");
    assert!(!text.contains("812 pixels"), "{text}");
}

#[test]
fn a_written_exercise_that_fails_beside_an_open_one_has_its_answer_offered() {
    let exercises = "    // EXERCISE(ch01-at): a\n    self.origin\n    // END EXERCISE\n}\nfn g() {\n\
                     // EXERCISE(ch01-frame): f\n    todo!()\n    // END EXERCISE\n";
    let mut chapter = row("01-rays", None, exercises);
    chapter.output = Some(TestOutput {
        failed: 2,
        failed_tests: vec!["a_ray_walks".into(), "the_frame".into()],
        panics: vec![
            ("a_ray_walks".into(), "r(2.5) is not 2.5 along".into()),
            (
                "the_frame".into(),
                "not yet implemented: ch01-frame: f".into(),
            ),
        ],
        ..TestOutput::default()
    });
    let text = report(&[chapter.clone()], Path::new("/w"));
    assert!(text.contains("exercise ch01-frame"), "{text}");
    assert!(
        text.contains("`workbook hint ch01-at --level 4` shows the answer"),
        "{text}"
    );
    // Only todo!s fail: nothing written fails, no answer is offered.
    let output = chapter.output.as_mut().unwrap();
    output.panics.remove(0);
    let text = report(&[chapter], Path::new("/w"));
    assert!(!text.contains("--level 4"), "{text}");
}

#[test]
fn a_result_of_the_last_run_says_so() {
    let ok = "test result: ok. 5 passed; 0 failed; 0 ignored\n";
    let mut rows = [
        row("01-rays", Some(ok), ""),
        row("02-hits", Some(FAILING), ""),
    ];
    for row in &mut rows {
        row.reused = true;
    }
    let text = report(&rows, Path::new("/w"));
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[1].ends_with("  unchanged since the last run"),
        "{text}"
    );
    assert!(
        lines[2].ends_with(" (unchanged since the last run)"),
        "{text}"
    );
}

#[test]
fn when_everything_passes_the_report_says_so() {
    let ok = "test result: ok. 5 passed; 0 failed; 0 ignored\n";
    let done = "    // EXERCISE(ch03-lambert): x\n    1.0\n    // END EXERCISE\n";
    let rows = [row("03-lambert", Some(ok), done)];
    let text = report(&rows, Path::new("/w"));
    assert!(text.contains("1/1"), "{text}");
    assert!(!text.contains('→'));
    assert!(text.contains("next: every chapter passes"));
}

#[test]
fn a_written_exercise_that_fails_is_explained_by_its_tests_message() {
    let failing = "thread 'the_lectures_worked_example' (7) panicked at tests/chapter02/spheres.rs:14:5:\n\
                   assertion `left == right` failed: the roots are 1 and 3\n  \
                   left: None\n right: Some((1.0, 3.0))\n\
                   test result: FAILED. 3 passed; 1 failed; 0 ignored\n";
    let written = "    // EXERCISE(ch02-sphere): x\n    None\n    // END EXERCISE\n";
    let rows = [row("02-hits", Some(failing), written)];
    let text = report(&rows, Path::new("/w"));
    assert!(
        text.contains(
            "next: chapter 2: the test the_lectures_worked_example fails:\n      \
             assertion `left == right` failed: the roots are 1 and 3; left: None; \
             right: Some((1.0, 3.0))\n      run `cargo test -p ch02-hits`"
        ),
        "{text}"
    );
    // The answer is there, now that the exercise was tried.
    assert!(
        text.contains("you have tried it: `workbook hint ch02-sphere --level 4` shows the answer"),
        "{text}"
    );
    // The row names the same failure as the advice.
    let row = text.lines().nth(1).unwrap();
    assert!(
        row.ends_with("  test the_lectures_worked_example"),
        "{text}"
    );
}

#[test]
fn the_row_and_the_advice_speak_of_the_same_exercise_in_the_texts_order() {
    // The light loop's test comes first in the chapter's order, but it
    // ran into the Lambert exercise's todo!; the text asks for the spot
    // first, and a later test ran into the spot's.
    let root = tempfile::tempdir().unwrap();
    let readme = root.path().join("chapters/03-lambert/README.md");
    std::fs::create_dir_all(readme.parent().unwrap()).unwrap();
    std::fs::write(
        &readme,
        "<!-- derives: ch03-spot -->\n<!-- derives: ch03-lambert -->\n",
    )
    .unwrap();
    let open = "    // EXERCISE(ch03-lambert): l\n    todo!()\n    // END EXERCISE\n}\nfn g() {\n\
                // EXERCISE(ch03-spot): s\n    todo!()\n    // END EXERCISE\n";
    let mut chapter = row("03-lambert", None, open);
    chapter.output = Some(TestOutput {
        failed: 2,
        failed_tests: vec!["the_light_loop_adds".into(), "the_cone_edges".into()],
        panics: vec![
            (
                "the_light_loop_adds".into(),
                "not yet implemented: ch03-lambert: l".into(),
            ),
            (
                "the_cone_edges".into(),
                "not yet implemented: ch03-spot: s".into(),
            ),
        ],
        ..TestOutput::default()
    });
    let text = report(&[chapter], root.path());
    let row = text.lines().nth(1).unwrap();
    assert!(row.ends_with("  test the_cone_edges"), "{text}");
    assert!(
        text.contains("next: chapter 3: exercise ch03-spot in"),
        "{text}"
    );
}
