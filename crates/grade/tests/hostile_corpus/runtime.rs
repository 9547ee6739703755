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

/// The attacks of `@KIND@`: "runtime", "hogs", "swapper", "panicker",
/// "pictures" or "flood".
pub fn attack() {
    match "@KIND@" {
        "runtime" => {
            outlive();
            reach_sockets();
            overwrite_shared();
            leak_pictures();
        }
        "hogs" => {
            fill_disk();
            fill_memory();
        }
        "swapper" => {
            swap_for_links();
            if in_probe() {
                forge_record();
            }
        }
        "panicker" if in_probe() => {
            let args: Vec<String> = std::env::args().collect();
            // Its arguments in a name that a look through its build
            // folder would report.
            let seed = args.iter().skip_while(|a| *a != "--seed").nth(1);
            let name = format!("{TARGET}/seed-{}", seed.map_or("", |s| s.as_str()));
            let _ = std::os::unix::fs::symlink("nowhere", name);
            panic!("the probe's arguments: {args:?}");
        }
        "pictures" if !in_probe() => many_pictures(),
        "flood" if !in_probe() => made_up_failures(),
        "panicker" => {
            let dir = format!("{TARGET}/snapshot-failures/01-rays");
            let _ = std::fs::create_dir_all(&dir);
            let _ = std::fs::write(format!("{dir}/\u{1b}[2J\rforged.diff.png"), b"x");
        }
        _ => {}
    }
}

/// Is this the grader's probe (its name), not a test?
fn in_probe() -> bool {
    std::env::args().any(|a| a == "--seed")
}

/// Folders the grader once read by path swapped for links: its probe's
/// output folder for the base copy's (where the reference's values were),
/// and its failure pictures' folder for a teacher's folder of pictures.
fn swap_for_links() {
    let probe = format!("{TARGET}/probe");
    let _ = std::fs::remove_dir_all(&probe);
    let _ = std::os::unix::fs::symlink("@BASE_PROBE@", &probe);
    let failures = format!("{TARGET}/snapshot-failures");
    let _ = std::fs::create_dir_all(&failures);
    let ours = format!("{failures}/01-rays");
    let _ = std::fs::remove_dir_all(&ours);
    let _ = std::os::unix::fs::symlink("@TEACHER_PICTURES@", &ours);
}

/// A record of its own on the grader's pipe (descriptor 3), in the
/// probe's format, with the seed and exercise it was given and values of
/// its making; then it ends the probe before the real record is written.
fn forge_record() {
    use std::os::fd::FromRawFd;
    let args: Vec<String> = std::env::args().collect();
    let after = |flag: &str| {
        let at = args.iter().position(|a| a == flag)?;
        args.get(at + 1).cloned()
    };
    let seed = after("--seed").unwrap_or_default();
    let id = after("--exercise").unwrap_or_default();
    let cases: Vec<String> = (0..24)
        .map(|i| format!("{{\"input\":\"case {i}\",\"value\":[0.5,0.5,0.5]}}"))
        .collect();
    let record = format!(
        "{{\"format\":\"raybook-probe-1\",\"seed\":{seed},\"exercises\":[{{\"id\":\"{id}\",\
         \"tolerance\":1e9,\"cases\":[{}]}}],\"scenes\":[]}}",
        cases.join(",")
    );
    // SAFETY: descriptor 3 is the grader's pipe in the probe; if it is not
    // open, the write fails and nothing else is touched.
    let mut pipe = unsafe { std::fs::File::from_raw_fd(3) };
    let _ = pipe.write_all(record.as_bytes());
    std::process::exit(0);
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

/// Forty failure pictures of 4 MiB each (160 MiB, more than the 32 the
/// grader takes): what is kept stays on the teacher's disk.
fn many_pictures() {
    let dir = format!("{TARGET}/snapshot-failures/01-rays");
    let _ = std::fs::create_dir_all(&dir);
    let picture = vec![7u8; 4 << 20];
    for i in 0..40 {
        let _ = std::fs::write(format!("{dir}/{i:02}.diff.png"), &picture);
    }
}

/// 12 MiB of made-up failures, each with its panic, past libtest's
/// capture: what the grader reads of a test run, a quarter of a million
/// names.
fn made_up_failures() {
    let mut text = String::new();
    let mut i = 0;
    while text.len() < 12 << 20 {
        text += &format!("thread 't{i}' panicked at x:1:1:\nm\ntest f{i} ... FAILED\n");
        i += 1;
    }
    let _ = std::io::stdout().write_all(text.as_bytes());
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
