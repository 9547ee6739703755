//! A student's folder read: what is refused, what is flagged, what is
//! listed (no grading).

use super::*;

fn record(version: &str, commit: &str) -> Record {
    Record {
        version: version.to_owned(),
        commit: commit.to_owned(),
        modified: false,
    }
}

#[test]
fn what_is_not_a_handout_of_this_version_is_refused_with_its_reason() {
    let class = tempfile::tempdir().unwrap();
    let root = class.path();
    let reference = record("0.1.0", "abc");
    let refused = |name: &str| check(root, name, (&reference, true)).unwrap_err();
    std::fs::create_dir(root.join("empty")).unwrap();
    assert!(refused("empty").contains("an empty folder"));
    std::fs::write(root.join("notes.txt"), "x").unwrap();
    assert!(refused("notes.txt").contains("a file, not a folder"));
    std::os::unix::fs::symlink("/etc", root.join("away")).unwrap();
    assert!(refused("away").contains("leading outside the class folder"));
    std::os::unix::fs::symlink(root.join("empty"), root.join("alias")).unwrap();
    assert!(refused("alias").contains("graded under its own name"));
    std::fs::create_dir_all(root.join("essay")).unwrap();
    std::fs::write(root.join("essay/essay.md"), "x").unwrap();
    assert!(refused("essay").contains("not a raybook handout"));

    let handout = root.join("handout");
    std::fs::create_dir_all(handout.join("chapters")).unwrap();
    std::fs::write(handout.join("Cargo.toml"), "").unwrap();
    std::fs::write(handout.join("chapters/chapters.toml"), "").unwrap();
    let graded = check(root, "handout", (&reference, true)).unwrap();
    assert!(
        graded.warnings[0].contains("no .raybook-handout.toml"),
        "{:?}",
        graded.warnings
    );
    record("0.1.0", "def").write(&handout).unwrap();
    let graded = check(root, "handout", (&reference, true)).unwrap();
    assert!(graded.warnings[0].contains("made from raybook 0.1.0 @ def"));
    record("0.1.0", "abc").write(&handout).unwrap();
    assert!(
        check(root, "handout", (&reference, true))
            .unwrap()
            .warnings
            .is_empty()
    );
    record("0.2.0", "abc").write(&handout).unwrap();
    assert!(refused("handout").contains("a handout of raybook 0.2.0"));
}

#[test]
fn tests_pictures_and_cargo_files_are_protected_and_a_readme_is_not() {
    for protected in [
        "chapters/02-hits/tests/chapter02/spheres.rs",
        "snapshots/01-rays/default.snap.png",
        "chapters/chapters.toml",
        "Cargo.lock",
        "chapters/01-rays/Cargo.toml",
        "chapters/01-rays/build.rs",
        ".cargo/config.toml",
        "chapters/01-rays/.cargo/config",
    ] {
        assert!(is_protected(Path::new(protected)), "{protected}");
    }
    assert!(!is_protected(Path::new("chapters/01-rays/README.md")));
    assert!(!is_protected(Path::new("crates/workbench/src/snapshot.rs")));
}

#[test]
fn the_digest_sees_every_byte_and_is_the_same_twice() {
    let digest = |text: &str| {
        let mut d = Digest::default();
        text.hash(&mut d);
        d.hex()
    };
    assert_eq!(digest("abc"), digest("abc"));
    assert_ne!(digest("abc"), digest("abd"));
    assert_eq!(digest("abc").len(), 32);
}

#[test]
fn files_are_listed_without_following_symlinks_or_entering_ignored_folders() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::create_dir_all(root.join("chapters/01-rays/src")).unwrap();
    std::fs::create_dir_all(root.join("target/debug")).unwrap();
    std::fs::write(root.join("chapters/01-rays/src/lib.rs"), "fn f() {}").unwrap();
    std::fs::write(root.join("target/debug/x"), "built").unwrap();
    std::os::unix::fs::symlink("/etc", root.join("chapters/etc")).unwrap();
    std::fs::write(root.join("Cargo.toml"), "").unwrap();
    std::fs::write(root.join("chapters/chapters.toml"), "").unwrap();
    let mut submission = check(
        root.parent().unwrap(),
        &name_of(root),
        (&record("0.1.0", "abc"), true),
    )
    .unwrap();
    let listed = files(&mut submission, &ignore_rules(Path::new("/nonexistent"))).unwrap();
    let expected = BTreeMap::from([
        (PathBuf::from("Cargo.toml"), Entry::File(0)),
        (PathBuf::from("chapters/01-rays/src/lib.rs"), Entry::File(9)),
        (PathBuf::from("chapters/chapters.toml"), Entry::File(0)),
        (PathBuf::from("chapters/etc"), Entry::Link),
    ]);
    assert_eq!(listed, expected);
}

fn name_of(dir: &Path) -> String {
    dir.file_name().unwrap().to_string_lossy().into_owned()
}

/// A handout whose record is a link (to a secret, to the terminal, to
/// an endless device) is graded, flagged, and the record never quoted
/// or waited for; an oversized file and a FIFO are flagged, not read.
#[test]
fn a_record_or_file_that_is_not_a_plain_file_is_flagged_never_read() {
    let class = tempfile::tempdir().unwrap();
    let reference = record("0.1.0", "abc");
    let secret = class.path().join("secret");
    std::fs::write(&secret, "version = \"top secret\"").unwrap();
    for (name, to) in [
        ("passwd", secret.as_path()),
        ("stdin", Path::new("/dev/stdin")),
        ("zero", Path::new("/dev/zero")),
    ] {
        let dir = class.path().join(name);
        std::fs::create_dir_all(dir.join("chapters/01-rays/src")).unwrap();
        std::fs::write(dir.join("Cargo.toml"), "").unwrap();
        std::fs::write(dir.join("chapters/chapters.toml"), "").unwrap();
        std::os::unix::fs::symlink(to, dir.join(RECORD_FILE)).unwrap();
        let start = Instant::now();
        let submission = check(class.path(), name, (&reference, true)).unwrap();
        assert!(start.elapsed() < Duration::from_secs(5), "{name}: waited");
        let flag = submission.flags.join("\n");
        assert!(
            flag.contains("a symlink") && !flag.contains("top secret"),
            "{flag}"
        );
    }
    let dir = class.path().join("zero");
    let big = std::fs::File::create(dir.join("chapters/01-rays/src/big.bin")).unwrap();
    big.set_len(1 << 30).unwrap();
    let fifo = dir.join("chapters/01-rays/src/pipe.rs");
    let name = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid C string.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
    let mut submission = check(class.path(), "zero", (&reference, true)).unwrap();
    let listed = files(&mut submission, &ignore_rules(Path::new("/nonexistent"))).unwrap();
    assert!(!listed.contains_key(Path::new("chapters/01-rays/src/big.bin")));
    assert_eq!(
        listed[Path::new("chapters/01-rays/src/pipe.rs")],
        Entry::Other("a FIFO")
    );
    let flags = submission.flags.join("\n");
    assert!(
        flags.contains("oversized file chapters/01-rays/src/big.bin"),
        "{flags}"
    );
    assert!(
        hash_files(&submission, &listed).is_ok(),
        "the FIFO is never opened"
    );
}
