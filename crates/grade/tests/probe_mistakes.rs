//! The probe judges as the tests do: every classic mistake of the
//! chapters' `mistakes.toml` loses its exercise's points, and every
//! lecture's own method (`[[lecture]]`) keeps them. A probe that misses a
//! mistake gives points for wrong code, whatever the tests say.
//!
//! Each mistake is written into a copy of the workspace (the workbook's
//! `handout --check-mistakes` machinery), the probe of its chapter built
//! there, and run on two seeds: the mistake is caught if its exercise's
//! values disagree with the reference's, or, failing that, if one of its
//! chapter's seeded scenes differs (`judging/rule.rs` then takes the points of the
//! chapter's exercises that draw it). It builds once per mistake, two to
//! four minutes for all of them on two cores, so it runs when asked, as CI
//! does:
//!
//! ```text
//! RAYBOOK_PROBE_MISTAKES=1 cargo test -p grade --test probe_mistakes -- --nocapture
//! RAYBOOK_PROBE_MISTAKES=ch05 ...   only the exercises whose id starts so
//! ```

use std::path::{Path, PathBuf};
use std::process::Command;

use grade_probe::{Picture, Probed, first_disagreement};
use workbench::chapters::{self, ChapterEntry};
use workbook::handout::check::{Check, mistakes_files};
use workbook::regions::Region;
use workbook::workspace::PROBE;

const SEEDS: [u64; 2] = [1, 20261205];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The probe's feature for a chapter, as the grader builds it.
fn feature(chapter: &ChapterEntry) -> String {
    format!("ch{:02}", chapter.number())
}

/// Writes `body`'s variant into the check's work folder, with the
/// teacher's probe and the full lock file beside it (a handout, which the
/// variant is, has neither), each file written only if it changed.
fn write_variant(check: &Check, root: &Path, body: impl Fn(&Region) -> Option<String>) {
    check.write_variant(body).unwrap();
    let work = root.join("target/probe-mistakes/work");
    let files = workbook::workspace::workspace_files(root).unwrap();
    let probe = files.iter().filter(|f| f.starts_with(PROBE));
    for file in probe.chain([&PathBuf::from("Cargo.lock")]) {
        let bytes = std::fs::read(root.join(file)).unwrap();
        let to = work.join(file);
        if std::fs::read(&to).ok().as_ref() != Some(&bytes) {
            std::fs::create_dir_all(to.parent().unwrap()).unwrap();
            std::fs::write(&to, &bytes).unwrap();
        }
    }
}

/// Builds the probe of the current variant with `feature`; the first error
/// line if it does not build.
fn build(check: &Check, feature: &str) -> Result<(), String> {
    let args = [
        "build",
        "--offline",
        "-p",
        "grade-probe",
        "--no-default-features",
        "--features",
        feature,
    ];
    let (ok, text) = check.cargo(&args)?;
    match ok {
        true => Ok(()),
        false => Err((text.lines())
            .find(|l| l.starts_with("error"))
            .unwrap_or("the build failed")
            .to_owned()),
    }
}

/// Runs the built probe with `args` and `seed`; what it wrote.
fn run(binary: &Path, args: [&str; 2], seed: u64) -> Result<Probed, String> {
    let out = tempfile::NamedTempFile::new().map_err(|e| e.to_string())?;
    let ran = Command::new(binary)
        .args(args)
        .args(["--seed", &seed.to_string(), "--out"])
        .arg(out.path())
        .output()
        .map_err(|e| e.to_string())?;
    if !ran.status.success() {
        let text = String::from_utf8_lossy(&ran.stderr);
        let line = text
            .lines()
            .find(|l| l.contains("panicked") || l.contains("grade-probe"));
        return Err(format!("crashed: {}", line.unwrap_or("")));
    }
    let bytes = std::fs::read(out.path()).map_err(|e| e.to_string())?;
    serde_json::from_slice(&bytes).map_err(|e| e.to_string())
}

/// What one seed's probe gave: each probed exercise's values and each
/// chapter's scenes.
#[derive(Default)]
struct Outputs {
    values: Vec<(String, grade_probe::Values)>,
    scenes: Vec<(String, Vec<Picture>)>,
}

/// The probe's outputs for `ids` and `folders` under `seed`.
fn outputs(binary: &Path, ids: &[&str], folders: &[&str], seed: u64) -> Outputs {
    let mut found = Outputs::default();
    for id in ids {
        if let Ok(mut p) = run(binary, ["--exercise", id], seed)
            && let Some(values) = p.exercises.pop()
        {
            found.values.push((id.to_string(), values));
        }
    }
    for folder in folders {
        if let Ok(p) = run(binary, ["--scenes", folder], seed) {
            found.scenes.push((folder.to_string(), p.scenes));
        }
    }
    found
}

/// Do two sets of seeded scenes agree, by the grader's own rule?
fn same_pictures(ours: &[Picture], theirs: &[Picture]) -> bool {
    ours.len() == theirs.len()
        && (ours.iter().zip(theirs)).all(|(a, b)| grade::picture_problem(a, Some(b)).is_none())
}

/// How the probe judged a variant of exercise `id` against `reference`:
/// "agrees", "scenes", or "values" and the first input that disagrees.
fn judged(reference: &[Outputs], found: &[Outputs], id: &str, folder: &str) -> String {
    let values = |o: &Outputs| {
        let found = o.values.iter().find(|(i, _)| i == id);
        found.map(|(_, v)| v.clone())
    };
    let scenes = |o: &Outputs| {
        let found = o.scenes.iter().find(|(f, _)| f == folder);
        found.map(|(_, s)| s.clone())
    };
    let mut verdict = "agrees";
    for (ours, theirs) in reference.iter().zip(found) {
        let (Some(a), Some(b)) = (values(ours), values(theirs)) else {
            return "values (none written)".to_owned();
        };
        if let Some(i) = first_disagreement(&a, &b) {
            let theirs = b.cases.get(i).map(|c| c.value.to_string());
            return format!(
                "values ({}: {} against {})",
                a.cases[i].input,
                a.cases[i].value,
                theirs.unwrap_or_default()
            );
        }
        let pictures = scenes(ours).zip(scenes(theirs));
        if pictures.is_none_or(|(a, b)| !same_pictures(&a, &b)) {
            verdict = "scenes";
        }
    }
    verdict.to_owned()
}

#[test]
fn every_classic_mistake_loses_its_points_and_every_lecture_method_keeps_them() {
    let Ok(only) = std::env::var("RAYBOOK_PROBE_MISTAKES") else {
        eprintln!("skipped: RAYBOOK_PROBE_MISTAKES=1 (or an id prefix) runs it (minutes)");
        return;
    };
    let only = if only == "1" { String::new() } else { only };
    let root = root();
    // A folder of its own: `handout --check-mistakes` writes its variants
    // into target/handout-check, and the two may run at once.
    let folder = root.join("target/probe-mistakes");
    let check = Check::in_folder(&root, &folder).expect("the check's work folder");
    let binary = folder.join("target/debug/grade-probe");
    let last = chapters::all().iter().rfind(|c| c.exercises).unwrap();
    write_variant(&check, &root, |_| None);
    build(&check, &feature(last)).expect("the reference's probe builds");
    let list = Command::new(&binary).arg("--list").output().unwrap();
    let list: serde_json::Value = serde_json::from_slice(&list.stdout).unwrap();
    let probed = |id: &str| {
        let exercises = list["exercises"].as_object().unwrap().values();
        exercises
            .flat_map(|l| l.as_array().unwrap())
            .any(|x| x == id)
    };
    let files = mistakes_files(&root).unwrap();
    let ids: Vec<String> = (files.iter())
        .flat_map(|(_, f)| f.mistake.iter().map(|m| m.exercise.clone()))
        .filter(|id| id.starts_with(&only) && probed(id))
        .collect();
    let ids: Vec<&str> = ids.iter().map(String::as_str).collect();
    let folders: Vec<&str> = (files.iter()).map(|(c, _)| c.folder.as_str()).collect();
    let reference: Vec<Outputs> = (SEEDS.iter())
        .map(|&s| outputs(&binary, &ids, &folders, s))
        .collect();

    let mut wrong = Vec::new();
    let mut count = 0;
    for (chapter, file) in &files {
        let variants = (file.mistake.iter())
            .map(|m| (&m.exercise, &m.body, true, m.what.as_str()))
            .chain(
                file.lecture
                    .iter()
                    .map(|l| (&l.exercise, &l.body, false, "the lecture's method")),
            );
        for (id, body, is_mistake, what) in variants {
            if !id.starts_with(&only) || !probed(id) {
                continue;
            }
            count += 1;
            write_variant(&check, &root, |r| (r.id == *id).then(|| body.clone()));
            let verdict = match build(&check, &feature(chapter)) {
                Err(e) => format!("does not compile ({e})"),
                Ok(()) => {
                    let found: Vec<Outputs> = (SEEDS.iter())
                        .map(|&s| outputs(&binary, &[id.as_str()], &[chapter.folder.as_str()], s))
                        .collect();
                    judged(&reference, &found, id, &chapter.folder)
                }
            };
            let right = match is_mistake {
                true => verdict != "agrees",
                false => verdict == "agrees",
            };
            let mark = if right { "" } else { "   <-- WRONG" };
            // A caught mistake's disagreement is long and expected: its kind only.
            let shown = match right && is_mistake {
                true => verdict.split(" (").next().unwrap_or_default(),
                false => &verdict,
            };
            println!("{id:<22} {what:<60} {shown}{mark}");
            if !right {
                wrong.push(format!("{id}: {what}: {verdict}"));
            }
        }
    }
    println!(
        "{} of {count} judged as they should be",
        count - wrong.len()
    );
    assert!(count > 0, "no mistake of {only:?} is probed");
    assert!(wrong.is_empty(), "judged wrongly: {wrong:#?}");
}
