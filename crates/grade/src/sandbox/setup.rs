//! How grading runs the students' commands: in the sandbox or not, and the
//! limits of a student's build folder, memory and processes, chosen once
//! when grading starts (`bwrap::start`) and handed to what needs them.

use crate::sandbox::cgroup::Parent;

/// How grading runs the students' commands.
#[derive(Debug, Clone)]
pub struct Setup {
    /// In bubblewrap (false: `--unsafe-no-sandbox`).
    pub sandboxed: bool,
    /// The size of a student's writable build folder, in bytes.
    pub disk: u64,
    /// The memory of a student's processes together, in bytes.
    pub memory: u64,
    /// The number of a student's processes (and threads) together.
    pub pids: u64,
    /// Where students' control groups are made, or why none can be.
    pub cgroups: Result<Parent, String>,
}

impl Setup {
    /// No sandbox: for what runs no student's code (a merge, unit tests).
    pub fn none() -> Setup {
        Setup {
            sandboxed: false,
            disk: 0,
            memory: 0,
            pids: 0,
            cgroups: Err("not started".to_owned()),
        }
    }

    /// What of it changes a student's result (the cache's key): the
    /// sandbox or not, and the limits; not where control groups live.
    pub fn key(&self) -> Setup {
        Setup {
            cgroups: Err(String::new()),
            ..*self
        }
    }
}
