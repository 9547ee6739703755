//! Running a student's build and tests so that they cannot take the
//! grading run down with them: in a process group of their own (bwrap's,
//! whose sandbox dies with it: `--die-with-parent` and its PID namespace
//! end every process inside, `setsid` or not), killed whole at the time
//! limit; with limits on each process's memory (address space), on the
//! size of a file and on core dumps, set with `setrlimit` in the child
//! before it starts; with a cap on what they print. (The small
//! environment is `build/cargo.rs`'s; the sandbox, the student's control group
//! and size-limited build folder, `sandbox/bwrap.rs`'s.)
//!
//! What the design still trusts is said plainly in `lib.rs`.

use std::io::Read;
use std::os::unix::process::CommandExt;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::{Arc, Mutex, OnceLock, mpsc};
use std::time::{Duration, Instant};

/// The limits a run is held to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock time before the whole process group is killed.
    pub time: Duration,
    /// Address space per process, in bytes (0: no limit).
    pub memory: u64,
    /// What the run may print (stdout and stderr together), in bytes.
    pub output: usize,
}

/// The largest file a run may write: a test that writes gigabytes to a file
/// gets SIGXFSZ instead of filling the disk.
const FILE_SIZE: u64 = 2 << 30;

/// How a run ended.
#[derive(Debug, Clone, Default)]
pub struct Ran {
    /// What it printed, stdout and stderr interleaved, up to the cap.
    pub text: String,
    /// Did the command exit with status 0?
    pub success: bool,
    /// Killed at the time limit.
    pub timed_out: bool,
    /// Killed for printing more than the cap.
    pub output_capped: bool,
    /// The wall-clock time it took.
    pub seconds: f64,
}

/// Runs `command` under `limits`: see the module's documentation. An error
/// only if it cannot be started.
pub fn run(mut command: Command, limits: &Limits) -> Result<Ran, String> {
    let (reader, writer) = std::io::pipe().map_err(|e| format!("cannot make a pipe: {e}"))?;
    let writer2 = writer
        .try_clone()
        .map_err(|e| format!("cannot make a pipe: {e}"))?;
    command
        .stdin(Stdio::null())
        .stdout(writer)
        .stderr(writer2)
        .process_group(0);
    let memory = limits.memory;
    // SAFETY: between fork and exec, only setrlimit, which is
    // async-signal-safe, and no allocation.
    unsafe {
        command.pre_exec(move || set_limits(memory));
    }
    let start = Instant::now();
    let mut child = command
        .spawn()
        .map_err(|e| format!("cannot run {:?}: {e}", command.get_program()))?;
    // The Command holds the pipe's writing ends: drop it, so that the
    // reader sees the end of the output when the children are gone.
    drop(command);
    let group = child.id() as libc::pid_t;
    let slot = Running::register(group);
    let capped = Arc::new(AtomicBool::new(false));
    let buffer = Arc::new(Mutex::new(Vec::new()));
    let done = read_capped(reader, group, limits.output, &buffer, &capped);
    let deadline = start + limits.time;
    let mut timed_out = false;
    while !has_exited(group) {
        if Instant::now() >= deadline {
            timed_out = true;
            kill_group(group);
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    // The leader is a zombie still, so its group id cannot have been
    // reused: end whatever it left running, then reap it.
    kill_group(group);
    let status = child.wait().map_err(|e| format!("cannot wait: {e}"));
    drop(slot);
    let status = status?;
    // A grandchild that left the group may hold the pipe open: wait a
    // little for the rest of the output, then go on without it.
    let _ = done.recv_timeout(Duration::from_secs(5));
    let bytes = buffer.lock().map(|b| b.clone()).unwrap_or_default();
    Ok(Ran {
        text: String::from_utf8_lossy(&bytes).into_owned(),
        success: status.success() && !timed_out,
        timed_out,
        output_capped: capped.load(Ordering::SeqCst),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The process groups running now, so that a grading run interrupted by
/// Ctrl-C (which reaches only the terminal's foreground group, not these)
/// or killed with SIGTERM or SIGHUP ends them too, instead of leaving a
/// student's endless loop running.
static GROUPS: [AtomicI32; 256] = [const { AtomicI32::new(0) }; 256];

/// A group's place in [`GROUPS`], freed when dropped.
struct Running(Option<usize>);

impl Running {
    /// Notes a running group (and, the first time, installs the handler).
    fn register(group: libc::pid_t) -> Running {
        static HANDLER: OnceLock<()> = OnceLock::new();
        HANDLER.get_or_init(|| {
            for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
                // SAFETY: the handler only reads atomics and calls kill,
                // signal and raise, which are async-signal-safe.
                unsafe {
                    libc::signal(
                        signal,
                        end_groups as extern "C" fn(libc::c_int) as libc::sighandler_t,
                    );
                }
            }
        });
        let free = GROUPS.iter().position(|g| {
            g.compare_exchange(0, group, Ordering::SeqCst, Ordering::SeqCst)
                .is_ok()
        });
        Running(free)
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        if let Some(slot) = self.0 {
            GROUPS[slot].store(0, Ordering::SeqCst);
        }
    }
}

/// On SIGINT, SIGTERM or SIGHUP: kills every running group, then dies of
/// the signal as it would have.
extern "C" fn end_groups(signal: libc::c_int) {
    for group in &GROUPS {
        let group = group.load(Ordering::SeqCst);
        if group != 0 {
            kill_group(group);
        }
    }
    // SAFETY: async-signal-safe calls, restoring the default action.
    unsafe {
        libc::signal(signal, libc::SIG_DFL);
        libc::raise(signal);
    }
}

/// In the child, before exec: the memory limit, the file size limit, and
/// no core dumps (a stack overflow aborts).
fn set_limits(memory: u64) -> std::io::Result<()> {
    let set = |resource, value: u64| {
        let limit = libc::rlimit {
            rlim_cur: value as libc::rlim_t,
            rlim_max: value as libc::rlim_t,
        };
        // SAFETY: setrlimit reads the struct we pass.
        if unsafe { libc::setrlimit(resource, &limit) } != 0 {
            return Err(std::io::Error::last_os_error());
        }
        Ok(())
    };
    if memory > 0 {
        set(libc::RLIMIT_AS, memory)?;
    }
    set(libc::RLIMIT_FSIZE, FILE_SIZE)?;
    set(libc::RLIMIT_CORE, 0)
}

/// Reads the pipe on a thread into `buffer`, up to `cap` bytes; past it,
/// kills the group and drains the rest. The receiver hears when the pipe
/// is closed.
fn read_capped(
    mut reader: std::io::PipeReader,
    group: libc::pid_t,
    cap: usize,
    buffer: &Arc<Mutex<Vec<u8>>>,
    capped: &Arc<AtomicBool>,
) -> mpsc::Receiver<()> {
    let (tx, rx) = mpsc::channel();
    let (buffer, capped) = (Arc::clone(buffer), Arc::clone(capped));
    std::thread::spawn(move || {
        let mut chunk = [0u8; 64 * 1024];
        while let Ok(n) = reader.read(&mut chunk) {
            if n == 0 {
                break;
            }
            let Ok(mut kept) = buffer.lock() else { break };
            let room = cap.saturating_sub(kept.len());
            kept.extend_from_slice(&chunk[..n.min(room)]);
            if n > room && !capped.swap(true, Ordering::SeqCst) {
                kill_group(group);
            }
        }
        let _ = tx.send(());
    });
    rx
}

/// Has the process `pid` exited? It is left a zombie (not reaped), so that
/// its id, and its group's, stay reserved.
fn has_exited(pid: libc::pid_t) -> bool {
    // SAFETY: siginfo_t is plain data; waitid fills it.
    let mut info: libc::siginfo_t = unsafe { std::mem::zeroed() };
    let flags = libc::WEXITED | libc::WNOHANG | libc::WNOWAIT;
    // SAFETY: a valid pointer to the struct above.
    let result = unsafe { libc::waitid(libc::P_PID, pid as libc::id_t, &mut info, flags) };
    // SAFETY: si_pid is set when a child has changed state, 0 otherwise.
    result != 0 || unsafe { info.si_pid() } != 0
}

/// Sends SIGKILL to every process of the group.
fn kill_group(group: libc::pid_t) {
    // SAFETY: kill has no memory effects; a group that is gone is ESRCH.
    unsafe {
        libc::kill(-group, libc::SIGKILL);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn limits(seconds: u64) -> Limits {
        Limits {
            time: Duration::from_secs(seconds),
            memory: 1 << 30,
            output: 1 << 20,
        }
    }

    fn sh(script: &str) -> Command {
        let mut command = Command::new("sh");
        command.args(["-c", script]);
        command
    }

    #[test]
    fn output_and_status_are_kept() {
        let ran = run(sh("echo out; echo err >&2; exit 3"), &limits(10)).unwrap();
        assert_eq!(ran.text, "out\nerr\n");
        assert!(!ran.success && !ran.timed_out && !ran.output_capped);
    }

    #[test]
    fn an_endless_loop_and_its_children_are_killed_at_the_limit() {
        // The background sleep holds the pipe open: killing only the shell
        // would leave the run waiting for it.
        let ran = run(sh("sleep 100 & while :; do :; done"), &limits(1)).unwrap();
        assert!(ran.timed_out && !ran.success);
        assert!(ran.seconds < 8.0, "took {} s", ran.seconds);
    }

    #[test]
    fn a_flood_of_output_is_cut_at_the_cap() {
        let ran = run(sh("yes flood"), &limits(30)).unwrap();
        assert!(ran.output_capped && !ran.timed_out);
        assert_eq!(ran.text.len(), 1 << 20);
    }

    #[test]
    fn the_memory_and_file_limits_are_set_in_the_child() {
        let ran = run(sh("ulimit -v; ulimit -f; ulimit -c"), &limits(10)).unwrap();
        // ulimit reports kibibytes and 512-byte blocks.
        let expected = format!("{}\n{}\n0\n", (1 << 30) / 1024, FILE_SIZE / 512);
        assert_eq!(ran.text, expected);
    }
}
