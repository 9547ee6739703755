//! A class graded in slices and merged gets the outputs of one run over
//! the whole class (issue 35, item 7): `grade --shard K/N`, `--merge`, and
//! the Slurm example `crates/grade/teacher/slurm-grade.sh`, run with an
//! `sbatch` that stands in for Slurm's.
//!
//! The class: `Ada Lovelace` (chapter 1 written), `ada_lovelace` (nothing
//! written: the two names make the same file name, so the second is
//! `ada_lovelace-2` in the whole class, whichever slice holds it),
//! `mistaken` (chapter 1 with a classic mistake, the whole field of view
//! where half belongs),
//! `broken` (does not compile), and two folders that are not graded
//! (`empty/`, `notes.txt`). Chapter 1 only.
//!
//! The eight slices run one after another with one cache (`--cache`), so
//! the reference is built once and each student graded once. Then one run
//! over the whole class, with the same cache: it must grade no one (each
//! student's result from a slice is the one it would compute: same files,
//! reference and settings), and write what the merge wrote, byte for byte
//! (every file: gradebook, JUnit, Gradescope, HTML report, pictures). Then
//! the Slurm script submits two slices and the merge with a stand-in
//! `sbatch`, which runs each job at once as Slurm would (a copy of the
//! script, `SLURM_ARRAY_TASK_ID` from 0), and its outputs must be the same.
//!
//! It takes minutes on a busy machine (it builds chapter 1 five times), so
//! it runs only when asked, as CI does:
//!
//! ```text
//! RAYBOOK_GRADE_SHARDS=1 cargo test -p grade --test grade_shards -- --nocapture
//! ```

mod grade_support;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use grade_support::{handout, read_csv, run_grade as grade, snapshot_reference};

#[test]
fn a_class_graded_in_slices_and_merged_gets_the_outputs_of_one_run() {
    if std::env::var_os("RAYBOOK_GRADE_SHARDS").is_none() {
        eprintln!("grade_shards: set RAYBOOK_GRADE_SHARDS=1 to grade a class in slices (minutes)");
        return;
    }
    let start = Instant::now();
    let base = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("grade-shards");
    let _ = std::fs::remove_dir_all(&base);
    let reference = snapshot_reference(&base.join("reference"));
    let class = base.join("class");
    make_class(&reference, &class);
    let cache = base.join("cache");
    let options = |out: &Path| -> Vec<std::ffi::OsString> {
        let mut args = vec![
            "--out".into(),
            out.into(),
            "--cache".into(),
            cache.clone().into(),
        ];
        args.extend([
            "--chapters".into(),
            "1".into(),
            "--seed".into(),
            "2026".into(),
        ]);
        args.push("--reference".into());
        args.push(reference.clone().into());
        args
    };

    let slices: Vec<PathBuf> = (1..=8).map(|k| base.join(format!("eight/{k}"))).collect();
    for (k, out) in (1..=8).zip(&slices) {
        let shard = format!("{k}/8");
        let more = options(out);
        let mut args = vec![class.as_os_str(), "--shard".as_ref(), shard.as_ref()];
        args.extend(more.iter().map(|a| a.as_os_str()));
        let said = grade(&args);
        eprintln!("slice {shard} ({:.0?}):\n{said}", start.elapsed());
    }
    let held = held_by_slice(&slices);
    assert_eq!(held.len(), 6, "every folder in one slice: {held:?}");
    assert_ne!(
        held["Ada Lovelace"], held["ada_lovelace"],
        "the test needs the two names that make one file name in two slices"
    );
    assert!(
        (1..=8).any(|k| !held.values().any(|&v| v == k)),
        "the test needs a slice with no student: {held:?}"
    );

    let merged = base.join("merged");
    let mut args = vec!["--merge".as_ref()];
    args.extend(slices.iter().rev().map(|s| s.as_os_str()));
    args.extend(["--out".as_ref(), merged.as_os_str()]);
    args.extend(["--reference".as_ref(), reference.as_os_str()]);
    eprintln!("{}", grade(&args));

    let whole = base.join("whole");
    let more = options(&whole);
    let mut args = vec![class.as_os_str()];
    args.extend(more.iter().map(|a| a.as_os_str()));
    let said = grade(&args);
    eprintln!("the whole class ({:.0?}):\n{said}", start.elapsed());
    assert!(
        said.contains("students: 0 graded in") && said.contains("4 unchanged"),
        "every result of a slice is the whole run's: {said}"
    );
    check_rows(&whole);
    assert_same_outputs(&whole, &merged);

    let slurm = base.join("slurm");
    let said = slurm_script(&base, &class, &reference, &slurm);
    eprintln!("the Slurm script:\n{said}");
    let log = std::fs::read_to_string(base.join("sbatch.log")).unwrap();
    let calls: Vec<&str> = log.lines().collect();
    assert_eq!(calls.len(), 2, "{log}");
    assert!(calls[0].contains("--array=0-1") && calls[0].ends_with(" shard"));
    assert!(calls[1].contains("--dependency=afterok:1") && calls[1].ends_with(" merge"));
    for k in 1..=2 {
        assert!(
            slurm
                .join(format!("shard-{k}-of-2/shard-{k}-of-2.json"))
                .is_file()
        );
    }
    assert_same_outputs(&whole, &slurm.join("class"));
    eprintln!("whole test: {:.0?}", start.elapsed());
}

/// Writes the class from the reference snapshot.
fn make_class(reference: &Path, class: &Path) {
    std::fs::create_dir_all(class).unwrap();
    handout(reference, &class.join("Ada Lovelace"), 1);
    handout(reference, &class.join("ada_lovelace"), 0);
    let mistaken = class.join("mistaken");
    handout(reference, &mistaken, 1);
    let files = workbook::handout::check::mistakes_files(reference).unwrap();
    let mistakes = files.iter().flat_map(|(_, f)| &f.mistake);
    let mirrored = mistakes
        .into_iter()
        .find(|m| m.what.ends_with(": mirrored"));
    let mirrored = mirrored.expect("chapter 1's mistakes.toml: the mirrored frame");
    let lib = mistaken.join("chapters/01-rays/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    let mistake = workbook::regions::replace_bodies(&source, |r| {
        (r.id == mirrored.exercise).then(|| mirrored.body.clone())
    });
    std::fs::write(&lib, mistake.unwrap()).unwrap();
    let broken = class.join("broken");
    handout(reference, &broken, 1);
    let lib = broken.join("chapters/01-rays/src/lib.rs");
    let source = std::fs::read_to_string(&lib).unwrap();
    std::fs::write(&lib, source + "\npub fn broken() -> u32 {\n    \"no\"\n}\n").unwrap();
    std::fs::create_dir(class.join("empty")).unwrap();
    std::fs::write(class.join("notes.txt"), "grade them kindly\n").unwrap();
}

/// Which slice holds each student, from the slices' files.
fn held_by_slice(slices: &[PathBuf]) -> BTreeMap<String, usize> {
    let mut held = BTreeMap::new();
    for (k, dir) in (1..).zip(slices) {
        let file = dir.join(format!("shard-{k}-of-{}.json", slices.len()));
        let json: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&file).unwrap()).unwrap();
        for student in json["students"].as_array().unwrap() {
            let name = student["name"].as_str().unwrap().to_owned();
            assert!(held.insert(name, k).is_none(), "{file:?}: a student twice");
        }
    }
    held
}

/// The rows say what the module's comment says.
fn check_rows(out: &Path) {
    let rows = read_csv(&out.join("grades.csv"));
    let score = |name: &str| rows[name]["score"].as_str();
    assert_eq!(score("Ada Lovelace"), "3", "{rows:?}");
    assert_eq!(score("ada_lovelace"), "0");
    assert_eq!(rows["broken"]["compiled"], "no");
    assert_ne!(score("mistaken"), "3");
    assert!(rows["empty"]["status"].starts_with("not graded: "));
    assert!(rows["notes.txt"]["status"].starts_with("not graded: "));
    assert!(out.join("gradescope/ada_lovelace-2.json").is_file());
}

/// Every file of the outputs (all but the cache and the slices' files)
/// is in both folders, with the same bytes.
fn assert_same_outputs(expected: &Path, actual: &Path) {
    let (want, got) = (outputs(expected), outputs(actual));
    assert_eq!(
        want.keys().collect::<Vec<_>>(),
        got.keys().collect::<Vec<_>>(),
        "the same files in {} and {}",
        expected.display(),
        actual.display()
    );
    for (file, bytes) in &want {
        assert!(
            got[file] == *bytes,
            "{file} differs:\n{}\n---- against ----\n{}",
            String::from_utf8_lossy(bytes),
            String::from_utf8_lossy(&got[file])
        );
    }
    assert!(want.len() > 8, "{:?}", want.keys());
}

/// The output files under `dir`, by path relative to it.
fn outputs(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut found = BTreeMap::new();
    let mut folders = vec![dir.to_owned()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if name == ".cache" || name.starts_with("shard-") {
                continue;
            }
            if path.is_dir() {
                folders.push(path);
            } else {
                let relative = path.strip_prefix(dir).unwrap().display().to_string();
                found.insert(relative, std::fs::read(&path).unwrap());
            }
        }
    }
    found
}

/// `sbatch` for a machine without Slurm, as far as the script uses it:
/// logs its arguments, runs the job at once and here, as Slurm would (a
/// copy of the script in a spool folder, so that the script cannot rely
/// on its own path; each task of an array with `SLURM_ARRAY_TASK_ID` from
/// the array's first id), and prints the job's id, as `--parsable` does.
const SBATCH: &str = r#"#!/usr/bin/env bash
set -euo pipefail
echo "$*" >>"$SBATCH_LOG"
id=$(wc -l <"$SBATCH_LOG")
array='' wrap=''
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --array=*) array=${1#--array=} ;;
    --wrap=*) wrap=${1#--wrap=} ;;
  esac
  shift
done
export SLURM_JOB_ID=$id SLURM_SUBMIT_DIR=$PWD
if [[ -n $wrap ]]; then
  bash -c "$wrap" >&2
else
  spool=$SBATCH_SPOOL/job$id
  mkdir -p "$spool"
  cp "$1" "$spool/slurm_script"
  shift
  first=${array%-*} last=${array#*-}
  for ((i = first; i <= last; i++)); do
    SLURM_ARRAY_JOB_ID=$id SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_TASK_COUNT=$((last - first + 1)) \
      SLURM_ARRAY_TASK_MIN=$first SLURM_ARRAY_TASK_MAX=$last \
      bash "$spool/slurm_script" "$@" >&2
  done
fi
echo "$id"
"#;

/// Runs the Slurm example as a teacher does on the login node (`bash
/// slurm-grade.sh`), two slices, with the stand-in `sbatch` first on the
/// PATH; what it printed.
fn slurm_script(base: &Path, class: &Path, reference: &Path, out: &Path) -> String {
    let bin = base.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let sbatch = bin.join("sbatch");
    std::fs::write(&sbatch, SBATCH).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&sbatch, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = std::env::join_paths(
        std::iter::once(bin.clone())
            .chain(std::env::split_paths(&std::env::var_os("PATH").unwrap())),
    )
    .unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("teacher/slurm-grade.sh");
    let run = Command::new("bash")
        .arg(script)
        .current_dir(base)
        .env("PATH", path)
        .env("SBATCH_LOG", base.join("sbatch.log"))
        .env("SBATCH_SPOOL", base.join("spool"))
        .env("CLASS", class)
        .env("OUT", out)
        .env("SHARDS", "2")
        .env("REFERENCE", reference)
        .env("GRADE", env!("CARGO_BIN_EXE_grade"))
        .env("GRADE_ARGS", "--chapters 1")
        .env("CACHE", base.join("cache"))
        .env("SEED", "2026")
        .env_remove("SLURM_ARRAY_TASK_ID")
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(run.status.success(), "the Slurm script failed:\n{text}");
    text
}
