//! `raybook handout DIR`: a copy of the workbook with the exercises taken out.
//!
//! The chapters mark the code a student writes as exercise regions (see
//! [`regions`]); a handout is the workspace with each region's body replaced
//! by `todo!`, so that its tests fail until the student writes it.

mod regions;
mod workspace;

use std::path::PathBuf;
use std::process::ExitCode;

pub use regions::{ALLOW_UNUSED, END, Region, START, hand_out, regions};
pub use workspace::{
    Written, current_workspace, holds_exercises, workspace_files, workspace_regions, write_tree,
};

/// `raybook handout DIR`: writes the workbook with its exercises taken out.
#[derive(clap::Args, Debug, Clone)]
pub struct HandoutArgs {
    /// Where to write the copy: a folder that does not exist yet, or an
    /// empty one.
    pub dir: PathBuf,
}

/// Runs `raybook handout`.
pub fn main(args: &HandoutArgs) -> ExitCode {
    match run(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &HandoutArgs) -> Result<(), String> {
    let root = current_workspace()?;
    let dir = &args.dir;
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
    let written = write_tree(&root, dir, |_| true)?;
    println!(
        "wrote {} files of {} to {}",
        written.files,
        root.display(),
        dir.display()
    );
    println!("{} exercises to write:", written.regions.len());
    for (file, line, region) in &written.regions {
        println!("  {:<20} {}:{line}", region.id, file.display());
    }
    println!(
        "\nnext: cd {} && cargo run --release -- progress\n      \
         then read chapters/01-rays/README.md and write the exercises of chapter 1",
        dir.display()
    );
    Ok(())
}
