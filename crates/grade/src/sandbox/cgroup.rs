//! One control group per student, so that their processes together, not
//! each alone, are held to the memory and process limits.
//!
//! On this machine's cgroup v1 (`/sys/fs/cgroup/memory`, `/sys/fs/cgroup/pids`)
//! a student's group is made under the grader's own group of each
//! controller (so that whatever bounds the grader still bounds them):
//! `memory.limit_in_bytes` bounds the memory of all their processes
//! together, the pages of their size-limited build folder included, and
//! `pids.max` the number of their processes and threads. Each sandboxed
//! command enters the group before it starts (`pre_exec`), and its
//! children inherit it. A group can be made where the grader may write
//! into its own group's folder: as root, or where an administrator has
//! delegated it.
//!
//! On a cgroup-v2 system (`/sys/fs/cgroup/cgroup.controllers`) an
//! unprivileged user's subtree is delegated by systemd: run the whole
//! grading in a scope of its own,
//! `systemd-run --user --scope -p MemoryMax=16G -p TasksMax=2048 cargo run -p grade -- CLASS`,
//! which bounds every student's run together; a per-student group needs a
//! delegated subtree whose controllers are enabled (`cgroup.subtree_control`),
//! which this module does not set up. Where no group can be made, grading
//! says so and each process is bounded alone (`RLIMIT_AS`), and the number
//! of processes by the time limit only.

use std::ffi::CString;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The controllers and the files that bound them.
const CONTROLLERS: [(&str, &str); 2] = [("memory", "memory.limit_in_bytes"), ("pids", "pids.max")];

/// Where the students' groups are made: the grader's own group of each
/// controller, found from `/proc/self/cgroup`.
#[derive(Debug, Clone)]
pub struct Parent {
    folders: Vec<PathBuf>,
}

impl Parent {
    /// The grader's own v1 groups of `memory` and `pids`, if a group can be
    /// made in each; else why not.
    pub fn find() -> Result<Parent, String> {
        if Path::new("/sys/fs/cgroup/cgroup.controllers").exists() {
            return Err(
                "this system has cgroup v2 only: run the grading in a scope of its \
                 own (systemd-run --user --scope -p MemoryMax=… -p TasksMax=…)"
                    .to_owned(),
            );
        }
        let own = std::fs::read_to_string("/proc/self/cgroup").map_err(|e| e.to_string())?;
        let mut folders = Vec::new();
        for (controller, _) in CONTROLLERS {
            let path = own.lines().find_map(|line| {
                let mut parts = line.splitn(3, ':');
                let (_, names, path) = (parts.next()?, parts.next()?, parts.next()?);
                names.split(',').any(|n| n == controller).then_some(path)
            });
            let Some(path) = path else {
                return Err(format!("no cgroup v1 {controller} controller"));
            };
            let folder = Path::new("/sys/fs/cgroup")
                .join(controller)
                .join(path.trim_start_matches('/'));
            let probe = folder.join(format!("raybook-probe-{}", std::process::id()));
            std::fs::create_dir(&probe)
                .and_then(|()| std::fs::remove_dir(&probe))
                .map_err(|e| format!("cannot make a group in {}: {e}", folder.display()))?;
            folders.push(folder);
        }
        Ok(Parent { folders })
    }

    /// A new group for one student, bounded to `memory` bytes and `pids`
    /// processes.
    pub fn group(&self, memory: u64, pids: u64) -> Result<Group, String> {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let name = format!(
            "raybook-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::SeqCst)
        );
        let mut group = Group {
            folders: Vec::new(),
            procs: Vec::new(),
        };
        for (folder, ((_, file), value)) in self
            .folders
            .iter()
            .zip(CONTROLLERS.iter().zip([memory, pids]))
        {
            let dir = folder.join(&name);
            std::fs::create_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
            group.folders.push(dir.clone());
            std::fs::write(dir.join(file), value.to_string())
                .map_err(|e| format!("{}: {e}", dir.join(file).display()))?;
            let procs = dir.join("cgroup.procs").into_os_string();
            group
                .procs
                .push(CString::new(procs.into_encoded_bytes()).map_err(|e| e.to_string())?);
        }
        Ok(group)
    }
}

/// A student's group; removed (its processes killed) when dropped.
#[derive(Debug)]
pub struct Group {
    folders: Vec<PathBuf>,
    procs: Vec<CString>,
}

impl Group {
    /// The `cgroup.procs` files to write `0` into, in the child before exec.
    pub fn procs(&self) -> Vec<CString> {
        self.procs.clone()
    }

    /// What the limits did, for the teacher: processes the kernel ended
    /// when the student's processes together reached the memory limit.
    pub fn notes(&self) -> Vec<String> {
        let Some(memory) = self.folders.first() else {
            return Vec::new();
        };
        let read = |file: &str| std::fs::read_to_string(memory.join(file)).unwrap_or_default();
        let killed = read("memory.oom_control")
            .lines()
            .find_map(|l| l.strip_prefix("oom_kill ")?.trim().parse::<u64>().ok())
            .unwrap_or(0);
        let limit = read("memory.limit_in_bytes")
            .trim()
            .parse::<u64>()
            .unwrap_or(0);
        match killed {
            0 => Vec::new(),
            n => vec![format!(
                "memory: the student's processes together reached their limit of {} MiB; \
                 the kernel ended {n} of them",
                limit >> 20
            )],
        }
    }
}

impl Drop for Group {
    fn drop(&mut self) {
        for dir in &self.folders {
            for _ in 0..50 {
                let procs = std::fs::read_to_string(dir.join("cgroup.procs")).unwrap_or_default();
                for pid in procs.lines().filter_map(|p| p.trim().parse::<i32>().ok()) {
                    // SAFETY: kill has no memory effects.
                    unsafe {
                        libc::kill(pid, libc::SIGKILL);
                    }
                }
                if std::fs::remove_dir(dir).is_ok() {
                    break;
                }
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
        }
    }
}

/// In the child, before exec: enters the group (writes `0`, "this
/// process", into each `cgroup.procs`). Only open, write and close, which
/// are async-signal-safe, on strings made before the fork.
pub fn enter(procs: &[CString]) -> std::io::Result<()> {
    for path in procs {
        // SAFETY: a valid C string; the descriptor is closed below.
        let fd = unsafe { libc::open(path.as_ptr(), libc::O_WRONLY | libc::O_CLOEXEC) };
        if fd < 0 {
            return Err(std::io::Error::last_os_error());
        }
        // SAFETY: writes one byte from a static buffer.
        let written = unsafe { libc::write(fd, b"0".as_ptr().cast(), 1) };
        // SAFETY: our own descriptor.
        unsafe { libc::close(fd) };
        if written != 1 {
            return Err(std::io::Error::last_os_error());
        }
    }
    Ok(())
}
