//! A student's build folder: their writable `target/`, a tmpfs of `--disk`'s
//! size that lives as long as their grading. Unprivileged, a tmpfs can be
//! mounted only in a mount namespace of one's own, which ends with its
//! last process: so a small process (`unshare --user --mount`, then `cat`
//! on a pipe that the grader holds) keeps it, each sandboxed command enters
//! it (`nsenter`) before bwrap builds its empty root around the folder,
//! and the grader reaches the folder through that process's root
//! (`/proc/PID/root`). The student's control group lives as long.

use std::ffi::CString;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use crate::sandbox::cgroup::Group;
use crate::sandbox::setup::Setup;

/// A student's writable build folder: a tmpfs of `--disk`'s size mounted
/// on it in a user and mount namespace of its own, which a small process
/// holds open for as long as the student is graded, and the student's
/// control group. Both end when it is dropped.
#[derive(Debug)]
pub struct BuildFolder {
    holder: Child,
    group: Option<Group>,
    /// The folder it is mounted on, and its size in bytes.
    dir: PathBuf,
    size: u64,
}

impl BuildFolder {
    /// Mounts the build folder on `dir` (an empty folder).
    pub fn new(dir: &Path, setup: &Setup) -> Result<BuildFolder, String> {
        let script = "mount -t tmpfs -o \"size=$2,mode=0755\" raybook-room \"$1\" \
                      && echo ready && exec cat";
        let mut holder = Command::new("unshare")
            .args([
                "--user",
                "--map-root-user",
                "--mount",
                "--",
                "sh",
                "-c",
                script,
                "sh",
            ])
            .arg(dir)
            .arg(setup.disk.max(1 << 20).to_string())
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot run unshare: {e}"))?;
        let mut line = String::new();
        let stdout = holder.stdout.take().expect("piped");
        let _ = BufReader::new(stdout).read_line(&mut line);
        if line.trim() != "ready" {
            let _ = holder.kill();
            let output = holder.wait_with_output().map_err(|e| e.to_string())?;
            return Err(format!(
                "cannot make a user and mount namespace (unshare --user --mount): {}",
                String::from_utf8_lossy(&output.stderr).trim()
            ));
        }
        let group = match &setup.cgroups {
            Ok(parent) => Some(parent.group(setup.memory, setup.pids)?),
            Err(_) => None,
        };
        let (dir, size) = (dir.to_owned(), setup.disk.max(1 << 20));
        Ok(BuildFolder {
            holder,
            group,
            dir,
            size,
        })
    }

    /// The holding process's id, whose namespaces a command enters.
    pub fn id(&self) -> u32 {
        self.holder.id()
    }

    /// Where the grader finds `path` (a path of the run) from outside:
    /// through the holder's root.
    pub fn outside(&self, path: &Path) -> PathBuf {
        let inside = path.strip_prefix("/").unwrap_or(path);
        Path::new("/proc")
            .join(self.holder.id().to_string())
            .join("root")
            .join(inside)
    }

    /// What the student's limits did: the memory limit reached, the build
    /// folder full (less than 1% of it free).
    pub fn notes(&self) -> Vec<String> {
        let mut notes = self.group.as_ref().map(Group::notes).unwrap_or_default();
        let free = free_bytes(&self.outside(&self.dir));
        if free.is_some_and(|free| free < self.size / 100) {
            notes.push(format!(
                "disk: the student's runs filled their build folder ({} MiB); \
                 writing more failed",
                self.size >> 20
            ));
        }
        notes
    }

    /// The group's `cgroup.procs` files.
    pub fn procs(&self) -> Vec<CString> {
        self.group.as_ref().map(Group::procs).unwrap_or_default()
    }
}

impl Drop for BuildFolder {
    fn drop(&mut self) {
        let _ = self.holder.kill();
        let _ = self.holder.wait();
    }
}

/// The free bytes of the file system at `dir`.
fn free_bytes(dir: &Path) -> Option<u64> {
    let name = CString::new(dir.as_os_str().as_encoded_bytes()).ok()?;
    // SAFETY: statvfs is plain data, filled by the call.
    let mut stat: libc::statvfs = unsafe { std::mem::zeroed() };
    // SAFETY: a valid C string and a pointer to the struct above.
    let done = unsafe { libc::statvfs(name.as_ptr(), &mut stat) };
    (done == 0).then(|| stat.f_bavail as u64 * stat.f_frsize as u64)
}
