//! `cargo run -p grade`: a teacher grades a class, every student's handout in
//! one run, or one submission as Gradescope's autograder runs it.
//!
//! For each student, each exercise passed or not, and each chapter's tests
//! passed and failed, the first failing test's message, the time taken,
//! whether it compiled. An exercise passes when the values the student's
//! function computed on inputs drawn from a seed agree with the
//! reference's, judged outside the sandbox, and its chapter's seeded
//! scenes agree too (`judge.rs` states the rule, `probe.rs` runs the
//! teacher's probe, `crates/grade-probe`); the chapters' tests run for the
//! feedback their messages give, and decide only an exercise no probe
//! covers (`mapping.rs`). The seed is drawn at grading time and kept in the
//! output folder, never in a handout. Outputs (`report/`): a CSV
//! gradebook, a Gradescope `results.json` per student, JUnit XML, an HTML
//! class report.
//!
//! Student code is untrusted. What grading does about it:
//! * it runs in a fresh copy, never in the student's folder, which is only
//!   read (`submission.rs`, `student.rs`), and symlinks are never followed;
//! * the copy holds the reference's files but for the student's own
//!   folders (each exercise chapter's `src/`): the tests, pictures,
//!   manifest, Cargo files and lock file are the reference's, and no build
//!   script of the student's is there; edits to them are flagged, and so
//!   are sources that reach outside their chapter (`#[path]`, `include!`
//!   and its kin: `reach.rs`) and build settings among their sources;
//! * every build and test run is in bubblewrap (`confine.rs`): an empty
//!   root holding the toolchain and registry sources read-only, the copy
//!   read-only, and its `target/` writable, a size-limited file system of
//!   the student's own; every namespace its own (no network, no host
//!   sockets, a PID namespace whose processes all end with the run); the
//!   student's processes together in a control group bounding their
//!   memory and number where the system allows one (`cgroup.rs`); cargo
//!   `--offline`, with a small environment. Where the sandbox cannot
//!   start, grading refuses to, unless the teacher says
//!   `--unsafe-no-sandbox`, which every output then shows;
//! * each run is killed at its time limit, under limits on address space,
//!   file size and core dumps, with a cap on what it prints (`sandbox.rs`);
//!   what stopped a run is recorded and the next one starts; Ctrl-C ends
//!   them too;
//! * the shared build artefacts are copies in the student's own target
//!   folder, never links to the base build or the teacher's (`share.rs`);
//! * what leaves the sandbox is checked: failure pictures are copied out
//!   only if they are regular files, of a bounded size, read within a
//!   time (`outbound.rs`); anything else in their place is refused and
//!   flagged.
//!
//! What the design still trusts, and why that is acceptable:
//! * the kernel and bubblewrap: a student who escapes a user namespace has
//!   a kernel exploit, which no grader stops; bubblewrap is small, audited
//!   and what every Flatpak application runs in, and distributions ship
//!   its fixes. A teacher who grades strangers (a MOOC) should still run
//!   `grade` in a throwaway virtual machine or account, as Gradescope does;
//! * the toolchain and the registry sources, which the students' code may
//!   read (they are public, and read-only in the sandbox), and rustc and
//!   the linker, which run on the student's source: a compiler bug that
//!   runs code at compile time runs it inside the same sandbox;
//! * the students' own copies: within its run, a student's code may write
//!   its own `target/` (its own build, its own failure pictures), so what
//!   the tests print and write is theirs to forge. Points therefore come
//!   not from a student's own report of itself but from the values its
//!   code computed on inputs it never saw, judged outside the sandbox
//!   (`judge.rs`); the pictures leave only through `outbound.rs`. An
//!   exercise that no probe covers yet is still judged by its tests, which
//!   a student can forge: every exercise of chapters 1 to 7 is probed, so
//!   none is left, but a new exercise is until its probe is written;
//! * the CPU: nothing but the time limits bounds a student's CPU time, and
//!   students graded side by side share the cores (a slow neighbour costs
//!   time, never points, since no verdict depends on speed);
//! * on cgroup v1 without a group the grader may make (an unprivileged
//!   teacher), the memory of a student's processes is bounded one process
//!   at a time (`--memory` of address space each) and their number only by
//!   the time limit; grading says so when it starts. `cgroup.rs` says how
//!   to bound them on a cgroup-v2 system;
//! * with `--unsafe-no-sandbox`, everything: the code runs as the teacher,
//!   reads and writes what the teacher can and reaches the network. It is
//!   for a class one trusts, and every output says it was used.

use ch00_toolkit as toolkit;
use workbook::{handout, progress, regions, workspace};

mod args;
mod beneath;
mod cargo;
mod cgroup;
mod class;
mod confine;
mod digest;
mod judge;
mod mapping;
mod merge;
mod outbound;
mod outcomes;
mod points;
mod pool;
mod probe;
mod reach;
mod reference;
mod report;
mod result;
mod room;
mod sandbox;
mod shard;
mod share;
mod student;
mod submission;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use reference::{Reference, Settings};
use sandbox::Limits;
use workbench::chapters::{self, ChapterEntry};
use workbook::workspace::current_workspace;

pub use args::GradeArgs;
/// The grader's rule for a seeded scene (the probe's mistakes check uses it).
pub use judge::picture_problem;
pub use result::{ChapterRun, StudentResult, Verdict};

/// The version of what grading caches (the tests of each exercise, each
/// student's result): a new one when what they mean changes, so that a
/// cache of an older workbook is never read as this one's.
const CACHE_FORMAT: &str = "grade-cache-2";

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
        return merge::main(args, &root, &out);
    }
    let (class, names) = students(args)?;
    let settings = settings(args, &out, &class)?;
    sandbox_setup(args)?;
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
    let points = points::Points::load(args.points.as_deref(), &out, &ids)?;
    let class_outputs = report::Class {
        reference: &reference,
        points: &points,
        students: &results,
    };
    let written = match args.shard {
        Some(shard) => {
            let graded_with = shard::graded_with(&reference, &settings, names.clone());
            let file = shard::ShardFile {
                shard,
                graded_with,
                students: results.clone(),
            };
            vec![shard::write(&out, &file)?]
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
fn sandbox_setup(args: &GradeArgs) -> Result<(), String> {
    let setup = confine::start(
        !args.unsafe_no_sandbox,
        args.disk << 20,
        args.memory << 20,
        PROCESSES,
    )?;
    if !setup.sandboxed {
        eprintln!("WARNING: {}", confine::UNSANDBOXED);
    } else if let Err(why) = &setup.cgroups {
        eprintln!(
            "note: no control group per student here ({why}): each process is held to \
             --memory alone, and the number of processes only by the time limit"
        );
    }
    Ok(())
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
fn settings(args: &GradeArgs, out: &Path, class: &Path) -> Result<Settings, String> {
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
