//! `workbook progress --watch`: progress again on every save.
//!
//! Watches the chapters' sources (`chapters/`) with the notify crate. Each
//! save of a `.rs` or `.toml` file clears the screen and shows the table
//! and the next exercise again. Saves that come together (an editor writes
//! a file in several steps, a formatter touches many) make one run.
//! Ctrl-C ends it: nothing is left behind, the terminal is as it was.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use notify::{EventKind, RecursiveMode, Watcher};

/// How long after a save to wait for the saves that come with it.
const SETTLE: Duration = Duration::from_millis(300);

/// Runs `progress` (which prints its table and tells whether everything
/// passed) now and after every save of a source file under `root`, with
/// the file saved.
pub fn watch(
    root: &Path,
    mut progress: impl FnMut(Option<&Path>) -> Result<bool, String>,
) -> Result<(), String> {
    let (_watcher, saves) = saves(root)?;
    let mut saved = None;
    loop {
        clear_screen();
        progress(saved.as_deref())?;
        println!("\nwatching chapters/ for saves (Ctrl-C to stop)");
        saved = next_save(&saves)?;
    }
}

/// The saves of `.rs` and `.toml` files under `root`'s `chapters/`, as
/// they come, each with the file saved (the lab watches with this too).
/// They come while the watcher returned is kept.
pub fn saves(
    root: &Path,
) -> Result<(impl Watcher + use<>, mpsc::Receiver<Option<PathBuf>>), String> {
    let (saved, saves) = mpsc::channel();
    let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
        if let Ok(event) = event
            && is_a_save(&event)
        {
            let _ = saved.send(event.paths.first().cloned());
        }
    })
    .map_err(|e| format!("cannot watch files: {e}"))?;
    let chapters = root.join("chapters");
    watcher
        .watch(&chapters, RecursiveMode::Recursive)
        .map_err(|e| format!("cannot watch {}: {e}", chapters.display()))?;
    Ok((watcher, saves))
}

/// Waits for a save, then for the ones that come with it; the file saved.
pub fn next_save(saves: &mpsc::Receiver<Option<PathBuf>>) -> Result<Option<PathBuf>, String> {
    let saved = saves
        .recv()
        .map_err(|_| "the file watcher stopped".to_owned())?;
    while saves.recv_timeout(SETTLE).is_ok() {}
    Ok(saved)
}

/// Is this a change to a Rust source or a TOML file (not an editor's
/// swap file, not a mere read)?
fn is_a_save(event: &notify::Event) -> bool {
    let changes = matches!(
        event.kind,
        EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_)
    );
    let sources = event
        .paths
        .iter()
        .any(|p| p.extension().is_some_and(|e| e == "rs" || e == "toml"));
    changes && sources
}

/// Clears the terminal, if it is one (a pipe keeps every run).
fn clear_screen() {
    if std::io::stdout().is_terminal() {
        print!("\x1b[2J\x1b[H");
    }
}
