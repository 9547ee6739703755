//! `raybook render --seed N`, end to end: the same seed gives the same
//! bytes on one thread and on two, another seed another picture, and no
//! seed the picture every render has always made.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The PNG bytes of the showcase at 48×36 with `args` (and `--quiet`).
fn render(dir: &Path, name: &str, args: &[&str]) -> Vec<u8> {
    let out: PathBuf = dir.join(format!("{name}.png"));
    let output = Command::new(env!("CARGO_BIN_EXE_raybook"))
        .args(["render", "--width", "48", "--height", "36", "--quiet"])
        .args(args)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    std::fs::read(&out).unwrap()
}

#[test]
fn the_same_seed_gives_the_same_bytes_at_1_and_2_threads_and_another_seed_another_picture() {
    let dir = tempfile::tempdir().unwrap();
    let dir = dir.path();
    for samples in ["1", "4"] {
        let seeded = |seed: &str, threads: &str| {
            let name = format!("s{samples}-seed{seed}-t{threads}");
            let args = ["--samples", samples, "--seed", seed, "--threads", threads];
            render(dir, &name, &args)
        };
        let one = seeded("1", "1");
        assert_eq!(
            one,
            seeded("1", "2"),
            "{samples} samples, seed 1: 1 and 2 threads"
        );
        assert_ne!(one, seeded("2", "1"), "{samples} samples: seeds 1 and 2");
        let unseeded = |threads| {
            let name = format!("s{samples}-t{threads}");
            render(dir, &name, &["--samples", samples, "--threads", threads])
        };
        assert_ne!(one, unseeded("1"), "{samples} samples: seed 1 and none");
        assert_eq!(unseeded("1"), unseeded("2"), "{samples} samples, no seed");
    }
}
