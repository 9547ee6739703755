//! `cargo run -q -p book -- [--open]`: the workbook as a book.
//!
//! The pages are the files a reader already reads: the workspace README,
//! each chapter's `README.md` and the appendices under `book/appendix/`.
//! mdBook reads only pages under its `src` and copies every other file it
//! finds there into the book, so this tool does not point it at the
//! workspace (that would publish `target/` and every solution). It lays the
//! pages out in `target/book/src` at the paths they have in the workspace,
//! so that every relative link and picture works as it does on the
//! repository's own view, copies only the pictures they show, expands
//! `{{#include FILE:ANCHOR}}` itself (refusing a missing anchor, which
//! mdBook lets pass, and any exercise's solution), and runs
//! `mdbook build`. It then checks every link of the HTML it wrote.

mod links;
mod stage;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

const USAGE: &str = "\
usage: cargo run -q -p book -- [--open]

Builds the workbook's book into target/book/html with mdBook, from the
chapter texts (chapters/*/README.md), the workspace README and the
appendices (book/appendix/*.md), in the order book/SUMMARY.md gives.

  --open    open the book in your browser when it is built

It fails on any line mdBook reports as an error or a warning, and on any
link or picture of the built book that leads nowhere (CI runs it).
Needs mdBook: cargo install --locked mdbook";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--help" || a == "-h") {
        println!("{USAGE}");
        return ExitCode::SUCCESS;
    }
    if let Some(bad) = args.iter().find(|a| *a != "--open") {
        eprintln!("error: unknown argument {bad}\n\n{USAGE}");
        return ExitCode::from(2);
    }
    let open = args.iter().any(|a| a == "--open");
    match build(&workspace_root(), open) {
        Ok(pages) => {
            println!(
                "book: {pages} pages, every link and picture found: target/book/html/index.html"
            );
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("error: {error}");
            ExitCode::FAILURE
        }
    }
}

/// The workspace this crate sits in (crates/book).
fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Stages the pages, builds them with mdBook and checks the links; the
/// number of pages built.
fn build(root: &Path, open: bool) -> Result<usize, String> {
    let book = root.join("target/book");
    let pages = stage::stage(root, &book)?;
    run_mdbook(&book, open)?;
    let broken = links::broken_links(&book.join("html"))?;
    if !broken.is_empty() {
        return Err(format!(
            "{} broken links:\n{}",
            broken.len(),
            broken.join("\n")
        ));
    }
    Ok(pages)
}

/// `mdbook build` of the staged book; an error for anything it reports as
/// an error or a warning (it exits 0 on some of them, such as a missing
/// include).
fn run_mdbook(book: &Path, open: bool) -> Result<(), String> {
    let mut command = Command::new("mdbook");
    command.arg("build").arg(book);
    if open {
        command.arg("--open");
    }
    let output = command.output().map_err(|e| {
        format!("cannot run mdbook ({e}); install it with: cargo install --locked mdbook")
    })?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    eprint!("{stderr}");
    let complaints: Vec<&str> = stderr
        .lines()
        .filter(|line| line.contains("ERROR") || line.contains("WARN"))
        .collect();
    if !output.status.success() || !complaints.is_empty() {
        return Err(format!("mdbook build failed:\n{}", complaints.join("\n")));
    }
    Ok(())
}
