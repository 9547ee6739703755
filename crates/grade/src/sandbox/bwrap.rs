//! The sandbox of a student's build and tests: bubblewrap (`bwrap`).
//!
//! Why bubblewrap: it is maintained (by the Flatpak and GNOME people,
//! packaged by every distribution: Debian's `bubblewrap`), it is what
//! Flatpak runs every desktop application in, so its set-up is well
//! trodden; it needs no root (user namespaces let an unprivileged teacher
//! make every namespace it asks for); and it starts from an *empty* root,
//! into which only what is named is mounted, so that what we forget to
//! hide is absent rather than exposed. nsjail does the same with a larger
//! configuration language and is not packaged in Debian's main archive;
//! Landlock only restricts file access, without a PID or network
//! namespace, and needs a recent kernel.
//!
//! Each command of a student runs in a fresh `bwrap` with every namespace
//! of its own (`--unshare-all`: user, mount, PID, network, IPC, UTS,
//! cgroup; `--disable-userns`, so that nothing inside makes more), a new
//! session (no terminal to push keys into), `--die-with-parent`, and only
//! the variables `build/cargo.rs` names (`--clearenv`). Its root is empty but
//! for:
//! * the toolchain, read-only: `/usr` and the `/lib*` and `/bin` links,
//!   the few files of `/etc` a compiler and linker read, the rustup home,
//!   and the cargo home's `bin/`, registry sources and configuration (not
//!   its credentials);
//! * the student's copy (`class/submission.rs`), read-only: the tests, snapshots,
//!   sources and Cargo files that the grading uses cannot be written while
//!   the run lasts;
//! * the copy's `target/`, writable: a tmpfs of its own, of a fixed size
//!   (`--disk`), held by a small process per student (`sandbox/build_folder.rs`: a user and
//!   mount namespace made with `unshare`, whose tmpfs lives as long as the
//!   student's grading and is entered with `nsenter` for each command). The
//!   shared build artefacts are copies in it (`build/share.rs`), so nothing
//!   writable there is anyone else's;
//! * a new `/proc`, a minimal `/dev`, a small `/tmp` and a small `/dev/shm`.
//!   Every place a run may write has a size: bubblewrap's `/dev` is a tmpfs
//!   of its own, as large as half the machine's memory and writable, so it
//!   is remounted read-only once its devices and `/dev/shm` are in it (a
//!   device node still reads and writes as a device). Otherwise a run could
//!   put gigabytes there, beyond `--disk`, and, where no control group
//!   counts the pages, beyond `--memory` too.
//!
//! Other students' copies, the reference's sources, the teacher's files,
//! outputs and caches, the host's `/tmp` and `/run` (and their sockets) are
//! not there; there is no network, not even the host's abstract sockets.
//! In its PID namespace, every process of a command ends with it: when the
//! command ends, or is killed at its time limit, the namespace's first
//! process dies and the kernel kills the rest, `setsid` or not. The
//! student's memory and processes together are bounded by a control group
//! (`sandbox/cgroup.rs`) where one can be made.
//!
//! Where the sandbox cannot start (no `bwrap`, user namespaces forbidden),
//! grading refuses to start and says how to fix it. A teacher may pass
//! `--unsafe-no-sandbox` for a class they trust: the commands then run as
//! the teacher, and every output says so.

use std::ffi::{OsStr, OsString};
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::sandbox::build_folder::BuildFolder;
use crate::sandbox::cgroup::{self, Parent};
pub use crate::sandbox::setup::Setup;

/// What every output says of a student graded without the sandbox.
pub const UNSANDBOXED: &str = "graded WITHOUT the sandbox (--unsafe-no-sandbox): the \
     student's code ran as the teacher, with the teacher's files and network";

/// Chooses how the students' commands run, and checks that the sandbox
/// starts (an error says why not and how to fix it). Once per process.
pub fn start(sandboxed: bool, disk: u64, memory: u64, pids: u64) -> Result<Setup, String> {
    let cgroups = if sandboxed {
        Parent::find()
    } else {
        Err("no sandbox".to_owned())
    };
    let setup = Setup {
        sandboxed,
        disk,
        memory,
        pids,
        cgroups,
    };
    if setup.sandboxed {
        check(&setup).map_err(|why| {
            format!(
                "the students' sandbox cannot start: {why}\n\
                 To fix it: install bubblewrap (`sudo apt-get install bubblewrap`) and allow \
                 unprivileged user namespaces (`sudo sysctl kernel.unprivileged_userns_clone=1` \
                 on Debian; on Ubuntu 23.10 and later also \
                 `sudo sysctl kernel.apparmor_restrict_unprivileged_userns=0`; inside a \
                 container, allow the unshare and mount system calls). For a class you trust, \
                 `--unsafe-no-sandbox` grades without it, and every output says so."
            )
        })?;
    }
    Ok(setup)
}

/// Does a student's sandbox start here, and hold: its build folder
/// writable, its copy and the rest not?
fn check(setup: &Setup) -> Result<(), String> {
    let bwrap = find_program("bwrap").ok_or("bwrap is not installed (no `bwrap` on PATH)")?;
    let _ = bwrap;
    for tool in ["unshare", "nsenter"] {
        find_program(tool).ok_or(format!("`{tool}` (util-linux) is not on PATH"))?;
    }
    let dir = std::env::temp_dir().join(format!("raybook-sandbox-check-{}", std::process::id()));
    let copy = dir.join("copy");
    std::fs::create_dir_all(copy.join("target")).map_err(|e| e.to_string())?;
    std::fs::write(dir.join("beside"), "not in the sandbox").map_err(|e| e.to_string())?;
    let result = (|| {
        let build = BuildFolder::new(&copy.join("target"), setup)?;
        let script = "echo ok > target/ok && ! (echo no > copy-file) 2>/dev/null \
                      && ! (echo no > /dev/unbounded) 2>/dev/null && ! test -e ../beside";
        let mut command = in_bwrap(
            (&copy, &copy),
            (Some(&build), None),
            (OsStr::new("sh"), &["-c".into(), script.into()]),
            &[("PATH".into(), "/usr/bin:/bin".into())],
        );
        let out = command
            .stdin(Stdio::null())
            .output()
            .map_err(|e| format!("cannot run bwrap: {e}"))?;
        let wrote = std::fs::read_to_string(build.outside(&copy.join("target/ok")));
        match (out.status.success(), wrote) {
            (true, Ok(_)) => Ok(()),
            (ran, wrote) => Err(format!(
                "a trial run failed ({}{}): {}{}",
                out.status,
                if ran {
                    "; its file not found from outside"
                } else {
                    ""
                },
                String::from_utf8_lossy(&out.stderr).trim(),
                wrote.err().map(|e| format!(" ({e})")).unwrap_or_default()
            )),
        }
    })();
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// The first `name` on PATH.
fn find_program(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(name))
        .find(|p| p.is_file())
}

/// The command that runs `program` with `args` and only `env`, in the
/// folder `cwd` of `copy`: in the sandbox when grading is sandboxed, with
/// `build` its writable build folder (none: the whole copy is writable, as
/// for the reference's own base copy); else plainly.
pub fn confined(
    (copy, cwd): (&Path, &Path),
    (build, shown): (Option<&BuildFolder>, Option<(&Path, &Path)>),
    (program, args): (&OsStr, &[OsString]),
    (env, sandboxed): (&[(OsString, OsString)], bool),
) -> Command {
    if !sandboxed {
        let mut command = Command::new(program);
        command.args(args).env_clear().envs(env.iter().cloned());
        command.current_dir(cwd);
        return command;
    }
    in_bwrap((copy, cwd), (build, shown), (program, args), env)
}

/// [`confined`], in the sandbox: `shown` is a folder of the grader's shown
/// read-only at a path of the run (the student's probes).
fn in_bwrap(
    (copy, cwd): (&Path, &Path),
    (build, shown): (Option<&BuildFolder>, Option<(&Path, &Path)>),
    (program, args): (&OsStr, &[OsString]),
    env: &[(OsString, OsString)],
) -> Command {
    let mut command = match build {
        Some(build) => {
            let mut command = Command::new("nsenter");
            command.arg("--target").arg(build.id().to_string());
            command.args(["--user", "--mount", "--preserve-credentials", "--", "bwrap"]);
            command
        }
        None => Command::new("bwrap"),
    };
    command.args(bwrap_args(copy, build.is_some(), env));
    if let Some((folder, at)) = shown {
        command.arg("--ro-bind").arg(folder).arg(at);
    }
    command.arg("--chdir").arg(cwd);
    command.arg("--").arg(program).args(args);
    command.current_dir("/");
    // bwrap's own environment is nobody's business; the run's is --setenv.
    command.env_clear();
    if let Ok(path) = std::env::var("PATH") {
        command.env("PATH", path);
    }
    let procs = build.map(BuildFolder::procs).unwrap_or_default();
    if !procs.is_empty() {
        // SAFETY: only open, write and close (async-signal-safe) on
        // strings made before the fork.
        unsafe {
            command.pre_exec(move || cgroup::enter(&procs));
        }
    }
    command
}

/// The files of `/etc` a compiler, linker and shell read.
const ETC: [&str; 8] = [
    "alternatives",
    "ld.so.cache",
    "ld.so.conf",
    "ld.so.conf.d",
    "passwd",
    "group",
    "nsswitch.conf",
    "localtime",
];

/// The size of a run's `/tmp` and of its `/dev/shm`, in bytes (64 MiB):
/// its scratch room is its build folder's `scratch/` (`TMPDIR`).
const SCRATCH: &str = "67108864";

/// The parts of the cargo home a build reads (not `credentials.toml`).
const CARGO_HOME: [&str; 5] = ["bin", "registry", "git", "config.toml", "config"];

/// bwrap's arguments: the namespaces, the empty root and what is mounted
/// in it, the environment.
fn bwrap_args(copy: &Path, has_room: bool, env: &[(OsString, OsString)]) -> Vec<OsString> {
    let mut args: Vec<OsString> = [
        "--unshare-all",
        "--unshare-user",
        "--disable-userns",
        "--die-with-parent",
        "--new-session",
        "--clearenv",
        "--proc",
        "/proc",
        "--dev",
        "/dev",
        "--size",
        SCRATCH,
        "--tmpfs",
        "/dev/shm",
        "--remount-ro",
        "/dev",
        "--size",
        SCRATCH,
        "--tmpfs",
        "/tmp",
        "--ro-bind",
        "/usr",
        "/usr",
    ]
    .map(OsString::from)
    .to_vec();
    let mut bind = |how: &str, from: &Path, to: &Path| {
        args.extend([how.into(), from.into(), to.into()]);
    };
    for top in ["bin", "sbin", "lib", "lib32", "lib64", "libx32"] {
        let path = Path::new("/").join(top);
        match std::fs::read_link(&path) {
            Ok(to) => bind("--symlink", &to, &path),
            Err(_) if path.is_dir() => bind("--ro-bind", &path, &path),
            Err(_) => {}
        }
    }
    for file in ETC {
        let path = Path::new("/etc").join(file);
        bind("--ro-bind-try", &path, &path);
    }
    let homes = tool_homes();
    if let Some(cargo) = &homes.cargo {
        for part in CARGO_HOME {
            bind("--ro-bind-try", &cargo.join(part), &cargo.join(part));
        }
    }
    if let Some(rustup) = &homes.rustup {
        bind("--ro-bind-try", rustup, rustup);
    }
    if has_room {
        bind("--ro-bind", copy, copy);
        bind("--bind", &copy.join("target"), &copy.join("target"));
    } else {
        bind("--bind", copy, copy);
    }
    for (name, value) in env {
        args.extend(["--setenv".into(), name.clone(), value.clone()]);
    }
    args
}

/// Where rustup and cargo keep the toolchain and the registry: read-only
/// in the sandbox.
pub struct Homes {
    pub cargo: Option<PathBuf>,
    pub rustup: Option<PathBuf>,
}

/// The cargo and rustup homes (their variables, else under HOME).
pub fn tool_homes() -> Homes {
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let find = |var: &str, folder: &str| {
        std::env::var_os(var)
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(folder)))
    };
    Homes {
        cargo: find("CARGO_HOME", ".cargo"),
        rustup: find("RUSTUP_HOME", ".rustup"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The arguments name every namespace, an empty root with the copy
    /// read-only and its target writable, `/dev` read-only but for a small
    /// `/dev/shm`, and never the cargo home's credentials or the host's /tmp.
    #[test]
    fn the_sandbox_starts_empty_and_mounts_only_what_it_names() {
        let copy = Path::new("/grading/work/alice");
        let env = [("HOME".into(), "/grading/work/alice/target/scratch".into())];
        let args: Vec<String> = bwrap_args(copy, true, &env)
            .iter()
            .map(|a| a.to_string_lossy().into_owned())
            .collect();
        let has = |words: &[&str]| args.windows(words.len()).any(|w| w == words);
        for flag in [
            "--unshare-all",
            "--die-with-parent",
            "--new-session",
            "--clearenv",
        ] {
            assert!(has(&[flag]), "{flag}");
        }
        assert!(has(&[
            "--ro-bind",
            "/grading/work/alice",
            "/grading/work/alice"
        ]));
        let target = "/grading/work/alice/target";
        assert!(has(&["--bind", target, target]));
        assert!(!has(&[
            "--bind",
            "/grading/work/alice",
            "/grading/work/alice"
        ]));
        assert!(has(&["--size", "67108864", "--tmpfs", "/tmp"]));
        assert!(has(&["--size", "67108864", "--tmpfs", "/dev/shm"]));
        let dev = args.iter().position(|a| a == "--dev").unwrap();
        let shm = args.iter().position(|a| a == "/dev/shm").unwrap();
        let read_only = args.windows(2).position(|w| w == ["--remount-ro", "/dev"]);
        assert!(
            read_only.is_some_and(|at| dev < at && shm < at),
            "/dev read-only once its mounts are in it"
        );
        assert!(!args.iter().any(|a| a.contains("credentials")));
        assert!(!has(&["--bind", "/", "/"]) && !has(&["--ro-bind", "/", "/"]));
        assert!(has(&[
            "--setenv",
            "HOME",
            "/grading/work/alice/target/scratch"
        ]));
        // The reference's base copy (no build folder of its own) is writable whole.
        let base: Vec<OsString> = bwrap_args(copy, false, &[]);
        let base: Vec<&OsStr> = base.iter().map(OsString::as_os_str).collect();
        let bind = [OsStr::new("--bind"), copy.as_os_str(), copy.as_os_str()];
        assert!(base.windows(3).any(|w| w == bind));
    }
}
