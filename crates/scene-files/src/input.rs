//! Opening the files a scene is read from: the scene file and every file it
//! names (OBJ meshes). Only regular files are read. A named pipe may never
//! end, nor may a device such as /dev/zero, and opening a pipe to read
//! waits for a writer that may never come: reading one would hang the
//! command instead of refusing it. A directory has no text to read.
//!
//! The file is opened first, without waiting (`O_NONBLOCK`: a pipe then
//! opens at once), and what it is is asked of the open file (`fstat`), so
//! nothing can be swapped in between the check and the read.

use std::fs::File;
use std::io;
use std::path::Path;

/// Opens `path` for reading if it is a regular file (a symbolic link to one
/// is followed); otherwise says what it is. Returns the file and its size.
pub(crate) fn open_regular(path: &Path) -> Result<(File, u64), String> {
    let file = open_without_waiting(path).map_err(|e| open_error(&e))?;
    let metadata = file.metadata().map_err(|e| e.to_string())?;
    let kind = metadata.file_type();
    if kind.is_dir() {
        return Err("it is a directory, not a file".into());
    }
    if !kind.is_file() {
        return Err(format!(
            "it is {}, not a regular file; scenes and meshes are read only from \
             regular files, since a pipe or a device may never end",
            kind_of(&kind)
        ));
    }
    Ok((file, metadata.len()))
}

/// Opens for reading; on unix without waiting for a writer (a named pipe
/// would otherwise block the open itself).
fn open_without_waiting(path: &Path) -> io::Result<File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// Why a file cannot be opened, in words: a loop of symbolic links is named
/// as such (the system says "too many levels of symbolic links").
fn open_error(error: &io::Error) -> String {
    #[cfg(unix)]
    if error.raw_os_error() == Some(libc::ELOOP) {
        return "the path loops through symbolic links (one links back to another), \
                so it names no file"
            .into();
    }
    error.to_string()
}

/// What a file that is neither a regular file nor a directory is, for
/// messages.
fn kind_of(kind: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if kind.is_char_device() {
            return "a device (such as /dev/zero, or a terminal)";
        }
        if kind.is_block_device() {
            return "a block device";
        }
        if kind.is_socket() {
            return "a socket";
        }
    }
    "something other than a file"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_regular_file_opens_with_its_size() {
        let file = tempfile::NamedTempFile::new().unwrap();
        std::fs::write(file.path(), "v 0 0 0\n").unwrap();
        let (_, size) = open_regular(file.path()).unwrap();
        assert_eq!(size, 8);
    }

    #[test]
    fn a_directory_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let e = open_regular(dir.path()).unwrap_err();
        assert_eq!(e, "it is a directory, not a file");
    }

    #[cfg(unix)]
    #[test]
    fn devices_pipes_and_link_loops_are_refused_at_once() {
        let start = std::time::Instant::now();
        let e = open_regular(Path::new("/dev/zero")).unwrap_err();
        assert!(e.starts_with("it is a device (such as /dev/zero"), "{e}");
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("pipe");
        let name = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        // SAFETY: mkfifo reads a NUL-terminated path that outlives the call.
        assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o600) }, 0);
        let e = open_regular(&fifo).unwrap_err();
        assert!(e.contains("named pipe"), "{e}");
        let (a, b) = (dir.path().join("a"), dir.path().join("b"));
        std::os::unix::fs::symlink(&b, &a).unwrap();
        std::os::unix::fs::symlink(&a, &b).unwrap();
        let e = open_regular(&a).unwrap_err();
        assert!(e.contains("loops through symbolic links"), "{e}");
        assert!(start.elapsed().as_secs() < 5);
    }
}
