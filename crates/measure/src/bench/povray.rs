//! POV-Ray 3.7, the peer raybook is timed against (Debian's `povray`).

use std::path::Path;
use std::process::{Command, Stdio};

/// Whether a `povray` can be run.
pub(super) fn installed() -> bool {
    Command::new("povray")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok()
}

/// POV-Ray rendering `pov` to `png`, `size` pixels square: no anti-aliasing
/// (-A), no display (-D), PNG output (+FN), no messages (-GA -V), and
/// `threads` worker threads (+WT).
pub(super) fn command(pov: &Path, png: &Path, size: u32, threads: u32) -> Command {
    let mut command = Command::new("povray");
    command
        .arg(format!("+I{}", pov.display()))
        .arg(format!("+O{}", png.display()))
        .args([
            format!("+W{size}"),
            format!("+H{size}"),
            format!("+WT{threads}"),
        ])
        .args(["-A", "-D", "+FN", "-GA", "-V"])
        .stdout(Stdio::null());
    command
}
