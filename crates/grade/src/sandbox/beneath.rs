//! Reading what a student could have written, by one road: every file and
//! folder is opened *beneath* a folder that grading opened itself, with no
//! symlink anywhere on the way, and only a regular file of a bounded size
//! is read, within a time.
//!
//! Why a descriptor and not a path: a path is resolved again at every use,
//! and the kernel follows a symlink in any of its middle folders. A student
//! who swaps `target/probe` for a link to the teacher's files, after the
//! grader checked the last part of a path, has the grader read (or delete)
//! the teacher's files. Here the starting folder is opened once, from a
//! path that passes through no folder a student can write (a student's
//! build folder is a mount point; their handout's folder is named by the
//! class list), and every open below it is `openat2` with
//! `RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS |
//! RESOLVE_NO_XDEV`: the kernel refuses the whole path if any part is a
//! link, leaves the folder, or crosses a mount. The file is opened
//! `O_NONBLOCK` (a FIFO cannot hold the class run) and `O_NOCTTY`, then
//! checked on the open descriptor (`fstat`): a regular file, at most the
//! size asked for. Where `openat2` is missing (a kernel before 5.6, a
//! seccomp filter that refuses it), the path is opened one part at a time
//! with `O_NOFOLLOW`, which refuses a link in every part just the same
//! (the mount check is then the sandbox's: a student cannot mount).
//!
//! The calls come from rustix (`openat2`, `fstat`, reading a folder): it
//! is the well-kept safe wrapper of these system calls that the standard
//! library's own tempfile and much of the ecosystem build on, and it was
//! in the lock file already.
//!
//! A refusal is a sentence of the grader's own ([`Refused`]): it never
//! quotes the file.

use std::ffi::OsStr;
use std::io::Read;
use std::os::fd::{AsFd, OwnedFd};
use std::os::unix::ffi::OsStrExt;
use std::path::{Component, Path, PathBuf};
use std::time::Instant;

use rustix::fs::{Mode, OFlags, ResolveFlags};
use rustix::io::Errno;

/// Why a file was not read, in the grader's words.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Refused {
    /// Not there.
    Missing,
    /// A symlink on the way or at the end: never followed.
    Link,
    /// A FIFO, a socket, a device, or a folder where a file was asked for
    /// (or a file where a folder was): its kind, in words.
    Kind(&'static str),
    /// Larger than the most asked for: its size.
    TooLarge(u64),
    /// Not read within the time.
    TooSlow,
    /// A path that names a parent, the root, or a character grading
    /// refuses in a name (see [`clean_name`]).
    BadName,
    /// A file where a folder was asked for.
    NotAFolder,
    /// Another error of the system, in its words (no file content).
    Other(String),
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refused::Missing => write!(f, "missing"),
            Refused::Link => write!(f, "a symlink, or a path through one: never followed"),
            Refused::Kind(kind) => write!(f, "{kind}, not a regular file: refused"),
            Refused::TooLarge(size) => write!(f, "{size} bytes, more than grading reads: refused"),
            Refused::TooSlow => write!(f, "not read in time: refused"),
            Refused::BadName => write!(f, "a name grading does not read: refused"),
            Refused::NotAFolder => write!(f, "not a folder: refused"),
            Refused::Other(e) => write!(f, "cannot be read ({e})"),
        }
    }
}

impl Refused {
    fn of(errno: Errno) -> Refused {
        match errno {
            Errno::NOENT => Refused::Missing,
            Errno::LOOP | Errno::XDEV => Refused::Link,
            Errno::NOTDIR => Refused::NotAFolder,
            e => Refused::Other(e.to_string()),
        }
    }
}

/// What an entry of a folder is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A regular file of this many bytes.
    File(u64),
    Folder,
    Link,
    /// Anything else, in words: "a FIFO", "a socket", "a device".
    Other(&'static str),
}

/// A folder opened once; everything below it is opened beneath it.
#[derive(Debug)]
pub struct Folder {
    fd: OwnedFd,
    /// Open one part at a time even where `openat2` is there (tests, and a
    /// teacher in doubt: `RAYBOOK_GRADE_NO_OPENAT2=1`).
    by_parts: bool,
}

impl Folder {
    /// Opens the folder at `path`, a path that passes through no folder a
    /// student can write (its last part is not followed if it is a link).
    pub fn open(path: &Path) -> Result<Folder, String> {
        let flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
        let fd = rustix::fs::open(path, flags, Mode::empty())
            .map_err(|e| format!("cannot open {}: {}", path.display(), Refused::of(e)))?;
        let by_parts = std::env::var_os("RAYBOOK_GRADE_NO_OPENAT2").is_some();
        Ok(Folder { fd, by_parts })
    }

    /// The same folder, opened one part at a time from now on.
    #[cfg(test)]
    fn by_parts(self) -> Folder {
        Folder {
            by_parts: true,
            ..self
        }
    }

    /// The folder `relative` beneath this one.
    pub fn folder(&self, relative: &Path) -> Result<Folder, Refused> {
        if relative.as_os_str().is_empty() {
            return Ok(Folder {
                fd: self.reopen()?,
                ..*self
            });
        }
        let flags = OFlags::RDONLY | OFlags::DIRECTORY;
        Ok(Folder {
            fd: open_beneath(&self.fd, relative, flags, self.by_parts)?,
            ..*self
        })
    }

    /// The bytes of the regular file `relative` beneath this folder: at
    /// most `most` bytes, read before `by`.
    pub fn read(&self, relative: &Path, most: u64, by: Instant) -> Result<Vec<u8>, Refused> {
        let flags = OFlags::RDONLY | OFlags::NONBLOCK | OFlags::NOCTTY;
        let fd = open_beneath(&self.fd, relative, flags, self.by_parts)?;
        let size = regular_size(&fd)?;
        if size > most {
            return Err(Refused::TooLarge(size));
        }
        let mut file = std::fs::File::from(fd);
        let mut bytes = Vec::with_capacity(size as usize);
        let mut chunk = vec![0u8; 1 << 16];
        loop {
            if Instant::now() > by {
                return Err(Refused::TooSlow);
            }
            let n = file
                .read(&mut chunk)
                .map_err(|e| Refused::Other(e.to_string()))?;
            if n == 0 {
                return Ok(bytes);
            }
            if bytes.len() as u64 + n as u64 > most {
                return Err(Refused::TooLarge(bytes.len() as u64 + n as u64));
            }
            bytes.extend_from_slice(&chunk[..n]);
        }
    }

    /// What `relative` is, without following it.
    pub fn kind(&self, relative: &Path) -> Result<Kind, Refused> {
        let (parent, name) = split(relative)?;
        let parent = self.folder(parent)?;
        let stat = rustix::fs::statat(&parent.fd, name, rustix::fs::AtFlags::SYMLINK_NOFOLLOW)
            .map_err(Refused::of)?;
        Ok(kind_of(stat.st_mode, stat.st_size as u64))
    }

    /// The entries of this folder (not `.` and `..`), with their kinds,
    /// sorted by name.
    pub fn entries(&self) -> Result<Vec<(std::ffi::OsString, Kind)>, Refused> {
        let mut dir = rustix::fs::Dir::new(self.reopen()?).map_err(Refused::of)?;
        let mut found = Vec::new();
        while let Some(entry) = dir.read() {
            let entry = entry.map_err(Refused::of)?;
            let name = OsStr::from_bytes(entry.file_name().to_bytes()).to_owned();
            if name == "." || name == ".." {
                continue;
            }
            let stat = rustix::fs::statat(
                &self.fd,
                entry.file_name(),
                rustix::fs::AtFlags::SYMLINK_NOFOLLOW,
            )
            .map_err(Refused::of)?;
            found.push((name, kind_of(stat.st_mode, stat.st_size as u64)));
        }
        found.sort_by(|a, b| a.0.cmp(&b.0));
        Ok(found)
    }

    /// Every entry below this folder, relative to it, without following a
    /// link: files, links and other kinds; folders are entered unless
    /// `skip(path, is_folder)` says so, and are not listed. At most `most`
    /// entries (a folder of millions is refused, not walked).
    pub fn walk(
        &self,
        skip: &dyn Fn(&Path, bool) -> bool,
        most: usize,
    ) -> Result<Vec<(PathBuf, Kind)>, String> {
        let mut found = Vec::new();
        let mut folders = vec![PathBuf::new()];
        while let Some(relative) = folders.pop() {
            let folder = self
                .folder(&relative)
                .map_err(|e| format!("{}: {e}", shown(&relative)))?;
            let entries = folder
                .entries()
                .map_err(|e| format!("{}: {e}", shown(&relative)))?;
            for (name, kind) in entries {
                let path = relative.join(name);
                if skip(&path, kind == Kind::Folder) {
                    continue;
                }
                match kind {
                    Kind::Folder => folders.push(path),
                    kind => found.push((path, kind)),
                }
                if found.len() + folders.len() > most {
                    return Err(format!("more than {most} files: not listed"));
                }
            }
        }
        found.sort_by(|a, b| a.0.cmp(&b.0));
        Ok(found)
    }

    /// This folder opened again (`.`), with a reading position of its own:
    /// a copied descriptor would share it, and a second listing would
    /// find nothing.
    fn reopen(&self) -> Result<OwnedFd, Refused> {
        let flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::CLOEXEC;
        rustix::fs::openat(&self.fd, ".", flags, Mode::empty()).map_err(Refused::of)
    }

    /// Makes the folder `name` in this one, if it is not there (no error
    /// if something is: what stands there is never followed).
    pub fn make_folder(&self, name: &str) {
        let _ = rustix::fs::mkdirat(&self.fd, name, Mode::from_raw_mode(0o755));
    }
}

/// The folder part and the last name of `relative`.
fn split(relative: &Path) -> Result<(&Path, &OsStr), Refused> {
    match (relative.parent(), relative.file_name()) {
        (Some(parent), Some(name)) => Ok((parent, name)),
        _ => Err(Refused::BadName),
    }
}

/// A path beneath a folder as the messages show it.
fn shown(relative: &Path) -> String {
    if relative.as_os_str().is_empty() {
        "the folder".to_owned()
    } else {
        clean_line(&relative.to_string_lossy())
    }
}

/// Opens `relative` beneath `dir` with `flags`: `openat2` refusing every
/// link and every way out, or, where the kernel has no `openat2`, one part
/// at a time with `O_NOFOLLOW`.
fn open_beneath(
    dir: &OwnedFd,
    relative: &Path,
    flags: OFlags,
    by_parts: bool,
) -> Result<OwnedFd, Refused> {
    let plain = relative
        .components()
        .all(|c| matches!(c, Component::Normal(_)));
    if !plain || relative.as_os_str().is_empty() {
        return Err(Refused::BadName);
    }
    let flags = flags | OFlags::NOFOLLOW | OFlags::CLOEXEC;
    let resolve = ResolveFlags::BENEATH
        | ResolveFlags::NO_SYMLINKS
        | ResolveFlags::NO_MAGICLINKS
        | ResolveFlags::NO_XDEV;
    if !by_parts {
        match rustix::fs::openat2(dir, relative, flags, Mode::empty(), resolve) {
            Err(Errno::NOSYS) | Err(Errno::PERM) => {}
            // A race with a rename, or a link that O_DIRECTORY reports as
            // "not a folder": the fallback tells which part it was.
            Err(Errno::AGAIN) | Err(Errno::NOTDIR) => return open_by_parts(dir, relative, flags),
            result => return result.map_err(Refused::of),
        }
    }
    open_by_parts(dir, relative, flags)
}

/// The fallback: each folder on the way opened with `O_NOFOLLOW |
/// O_DIRECTORY` beneath the last, then the end with `flags`.
fn open_by_parts(dir: &OwnedFd, relative: &Path, flags: OFlags) -> Result<OwnedFd, Refused> {
    let parts: Vec<&OsStr> = relative.iter().collect();
    let (last, folders) = parts.split_last().ok_or(Refused::BadName)?;
    let mut here: Option<OwnedFd> = None;
    for part in folders {
        let at = here.as_ref().map_or(dir.as_fd(), |fd| fd.as_fd());
        let folder = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
        let opened = rustix::fs::openat(at, *part, folder, Mode::empty());
        here = Some(opened.map_err(|e| refused_at(at, part, e))?);
    }
    let at = here.as_ref().map_or(dir.as_fd(), |fd| fd.as_fd());
    rustix::fs::openat(at, *last, flags, Mode::empty()).map_err(|e| refused_at(at, last, e))
}

/// Why opening `name` in `at` failed: `O_NOFOLLOW` with `O_DIRECTORY`
/// says "not a folder" of a link, so a link is looked for first.
fn refused_at(at: std::os::fd::BorrowedFd, name: &OsStr, errno: Errno) -> Refused {
    let stat = rustix::fs::statat(at, name, rustix::fs::AtFlags::SYMLINK_NOFOLLOW);
    match stat {
        Ok(stat) if kind_of(stat.st_mode, 0) == Kind::Link => Refused::Link,
        _ => Refused::of(errno),
    }
}

/// The size of the open `fd` if it is a regular file.
fn regular_size(fd: &OwnedFd) -> Result<u64, Refused> {
    let stat = rustix::fs::fstat(fd).map_err(Refused::of)?;
    match kind_of(stat.st_mode, stat.st_size as u64) {
        Kind::File(size) => Ok(size),
        Kind::Folder => Err(Refused::Kind("a folder")),
        Kind::Link => Err(Refused::Link),
        Kind::Other(what) => Err(Refused::Kind(what)),
    }
}

/// A kind from `st_mode`.
fn kind_of(mode: u32, size: u64) -> Kind {
    match rustix::fs::FileType::from_raw_mode(mode) {
        rustix::fs::FileType::RegularFile => Kind::File(size),
        rustix::fs::FileType::Directory => Kind::Folder,
        rustix::fs::FileType::Symlink => Kind::Link,
        rustix::fs::FileType::Fifo => Kind::Other("a FIFO"),
        rustix::fs::FileType::Socket => Kind::Other("a socket"),
        rustix::fs::FileType::CharacterDevice | rustix::fs::FileType::BlockDevice => {
            Kind::Other("a device")
        }
        _ => Kind::Other("an unknown kind of file"),
    }
}

/// `text` on one line, as a terminal, a CSV cell or a report may show it:
/// every control character but a tab (a line break, a carriage return,
/// ESC and the escape sequences it starts) and every bidirectional control
/// (which can reorder what a reader sees) replaced by `?`.
pub fn clean_line(text: &str) -> String {
    text.chars()
        .map(|c| if is_unsafe(c) { '?' } else { c })
        .collect()
}

/// Is `name` one grading takes as it is (no control or bidirectional
/// character)? A picture named otherwise is refused.
pub fn clean_name(name: &str) -> bool {
    !name.chars().any(is_unsafe)
}

/// A control character (not a tab), or a bidirectional formatting
/// character.
pub fn is_unsafe(c: char) -> bool {
    (c.is_control() && c != '\t')
        || matches!(c,
            '\u{200E}' | '\u{200F}' | '\u{061C}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}')
}

#[cfg(test)]
#[path = "beneath_tests.rs"]
mod tests;
