//! `cargo run -p grade`: a teacher grades a class, every student's handout in
//! one run, or one submission as Gradescope's autograder runs it.
//!
//! For each student, each exercise passed or not, and each chapter's tests
//! passed and failed, the first failing test's message, the time taken,
//! whether it compiled. An exercise passes when the values the student's
//! function computed on inputs drawn from a seed agree with the
//! reference's, judged outside the sandbox, and its chapter's seeded
//! scenes agree too; the chapters' tests run for the feedback their
//! messages give. The seed is drawn at grading time and kept in the output
//! folder, never in a handout.
//!
//! The grader's parts, by concern. None imports another in a circle:
//! each uses only the parts above it in this table.
//!
//! | part        | what it holds |
//! |-------------|---------------|
//! | `sandbox/`  | where a student's code runs and what may leave it: bubblewrap (`bwrap.rs`), the student's build folder (`build_folder.rs`), control groups (`cgroup.rs`), limits on a run (`limits.rs`), reading beneath a folder (`beneath.rs`), the failure pictures (`outbound.rs`); **the trust model** is its `mod.rs` |
//! | `build/`    | cargo in a copy (`cargo.rs`), the build artefacts students share (`share.rs`), a digest |
//! | `judging/`  | what a student is judged against, and how: the reference (`reference.rs`), the probe (`probe.rs`), the rule (`rule.rs`), the tests of each exercise (`exercise_tests.rs`) and their outcomes, the verdicts (`verdict.rs`) |
//! | `report/`   | the outputs: the CSV gradebook, a Gradescope `results.json` per student, JUnit XML, the HTML report, the points |
//! | `class/`    | the students: a folder read (`submission.rs`), one graded (`student.rs`), in slices and merged (`shard.rs`, `merge.rs`), sources that reach outside (`source_paths.rs`) |
//!
//! Beside them, `args.rs` (the command line) and `pool.rs` (work side by
//! side: the students, the reference's runs).

use ch00_toolkit as toolkit;

mod args;
mod build;
mod class;
mod judging;
mod pool;
mod report;
mod sandbox;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use judging::probe;
use judging::reference::{Reference, Settings};
use sandbox::bwrap::Setup;
use sandbox::limits::Limits;
use workbench::chapters::{self, ChapterEntry};
use workbook::workspace::current_workspace;

pub use args::GradeArgs;
/// The grader's rule for a seeded scene (the probe's mistakes check uses it).
pub use judging::rule::picture_problem;
pub use judging::verdict::{ChapterRun, StudentResult, Verdict};

/// Runs `grade`.
pub fn main(args: &GradeArgs) -> ExitCode {
    match grade(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Prepares the reference, grades the students (or the slice `--shard`
/// names), writes the outputs; or, with `--merge`, joins slices.
fn grade(args: &GradeArgs) -> Result<(), String> {
    let root = match &args.reference {
        Some(dir) => dir
            .canonicalize()
            .map_err(|e| format!("{}: {e}", dir.display()))?,
        None => current_workspace()?,
    };
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("target/grade"));
    std::fs::create_dir_all(&out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let out = out.canonicalize().map_err(|e| e.to_string())?;
    if !args.merge.is_empty() {
        return class::merge::main(args, &root, &out);
    }
    let (class, names) = students(args)?;
    let sandbox = sandbox_setup(args)?;
    let settings = settings(args, &out, &class, sandbox)?;
    let seed_file = out.join("seed.txt");
    toolkit::image::write_atomically(&seed_file, format!("{}\n", settings.seed).as_bytes())
        .map_err(|e| format!("cannot write {}: {e}", seed_file.display()))?;
    let start = Instant::now();
    let reference = Reference::prepare(&root, &settings, &|line| eprintln!("{line}"))?;
    let prepared = start.elapsed();
    let start = Instant::now();
    let slugs = class::slugs(&names);
    let (chosen, chosen_slugs): (Vec<String>, Vec<String>) = (names.iter().cloned())
        .zip(slugs)
        .filter(|(name, _)| args.shard.is_none_or(|shard| shard.holds(name)))
        .unzip();
    let (results, graded) = class::grade_class(
        &class,
        (&chosen, &chosen_slugs),
        &reference,
        &settings,
        (&out, args.again),
    );
    let took = start.elapsed();
    let ids: Vec<_> = reference.tests.exercises.clone();
    let points = report::points::Points::load(args.points.as_deref(), &out, &ids)?;
    let class_outputs = report::Class {
        reference: &reference,
        points: &points,
        students: &results,
    };
    let written = match args.shard {
        Some(shard) => {
            let graded_with = class::shard::graded_with(&reference, &settings, names.clone());
            let file = class::shard::ShardFile {
                shard,
                graded_with,
                students: results.clone(),
            };
            vec![class::shard::write(&out, &file)?]
        }
        None => report::write_all(&out, &class_outputs)?,
    };
    if let (Some(path), Some(student)) = (&args.gradescope, results.first()) {
        report::write(path, report::results_json(&class_outputs, student))?;
    }
    report::print_table(&class_outputs);
    let refused = results.iter().filter(|s| s.refused.is_some()).count();
    let unchanged = results.len() - graded - refused;
    println!(
        "\nreference prepared in {:.0} s; students: {graded} graded in {:.0} s ({} side \
         by side), {unchanged} unchanged since the last run, {refused} not graded",
        prepared.as_secs_f64(),
        took.as_secs_f64(),
        settings.jobs
    );
    if let Some(shard) = args.shard {
        let (slice, of) = (results.len(), names.len());
        println!("slice {shard}: {slice} of the class's {of} students");
    }
    report::print_written(&class_outputs, &written);
    Ok(())
}

/// Starts the students' sandbox (or refuses to grade, saying why), and
/// says what bounds a student.
fn sandbox_setup(args: &GradeArgs) -> Result<Setup, String> {
    let setup = sandbox::bwrap::start(
        !args.unsafe_no_sandbox,
        args.disk << 20,
        args.memory << 20,
        PROCESSES,
    )?;
    if !setup.sandboxed {
        eprintln!("WARNING: {}", sandbox::bwrap::UNSANDBOXED);
    } else if let Err(why) = &setup.cgroups {
        eprintln!(
            "note: no control group per student here ({why}): each process is held to \
             --memory alone, and the number of processes only by the time limit"
        );
    }
    Ok(setup)
}

/// Processes and threads a student may have at once (with a control group).
const PROCESSES: u64 = 2048;

/// The class folder and the student folders' names in it (for --one, the
/// submission's parent and its name).
fn students(args: &GradeArgs) -> Result<(PathBuf, Vec<String>), String> {
    if let Some(one) = &args.one {
        let absolute = std::path::absolute(one).map_err(|e| format!("{}: {e}", one.display()))?;
        let name = absolute
            .file_name()
            .map(|n| n.to_string_lossy().into_owned());
        let parent = absolute.parent().map(Path::to_owned);
        let (Some(name), Some(parent)) = (name, parent) else {
            return Err(format!("{}: not a folder to grade", one.display()));
        };
        return Ok((parent, vec![name]));
    }
    let class = args
        .students
        .as_ref()
        .expect("clap requires STUDENTS or --one");
    let class = class
        .canonicalize()
        .map_err(|e| format!("the class folder {}: {e}", class.display()))?;
    let names = class::list(&class)?;
    Ok((class, names))
}

/// The settings the arguments give.
fn settings(
    args: &GradeArgs,
    out: &Path,
    class: &Path,
    sandbox: Setup,
) -> Result<Settings, String> {
    if let (Some(shard), None) = (&args.shard, args.seed) {
        return Err(format!(
            "--shard {shard}: every slice must judge on the same inputs; give each the same \
             --seed N (the Slurm and GitHub examples draw one for the whole class)"
        ));
    }
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let jobs = args.jobs.unwrap_or(cores).max(1);
    let limits = |seconds| Limits {
        time: Duration::from_secs(seconds),
        memory: args.memory << 20,
        output: (args.output as usize) << 20,
    };
    let cache = args.cache.clone().unwrap_or_else(|| out.join(".cache"));
    std::fs::create_dir_all(&cache)
        .map_err(|e| format!("cannot create {}: {e}", cache.display()))?;
    let cache = cache.canonicalize().map_err(|e| e.to_string())?;
    Ok(Settings {
        chapters: chosen_chapters(args.chapters.as_deref())?,
        build: limits(args.build_timeout),
        test: limits(args.timeout),
        cargo_jobs: (cores / jobs).max(1),
        jobs,
        exclude: vec![out.to_owned(), class.to_owned(), cache.clone()],
        cache,
        // A resubmission on Gradescope (--one) is judged on inputs drawn
        // afresh, so that no table of answers can be built over
        // resubmissions; a class keeps one seed for all its runs.
        seed: match &args.one {
            Some(_) => probe::seed(args.seed, None),
            None => probe::seed(args.seed, Some(&out.join("seed.txt"))),
        },
        sandbox: std::sync::Arc::new(sandbox),
    })
}

/// The chapters with exercises whose numbers `list` names (`1-3`, `1,2,5`);
/// all of them without a list.
pub fn chosen_chapters(list: Option<&str>) -> Result<Vec<&'static ChapterEntry>, String> {
    let graded: Vec<&'static ChapterEntry> =
        chapters::all().iter().filter(|c| c.exercises).collect();
    let Some(list) = list else {
        return Ok(graded);
    };
    let mut numbers = Vec::new();
    for part in list.split(',').map(str::trim) {
        let number = |s: &str| {
            s.trim()
                .parse::<u32>()
                .map_err(|_| format!("--chapters {list}: {s:?} is not a chapter number"))
        };
        match part.split_once('-') {
            Some((from, to)) => numbers.extend(number(from)?..=number(to)?),
            None => numbers.push(number(part)?),
        }
    }
    let chosen: Vec<_> = (graded.iter().copied())
        .filter(|c| numbers.contains(&c.number()))
        .collect();
    match numbers
        .iter()
        .find(|n| !chosen.iter().any(|c| c.number() == **n))
    {
        Some(n) => Err(format!(
            "--chapters {list}: chapter {n} has no exercises to grade"
        )),
        None => Ok(chosen),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chapters_are_chosen_by_ranges_and_lists() {
        let folders = |list| {
            let chosen = chosen_chapters(Some(list)).unwrap();
            chosen.iter().map(|c| c.number()).collect::<Vec<_>>()
        };
        assert_eq!(folders("1-3"), [1, 2, 3]);
        assert_eq!(folders("1, 5,2"), [1, 2, 5]);
        assert!(
            chosen_chapters(Some("8"))
                .unwrap_err()
                .contains("no exercises")
        );
        assert!(chosen_chapters(Some("x")).is_err());
        assert!(chosen_chapters(None).unwrap().len() >= 7);
    }
}
