//! The chapters the lab shows, and running a chapter's own binary (the
//! debug build that its tests and `progress` made, or that the lab builds).

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use workbook::verify::tree::facts::SIZE;
use workbook::workbench::chapters::{self, ChapterEntry};

/// The chapters with a bench: those with a reference picture
/// (chapters.toml's `verify`), in order.
pub fn benches() -> Vec<&'static ChapterEntry> {
    chapters::all()
        .iter()
        .filter(|c| c.verify.is_some())
        .collect()
}

/// A chapter of the bench, by folder (`02-hits`), or a clear error.
pub fn bench_chapter(name: &str) -> Result<&'static ChapterEntry, String> {
    benches()
        .into_iter()
        .find(|c| c.folder == name)
        .ok_or_else(|| {
            let names: Vec<String> = benches().iter().map(|c| c.folder.clone()).collect();
            format!("no chapter {name:?}; the chapters are {}", names.join(", "))
        })
}

/// The debug build of a chapter's binary in the workspace at `root`.
pub fn binary(root: &Path, chapter: &ChapterEntry) -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"));
    let name = format!("{}{}", chapter.package(), std::env::consts::EXE_SUFFIX);
    let target = if target.is_relative() {
        root.join(target)
    } else {
        target
    };
    target.join("debug").join(name)
}

/// How long a chapter's binary may take before the lab stops it: a render
/// at 160×120 takes well under a second in a debug build, unless the
/// student's code loops forever.
pub const PATIENCE: Duration = Duration::from_secs(60);

/// Runs the chapter's binary on its default scene at the snapshot size
/// (with the arguments of its reference picture) and `extra` arguments;
/// stopped after [`PATIENCE`].
pub fn run(root: &Path, chapter: &ChapterEntry, extra: &[&str]) -> Result<Output, String> {
    let (width, height) = (SIZE.0.to_string(), SIZE.1.to_string());
    let mut args = vec!["--width", &width, "--height", &height, "--quiet"];
    let reference = chapter.verify.as_ref().map(|v| v.args.as_slice());
    args.extend(reference.unwrap_or_default().iter().map(String::as_str));
    args.extend(extra);
    run_with(root, chapter, &args, PATIENCE)
}

/// Runs the chapter's binary with exactly `args` (in `root`), stopped
/// after `patience`.
pub fn run_with(
    root: &Path,
    chapter: &ChapterEntry,
    args: &[&str],
    patience: Duration,
) -> Result<Output, String> {
    let binary = binary(root, chapter);
    if !binary.exists() {
        return Err(format!(
            "chapter {}'s binary is not built yet ({}): the lab builds it when it shows the chapter",
            chapter.folder,
            binary.display()
        ));
    }
    let mut child = Command::new(&binary)
        .args(args)
        .current_dir(root)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run {}: {e}", binary.display()))?;
    let (stdout, stderr) = (
        read_at_most(child.stdout.take()),
        read_at_most(child.stderr.take()),
    );
    let started = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if started.elapsed() > patience => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "chapter {}'s binary ran for more than {} s and was stopped: does a loop of yours never end?",
                    chapter.folder,
                    patience.as_secs()
                ));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(2)),
            Err(e) => return Err(format!("cannot wait for {}: {e}", binary.display())),
        }
    };
    Ok(Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    })
}

/// The most bytes of a run's stdout, or of its stderr, that the lab keeps:
/// a ray tree's JSON is a few kB, but a `println!` or `dbg!` left in a loop
/// that never ends prints gigabytes in the minute a run may take.
pub const MOST_OUTPUT: u64 = 16 << 20;

/// Reads a pipe to its end on a thread of its own (so that the child never
/// waits on a full pipe), keeping its first [`MOST_OUTPUT`] bytes.
fn read_at_most(pipe: Option<impl Read + Send + 'static>) -> JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.by_ref().take(MOST_OUTPUT).read_to_end(&mut kept);
            let _ = std::io::copy(&mut pipe, &mut std::io::sink());
        }
        kept
    })
}

/// The exercise whose `todo!` a run reached: its id and hint, from the
/// panic message `not yet implemented: ID: hint`.
pub fn todo_reached(stderr: &str) -> Option<(String, String)> {
    let (_, rest) = stderr.split_once("not yet implemented: ")?;
    let line = rest.lines().next().unwrap_or(rest);
    let (id, hint) = line.split_once(": ").unwrap_or((line, ""));
    Some((id.trim().to_owned(), hint.trim().to_owned()))
}

/// What a failed run said, shortened: its panic or its last lines.
pub fn failure(output: &Output) -> String {
    let stderr = String::from_utf8_lossy(&output.stderr);
    if let Some((id, hint)) = todo_reached(&stderr) {
        return format!("your code reached the todo! of exercise {id} ({hint}): write it first");
    }
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    let tail = &lines[lines.len().saturating_sub(8)..];
    format!(
        "the chapter's binary failed ({}):\n{}",
        output.status,
        tail.join("\n")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_todo_names_its_exercise() {
        let stderr = "thread 'main' (7) panicked at chapters/02-hits/src/sphere.rs:40:5:\n\
                      not yet implemented: ch02-sphere: where the ray meets the sphere\nnote: …";
        assert_eq!(
            todo_reached(stderr),
            Some((
                "ch02-sphere".into(),
                "where the ray meets the sphere".into()
            ))
        );
        assert_eq!(todo_reached("error: no such file"), None);
    }

    #[test]
    fn a_flood_of_output_is_read_to_its_end_but_not_kept() {
        let flood = std::io::repeat(b'x').take(MOST_OUTPUT + 3 * 4096);
        let kept = read_at_most(Some(flood)).join().unwrap();
        assert_eq!(kept.len() as u64, MOST_OUTPUT);
        assert!(
            read_at_most(None::<std::io::Empty>)
                .join()
                .unwrap()
                .is_empty()
        );
    }

    #[test]
    fn chapters_are_found_by_folder_only() {
        assert_eq!(bench_chapter("02-hits").unwrap().number(), 2);
        let error = bench_chapter("../02-hits").unwrap_err();
        assert!(
            error.contains("the chapters are 01-rays, 02-hits"),
            "{error}"
        );
        assert!(
            bench_chapter("08-bvh").is_err(),
            "a chapter without a reference"
        );
    }
}
