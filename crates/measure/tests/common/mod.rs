//! What the tests that run the `raybook` binary share: a run with a time
//! limit, and a scene that names a mesh.

#![allow(dead_code)] // each test file uses its own part

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How long a run that should be refused at once may take before it counts
/// as a hang: generous, so that a busy machine does not fail the test (the
/// refusals take milliseconds).
pub const HANG: Duration = Duration::from_secs(10);

/// What a run of `raybook` did.
pub struct Run {
    pub success: bool,
    pub stdout: String,
    pub stderr: String,
    pub took: Duration,
}

/// Runs `raybook ARGS` in `dir`, killed (and the test failed) if it takes
/// longer than [`HANG`].
pub fn raybook(dir: &Path, args: &[&str]) -> Run {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_raybook"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("raybook runs");
    while child
        .try_wait()
        .expect("raybook can be waited for")
        .is_none()
    {
        if start.elapsed() > HANG {
            child.kill().ok();
            child.wait().ok();
            panic!("raybook {args:?} still ran after {HANG:?}: it hangs");
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let output = child.wait_with_output().expect("raybook's output");
    Run {
        success: output.status.success(),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
        took: start.elapsed(),
    }
}

/// A small TOML scene whose second object is a mesh from `path`, named on
/// line [`PATH_LINE`], column [`PATH_COLUMN`] (where its string starts).
pub fn scene_with_mesh(path: &str) -> String {
    format!(
        "[camera]\neye = [0.0, 0.5, 4.0]\nlook_at = [0.0, 0.5, 0.0]\nup = [0.0, 1.0, 0.0]\n\
         vfov = 40.0\n\n[image]\nwidth = 16\nheight = 12\n\n[materials.grey]\n\
         color = [0.7, 0.7, 0.7]\n\n[[lights]]\ntype = \"point\"\nposition = [2.0, 4.0, 3.0]\n\
         intensity = 40.0\n\n[[objects]]\ntype = \"plane\"\nnormal = [0.0, 1.0, 0.0]\n\
         offset = 0.0\nmaterial = \"grey\"\n\n[[objects]]\ntype = \"mesh\"\npath = {path:?}\n\
         material = \"grey\"\n"
    )
}

/// The line of [`scene_with_mesh`] that names the mesh.
pub const PATH_LINE: u32 = 27;

/// The column where the mesh's path starts on [`PATH_LINE`].
pub const PATH_COLUMN: u32 = 8;

/// The names in `dir`, sorted: to see that a refused render left nothing
/// behind (no picture, no temporary file).
pub fn names_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("a readable folder")
        .map(|entry| {
            entry
                .expect("an entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    names.sort();
    names
}

/// Makes a named pipe at `path`.
#[cfg(unix)]
pub fn fifo(path: &Path) {
    let name = std::ffi::CString::new(path.to_str().expect("a UTF-8 path")).expect("no NUL");
    // SAFETY: mkfifo reads a NUL-terminated path that outlives the call.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o600) }, 0, "mkfifo");
}
