//! A hostile student's code, from the grading tests' corpus
//! (`tests/hostile.rs`): run once from chapter 1's `at`, it tries at test
//! time what the sandbox must stop. The test writes real paths in place of
//! the `@…@` names. Every attempt is allowed to fail: its honest work (the
//! exercise's value) is what it returns.

use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Its own target folder, as the sandbox shows it.
const TARGET: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../target");

/// The attacks of `@KIND@`: "runtime" or "hogs".
pub fn attack() {
    if "@KIND@" == "runtime" {
        outlive();
        reach_sockets();
        overwrite_shared();
        leak_pictures();
    } else {
        fill_disk();
        fill_memory();
    }
}

/// A process that leaves the session, to outlive the run.
fn outlive() {
    let _ = quiet(Command::new("setsid").args(["sleep", "987654"])).spawn();
}

/// Unix sockets to a process outside: a path and an abstract name.
fn reach_sockets() {
    use std::os::linux::net::SocketAddrExt;
    use std::os::unix::net::{SocketAddr, UnixStream};
    if let Ok(mut stream) = UnixStream::connect("@SOCKET@") {
        let _ = stream.write_all(b"escaped");
    }
    if let Ok(address) = SocketAddr::from_abstract_name(b"@ABSTRACT@")
        && let Ok(mut stream) = UnixStream::connect_addr(&address)
    {
        let _ = stream.write_all(b"escaped");
    }
}

/// Overwrites in place the registry artefacts it finds: its own target's
/// (once hard links to the base build's and the teacher's), the base
/// build's and the teacher's by their absolute paths.
fn overwrite_shared() {
    let own = format!("{TARGET}/debug/deps");
    for dir in [own.as_str(), "@BASE_DEPS@", "@TEACHER_DEPS@"] {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let ours = ["libch0", "libworkbench", "libscene_files", "libtest_support"];
            let registry = name.ends_with(".rlib") && !ours.iter().any(|o| name.starts_with(o));
            if registry || name.starts_with("raybook-hostile-canary") {
                let file = std::fs::OpenOptions::new().write(true).open(entry.path());
                if let Ok(mut file) = file {
                    let _ = file.write_all(b"overwritten in place");
                }
            }
        }
    }
}

/// A symlink to a secret and a FIFO where the grader copies failure
/// pictures from.
fn leak_pictures() {
    let dir = format!("{TARGET}/snapshot-failures/01-rays");
    let _ = std::fs::create_dir_all(&dir);
    let _ = std::os::unix::fs::symlink("@SECRET@", format!("{dir}/leak.diff.png"));
    let _ = quiet(Command::new("mkfifo").arg(format!("{dir}/block.diff.png"))).status();
}

/// Six children that each grow until their own limit (`tail` of an
/// endless stream with no line break keeps it all): together far over the
/// student's memory. Waits until they end (at most two minutes).
fn fill_memory() {
    let mut tails: Vec<_> = (0..6)
        .filter_map(|_| quiet(Command::new("tail").arg("/dev/zero")).spawn().ok())
        .collect();
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(120)
        && tails.iter_mut().any(|t| matches!(t.try_wait(), Ok(None)))
    {
        std::thread::sleep(Duration::from_millis(100));
    }
    for tail in &mut tails {
        let _ = tail.kill();
        let _ = tail.wait();
    }
}

/// Files of 64 MiB, together over the student's disk, kept.
fn fill_disk() {
    let dir = format!("{TARGET}/hog");
    let _ = std::fs::create_dir_all(&dir);
    let chunk = vec![7u8; 1 << 20];
    'files: for i in 0..64 {
        let name = format!("{dir}/{}-{i}", std::process::id());
        let Ok(mut file) = std::fs::File::create(name) else {
            break;
        };
        for _ in 0..64 {
            if file.write_all(&chunk).is_err() {
                break 'files;
            }
        }
    }
}

fn quiet(command: &mut Command) -> &mut Command {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
}
