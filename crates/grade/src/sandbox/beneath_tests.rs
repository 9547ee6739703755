//! Reading beneath a folder: links anywhere on the way, kinds, sizes,
//! times, walks, and the one-line rule for names.
use super::*;
use std::time::Duration;

fn soon() -> Instant {
    Instant::now() + Duration::from_secs(10)
}

/// Every check twice: with `openat2`, and one part at a time.
fn both(path: &Path, check: impl Fn(Folder)) {
    check(Folder::open(path).unwrap());
    check(Folder::open(path).unwrap().by_parts());
}

#[test]
fn a_link_anywhere_on_the_way_is_refused_and_a_file_beneath_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let (root, secret) = (dir.path().join("room"), dir.path().join("teacher"));
    std::fs::create_dir_all(root.join("probe")).unwrap();
    std::fs::create_dir_all(&secret).unwrap();
    std::fs::write(secret.join("x.json"), "the reference's").unwrap();
    std::fs::write(root.join("probe/own.json"), "mine").unwrap();
    std::os::unix::fs::symlink(&secret, root.join("swapped")).unwrap();
    std::os::unix::fs::symlink(secret.join("x.json"), root.join("probe/last.json")).unwrap();
    both(&root, |room| {
        let read = |p: &str| room.read(Path::new(p), 100, soon());
        assert_eq!(read("probe/own.json").unwrap(), b"mine");
        assert_eq!(read("swapped/x.json"), Err(Refused::Link), "a middle link");
        assert_eq!(read("probe/last.json"), Err(Refused::Link), "a last link");
        assert_eq!(read("../teacher/x.json"), Err(Refused::BadName));
        assert_eq!(read("/etc/passwd"), Err(Refused::BadName));
        assert_eq!(read("probe/none"), Err(Refused::Missing));
        assert_eq!(
            room.folder(Path::new("swapped")).unwrap_err(),
            Refused::Link
        );
        assert_eq!(
            room.folder(Path::new("probe/own.json")).unwrap_err(),
            Refused::NotAFolder
        );
        assert_eq!(read("probe/own.json").unwrap(), b"mine");
    });
}

#[test]
fn only_a_regular_file_of_the_size_asked_is_read_and_a_fifo_never_blocks() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("big"), vec![1u8; 1000]).unwrap();
    let fifo = dir.path().join("fifo");
    let name = std::ffi::CString::new(fifo.as_os_str().as_bytes()).unwrap();
    // SAFETY: a valid C string.
    assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    both(dir.path(), |folder| {
        let read = |p: &str, most| folder.read(Path::new(p), most, soon());
        assert_eq!(read("big", 999), Err(Refused::TooLarge(1000)));
        assert_eq!(read("big", 1000).unwrap().len(), 1000);
        let start = Instant::now();
        assert_eq!(read("fifo", 10), Err(Refused::Kind("a FIFO")));
        assert!(start.elapsed() < Duration::from_secs(5));
        assert_eq!(read("sub", 10), Err(Refused::Kind("a folder")));
        let past = Instant::now() - Duration::from_millis(1);
        assert_eq!(
            folder.read(Path::new("big"), 1000, past),
            Err(Refused::TooSlow)
        );
    });
}

#[test]
fn a_walk_lists_links_and_fifos_without_entering_or_following_them() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::create_dir_all(root.join("a/b")).unwrap();
    std::fs::write(root.join("a/b/f.rs"), "x").unwrap();
    std::os::unix::fs::symlink("/etc", root.join("a/etc")).unwrap();
    std::fs::create_dir_all(root.join("skipped")).unwrap();
    std::fs::write(root.join("skipped/g"), "y").unwrap();
    let folder = Folder::open(root).unwrap();
    let skip = |p: &Path, _: bool| p == Path::new("skipped");
    let walked = folder.walk(&skip, 100).unwrap();
    assert_eq!(
        walked,
        vec![
            (PathBuf::from("a/b/f.rs"), Kind::File(1)),
            (PathBuf::from("a/etc"), Kind::Link),
        ]
    );
    assert!(folder.walk(&|_, _| false, 1).is_err(), "the cap");
    assert_eq!(folder.kind(Path::new("a/etc")), Ok(Kind::Link));
}

#[test]
fn control_and_bidirectional_characters_never_reach_a_line() {
    assert_eq!(clean_line("a\nb\r\u{1b}[2J\u{202E}c"), "a?b??[2J?c");
    assert!(clean_name("default"));
    assert!(!clean_name("de\u{1b}fault") && !clean_name("x\u{2067}"));
    assert_eq!(clean_line("\t=SUM(1)"), "\t=SUM(1)", "a tab stays");
}
