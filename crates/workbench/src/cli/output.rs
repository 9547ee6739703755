//! What a chapter binary shows besides its picture: the progress bar while
//! it renders, the report after, and a quiet end when its reader goes away.

use indicatif::{ProgressBar, ProgressStyle};

use super::{Chapter, Rendered};

/// A progress bar over the rows of a render; hidden when `quiet` (and by
/// indicatif itself when the output is not a terminal).
pub fn progress_bar(rows: u32, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(rows as u64);
    let style =
        ProgressStyle::with_template("{spinner} rendering [{bar:40}] {pos}/{len} rows, {eta} left")
            .expect("a valid template")
            .progress_chars("=> ");
    bar.set_style(style);
    bar
}

/// Prints what was rendered, where, how big, how long and how many rays.
pub fn report(chapter: &Chapter, scene: &str, out: &std::path::Path, r: &Rendered) {
    println!(
        "chapter {} ({}): rendered {scene}\nwrote {} ({}×{} pixels) in {:.3} s\n{}",
        chapter.entry().folder,
        chapter.entry().title,
        out.display(),
        r.image.width,
        r.image.height,
        r.seconds.as_secs_f64(),
        r.stats
    );
}

/// Lets the process end quietly when whoever reads its output goes away, as
/// `raybook render … | head -1` does after one line.
///
/// A Rust program ignores the signal (SIGPIPE) that ends other command-line
/// tools then, so its next `println!` would panic ("failed printing to
/// stdout: Broken pipe"). Restoring the signal's default action makes the
/// process end silently instead, like `cat` or `grep`. Every binary calls
/// this first (chapter binaries through [`run_or_explain`]).
pub fn end_quietly_when_output_closes() {
    #[cfg(unix)]
    // SAFETY: signal() only sets the process's action for SIGPIPE back to
    // the default; no handler of ours runs.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}
