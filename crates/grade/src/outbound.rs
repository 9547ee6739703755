//! What leaves a student's sandbox: a file the grader copies out of their
//! build folder (a failure picture, a log) is copied only if it is a
//! regular file, up to a size, within a time.
//!
//! Anything else in its place is refused with a reason that the student's
//! result notes: a symlink (copying it would copy whatever the teacher may
//! read into the report), a FIFO (opening it would block the class run
//! until someone writes), a device, a folder. It is opened with
//! `O_NOFOLLOW` (a symlink is refused by the kernel, even one swapped in
//! after the check) and `O_NONBLOCK` (a FIFO opens without waiting), and
//! checked again on the open file (`fstat`), whose bytes are then read.

use std::io::{Read, Write};
use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
use std::path::Path;
use std::time::{Duration, Instant};

/// The most a file copied out may hold: a failure picture is a few
/// hundred KiB.
pub const MAX_BYTES: u64 = 32 << 20;

/// The longest a copy may take.
pub const MAX_TIME: Duration = Duration::from_secs(10);

/// Copies the regular file `from` to `to`, at most `max` bytes, within
/// `time`; else an error saying what was there instead.
pub fn copy_out(from: &Path, to: &Path, max: u64, time: Duration) -> Result<(), String> {
    let start = Instant::now();
    let meta = std::fs::symlink_metadata(from).map_err(|e| format!("cannot read it: {e}"))?;
    let kind = what(&meta.file_type());
    if kind != "a regular file" {
        return Err(format!("{kind}, not a regular file: refused"));
    }
    let flags = libc::O_NOFOLLOW | libc::O_NONBLOCK;
    let mut file = std::fs::File::options()
        .read(true)
        .custom_flags(flags)
        .open(from)
        .map_err(|e| format!("cannot open it as a regular file ({e}): refused"))?;
    let meta = file.metadata().map_err(|e| e.to_string())?;
    let kind = what(&meta.file_type());
    if kind != "a regular file" {
        return Err(format!("{kind}, not a regular file: refused"));
    }
    if meta.len() > max {
        return Err(format!(
            "{} bytes, more than the {max} a file copied out may hold: refused",
            meta.len()
        ));
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    let mut chunk = vec![0u8; 1 << 16];
    loop {
        if start.elapsed() > time {
            return Err(format!("not read within {} s: refused", time.as_secs()));
        }
        let n = file.read(&mut chunk).map_err(|e| e.to_string())?;
        if n == 0 {
            break;
        }
        if bytes.len() as u64 + n as u64 > max {
            return Err(format!(
                "grew past the {max} bytes a file copied out may hold: refused"
            ));
        }
        bytes.extend_from_slice(&chunk[..n]);
    }
    if let Some(parent) = to.parent() {
        std::fs::create_dir_all(parent).map_err(|e| e.to_string())?;
    }
    let mut out = std::fs::File::create(to).map_err(|e| format!("{}: {e}", to.display()))?;
    out.write_all(&bytes)
        .map_err(|e| format!("{}: {e}", to.display()))
}

/// What a file type is, in words.
fn what(kind: &std::fs::FileType) -> &'static str {
    if kind.is_symlink() {
        "a symlink"
    } else if kind.is_fifo() {
        "a FIFO"
    } else if kind.is_block_device() || kind.is_char_device() {
        "a device"
    } else if kind.is_socket() {
        "a socket"
    } else if kind.is_dir() {
        "a folder"
    } else {
        "a regular file"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_within_the_size_leave() {
        let dir = tempfile::tempdir().unwrap();
        let (from, to) = (dir.path().join("a.png"), dir.path().join("out/a.png"));
        std::fs::write(&from, b"picture").unwrap();
        copy_out(&from, &to, MAX_BYTES, MAX_TIME).unwrap();
        assert_eq!(std::fs::read(&to).unwrap(), b"picture");
        let big = copy_out(&from, &dir.path().join("b"), 3, MAX_TIME).unwrap_err();
        assert!(big.contains("more than the 3"), "{big}");

        let link = dir.path().join("link.png");
        std::os::unix::fs::symlink("/etc/passwd", &link).unwrap();
        let refused = copy_out(&link, &dir.path().join("c"), MAX_BYTES, MAX_TIME).unwrap_err();
        assert!(refused.starts_with("a symlink"), "{refused}");
        assert!(!dir.path().join("c").exists());

        let fifo = dir.path().join("fifo.png");
        let name = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
        // SAFETY: a valid C string.
        assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
        let start = Instant::now();
        let refused = copy_out(&fifo, &dir.path().join("d"), MAX_BYTES, MAX_TIME).unwrap_err();
        assert!(refused.starts_with("a FIFO"), "{refused}");
        assert!(start.elapsed() < MAX_TIME, "a FIFO must not block");
        let folder = copy_out(dir.path(), &dir.path().join("e"), MAX_BYTES, MAX_TIME);
        assert!(folder.unwrap_err().starts_with("a folder"));
    }
}
