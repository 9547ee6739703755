//! Confining a student's build and tests with Linux namespaces, where the
//! system lets us make them (`unshare` and `setpriv` from util-linux, and
//! user namespaces, which let an unprivileged teacher do it too):
//!
//! * a network namespace of their own: nothing to reach, not even by a test
//!   that ignores `cargo --offline`;
//! * a mount namespace in which every file system is read-only but their
//!   copy (its sources, its target folder, its HOME and TMPDIR), with an
//!   empty `/dev/shm` of their own: a test cannot delete or change the
//!   teacher's files, the other students' copies or the reference's;
//! * no capabilities and no way to gain any (`setpriv --no-new-privs`,
//!   every capability dropped), so that they cannot undo the above: the
//!   namespace's root may remount, its processes may not.
//!
//! Where that cannot be made, the network namespace alone is tried, and
//! then nothing (`grade` says which). Reading is not confined: a
//! test can read any file the teacher can (but has no network to send it
//! anywhere).

use std::ffi::OsStr;
use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::OnceLock;

/// What a confined command gets, from the most confined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Confinement {
    /// Read-only file systems but its copy, no network, no capabilities.
    Full,
    /// No network.
    Network,
    /// Nothing: the system allows no namespace.
    None,
}

/// Makes every mount read-only but `$1` (the copy, bound onto itself so
/// that it is a mount of its own and stays writable), `/proc`, `/sys` and
/// `/dev`; gives the run an empty `/dev/shm`; drops every capability and
/// runs the rest of the arguments.
const SCRIPT: &str = r#"set -e
w="$1"; shift
mount --bind "$w" "$w"
while read -r _ _ _ _ m _; do
  case "$m" in
    /proc|/proc/*|/sys|/sys/*|/dev|/dev/pts|/dev/pts/*|"$w") ;;
    *) mount -o remount,bind,ro "$m" 2>/dev/null || true ;;
  esac
done < /proc/self/mountinfo
mount -t tmpfs -o size=64m tmpfs /dev/shm
exec setpriv --no-new-privs --bounding-set=-all --inh-caps=-all -- "$@"
"#;

/// The namespaces: new user (so that an unprivileged user may make the
/// others), mount and network namespaces.
const UNSHARE: [&str; 5] = ["--user", "--map-root-user", "--mount", "--net", "--"];

/// A command that runs `program` confined (see the module), `writable`
/// being the one folder it may write into.
pub fn confined(program: &OsStr, writable: &Path) -> Command {
    match confinement() {
        Confinement::Full => {
            let mut command = Command::new("unshare");
            command.args(UNSHARE).args(["sh", "-c", SCRIPT, "sh"]);
            command.arg(writable).arg(program);
            command
        }
        Confinement::Network => {
            let mut command = Command::new("unshare");
            command.args(["--user", "--map-root-user", "--net", "--"]);
            command.arg(program);
            command
        }
        Confinement::None => Command::new(program),
    }
}

/// What this system allows, found once by trying.
pub fn confinement() -> Confinement {
    static FOUND: OnceLock<Confinement> = OnceLock::new();
    *FOUND.get_or_init(|| {
        if full_works() {
            Confinement::Full
        } else if succeeds(
            Command::new("unshare")
                .args(["--user", "--map-root-user", "--net"])
                .arg("true"),
        ) {
            Confinement::Network
        } else {
            Confinement::None
        }
    })
}

/// Does full confinement work: the writable folder writable, the rest not?
fn full_works() -> bool {
    let base = std::env::temp_dir().join(format!("raybook-confine-{}", std::process::id()));
    let (dir, outside) = (base.join("writable"), base.join("not"));
    if std::fs::create_dir_all(&dir).is_err() || std::fs::create_dir_all(&outside).is_err() {
        return false;
    }
    let test = format!(
        "touch '{}/ok' && ! touch '{}/no' 2>/dev/null",
        dir.display(),
        outside.display()
    );
    let mut command = Command::new("unshare");
    command.args(UNSHARE).args(["sh", "-c", SCRIPT, "sh"]);
    command.arg(&dir).args(["sh", "-c", &test]);
    let works = succeeds(&mut command) && dir.join("ok").exists();
    let _ = std::fs::remove_dir_all(&base);
    works
}

fn succeeds(command: &mut Command) -> bool {
    command
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a system that allows it (the CI machine does), a confined run
    /// writes into its folder and nowhere else, and cannot remount.
    #[test]
    fn a_confined_run_writes_only_into_its_folder() {
        if confinement() != Confinement::Full {
            eprintln!("no namespaces here: {:?}", confinement());
            return;
        }
        let (dir, outside) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
        let script = format!(
            "touch '{0}/ok'; touch '{1}/no'; mount -o remount,rw / ; touch '{1}/after'; exit 0",
            dir.path().display(),
            outside.path().display()
        );
        let mut command = confined(OsStr::new("sh"), dir.path());
        command.args(["-c", &script]);
        assert!(succeeds(&mut command));
        assert!(dir.path().join("ok").exists());
        assert!(!outside.path().join("no").exists() && !outside.path().join("after").exists());
    }
}
