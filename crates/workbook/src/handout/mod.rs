//! `workbook handout DIR`: a copy of the workbook with the exercises taken out.
//!
//! The chapters mark the code a student writes as exercise regions (see
//! [`regions`]); a handout is the workspace with each region's body replaced
//! by `todo!`, so that its tests fail until the student writes it.

pub mod check;
pub mod record;
pub mod share;
pub mod take_out;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

pub use crate::regions::{ALLOW_UNUSED, END, Region, START, hand_out, regions, replace_bodies};
pub use crate::workspace::{
    Written, current_workspace, holds_exercises, workspace_files, workspace_regions, write_tree,
    write_tree_with,
};
use check::{Caught, Check};

/// `workbook handout DIR`: writes the workbook with its exercises taken out.
#[derive(clap::Args, Debug, Clone)]
#[command(group = clap::ArgGroup::new("what").required(true))]
pub struct HandoutArgs {
    /// Where to write the copy: a folder that does not exist yet, or an
    /// empty one.
    #[arg(group = "what")]
    pub dir: Option<PathBuf>,

    /// With DIR: leave the exercises of chapters 1 to N solved, so that a
    /// teacher can release the solutions as the course goes on (0: none).
    #[arg(long, value_name = "N", requires = "dir")]
    pub solved_through: Option<u32>,

    /// With DIR: write the files only. By default the registry crates this
    /// clone has compiled are copied into DIR's target/ too, so that the
    /// first `progress` there builds only the workbook's own crates (about
    /// 40 s instead of 80 on two cores); a handout for another machine, or
    /// one of many for a class, has no use for them.
    #[arg(long, requires = "dir")]
    pub files_only: bool,

    /// The maintainers' check that needs a second build of the workbook
    /// (in target/handout-check): the lecture's own methods (the
    /// `[[lecture]]` solutions of the chapters' mistakes.toml) pass every
    /// test of their chapters, and the whole handout compiles. That each
    /// exercise makes a test fail is part of `cargo test`.
    #[arg(long, group = "what")]
    pub check: bool,

    /// The maintainers' check of the tests: write each classic mistake of
    /// the chapters' mistakes.toml into its exercise, run the chapter's
    /// tests, and show which mistakes the tests catch. Fails if one goes
    /// unnoticed.
    #[arg(long, group = "what")]
    pub check_mistakes: bool,

    /// With --check-mistakes: only the mistakes of the exercises whose id
    /// starts with this (`ch06-split`, or `ch06` for a whole chapter).
    #[arg(long, requires = "check_mistakes", value_name = "ID")]
    pub only: Option<String>,
}

/// Runs `workbook handout`.
pub fn main(args: &HandoutArgs) -> ExitCode {
    let result = match &args.dir {
        Some(dir) => write_handout(dir, args.solved_through.unwrap_or(0), !args.files_only),
        None if args.check => check_handout(),
        None => check_mistakes(args.only.as_deref().unwrap_or("")),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Writes the handout into `dir`, with the exercises of chapters 1 to
/// `solved_through` left solved.
/// Then, with `compiled`, it copies in the registry crates this workspace
/// has compiled ([`share_builds`]).
fn write_handout(dir: &Path, solved_through: u32, compiled: bool) -> Result<(), String> {
    let root = current_workspace()?;
    write_handout_from(&root, dir, solved_through)?;
    if compiled {
        share_builds(&root, dir);
    }
    println!(
        "\nnext: cd {} && cargo run -q -p workbook -- progress\n      \
         then read chapters/01-rays/README.md and write the exercises of chapter 1",
        dir.display()
    );
    Ok(())
}

/// [`write_handout`]'s files, from the workspace at `root` (the grader's
/// tests make handouts of a still snapshot of the reference): no compiled
/// crate is copied.
pub fn write_handout_from(root: &Path, dir: &Path, solved_through: u32) -> Result<(), String> {
    let root = root.to_owned();
    if let Ok(mut entries) = std::fs::read_dir(dir)
        && entries.next().is_some()
    {
        return Err(format!(
            "{} exists and is not empty; name a new or empty folder",
            dir.display()
        ));
    }
    if dir.exists() && !dir.is_dir() {
        return Err(format!("{} exists and is not a folder", dir.display()));
    }
    let written = write_tree(&root, dir, |r| {
        r.chapter().is_none_or(|chapter| chapter > solved_through)
    })?;
    // Which raybook it was made from, for `grade`.
    record::Record::of_workspace(&root).write(dir)?;
    println!(
        "wrote {} files of {} to {}",
        written.files,
        root.display(),
        dir.display()
    );
    if solved_through > 0 {
        println!("the exercises of chapters 1 to {solved_through} are solved");
    }
    println!("{} exercises to write:", written.regions.len());
    for (file, line, region) in &written.regions {
        println!("  {:<20} {}:{line}", region.id, file.display());
    }
    Ok(())
}

/// Copies into the handout's target folder the registry crates this
/// workspace has compiled already (the workbook's tools' at least: this
/// command was built with them), so that the handout's first `progress`
/// compiles only what is new there. Says what it did; a failure costs only
/// time, so it is a note, not an error.
fn share_builds(root: &Path, dir: &Path) {
    match share::registry_builds(root, &dir.join("target"), share::How::Copy) {
        Ok(0) => {}
        Ok(n) => println!(
            "copied {n} compiled dependencies ({} MB) from {}/target (--files-only: none)",
            size_of(&dir.join("target")) >> 20,
            root.display()
        ),
        Err(e) => println!("note: the handout builds its dependencies itself ({e})"),
    }
}

/// The bytes of the files under `path`.
fn size_of(path: &Path) -> u64 {
    let Ok(entries) = std::fs::read_dir(path) else {
        return std::fs::metadata(path).map_or(0, |m| m.len());
    };
    entries.flatten().map(|e| size_of(&e.path())).sum()
}

/// The lecture's methods pass and the whole handout compiles.
fn check_handout() -> Result<(), String> {
    let root = current_workspace()?;
    let check = Check::new(&root)?;
    for line in check::lectures_pass(&check, &root)? {
        println!("{line}");
    }
    check::whole_handout_builds(&check)?;
    println!("the whole handout compiles");
    Ok(())
}

/// Replays every recorded mistake and prints what the tests made of it.
fn check_mistakes(only: &str) -> Result<(), String> {
    let root = current_workspace()?;
    let check = Check::new(&root)?;
    let mut missed = Vec::new();
    let mut count = 0;
    for (chapter, file) in check::mistakes_files(&root)? {
        for mistake in file.mistake.iter().filter(|m| m.exercise.starts_with(only)) {
            count += 1;
            let caught = check::replay(&check, chapter, mistake)?;
            let verdict = match &caught {
                Caught::Named => "caught, named".to_owned(),
                Caught::Unnamed => format!("caught, but no test says {:?}", mistake.expect),
                Caught::Misblamed(ids) => {
                    format!(
                        "MISBLAMED: a test says the mistake is in {}",
                        ids.join(", ")
                    )
                }
                Caught::Missed => "MISSED: every test passes".to_owned(),
                Caught::NoBuild(e) => format!("MISSED: does not compile: {e}"),
            };
            println!("{:<22} {:<44} {verdict}", mistake.exercise, mistake.what);
            if !matches!(caught, Caught::Named) {
                missed.push(format!("{}: {}", mistake.exercise, mistake.what));
            }
        }
    }
    println!(
        "{} of {count} mistakes caught and named",
        count - missed.len()
    );
    if missed.is_empty() {
        Ok(())
    } else {
        Err(format!("not caught and named: {}", missed.join("; ")))
    }
}
