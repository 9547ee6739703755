//! Opening the lab in the browser without showing its token to other users.
//!
//! A program's arguments are public on Linux: any local user reads them in
//! `/proc/PID/cmdline`. So the browser is not handed the lab's address
//! (which holds the token); it is handed the path of a small HTML page
//! that redirects to the address, in a folder only the student can enter
//! (0700), readable by the student only (0600). Both are created afresh,
//! atomically: `mkdir` of a new random name fails rather than reuse what
//! another user made (even a symbolic link), and the file is created only
//! if it does not exist. Jupyter opens its notebooks the same way.

use std::fs::{DirBuilder, OpenOptions};
use std::io::Write;
use std::os::unix::fs::{DirBuilderExt, OpenOptionsExt};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

/// The redirecting page and its folder; both removed when dropped.
pub struct RedirectFile {
    folder: PathBuf,
    file: PathBuf,
}

impl RedirectFile {
    /// Writes a page that redirects to `url`, in a new folder under
    /// `$XDG_RUNTIME_DIR` (the user's own, 0700 by definition) or else the
    /// system's temporary folder.
    pub fn new(url: &str) -> std::io::Result<RedirectFile> {
        let base = std::env::var_os("XDG_RUNTIME_DIR")
            .map(PathBuf::from)
            .filter(|dir| dir.is_absolute() && dir.is_dir())
            .unwrap_or_else(std::env::temp_dir);
        RedirectFile::new_in(&base, url)
    }

    /// Writes a page that redirects to `url`, in a new folder under `base`.
    pub fn new_in(base: &Path, url: &str) -> std::io::Result<RedirectFile> {
        let name = crate::guard::new_token().map_err(std::io::Error::other)?;
        let folder = base.join(format!("raybook-lab-{name}"));
        DirBuilder::new().mode(0o700).create(&folder)?;
        let file = folder.join("open-the-lab.html");
        let written = OpenOptions::new()
            .write(true)
            .create_new(true)
            .mode(0o600)
            .open(&file)
            .and_then(|mut f| f.write_all(redirect_page(url).as_bytes()));
        let page = RedirectFile { folder, file };
        written.map(|()| page)
    }

    /// The page's path: what the browser is given.
    pub fn path(&self) -> &Path {
        &self.file
    }
}

impl Drop for RedirectFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.file);
        let _ = std::fs::remove_dir(&self.folder);
    }
}

/// A page that sends the browser on to `url` at once (and shows it as a
/// link, should the browser refuse to follow). `url` is the lab's own
/// address: digits, dots, a colon, slashes and hex, nothing to escape.
fn redirect_page(url: &str) -> String {
    debug_assert!(!url.contains(['"', '<', '>', '&']), "{url}");
    format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n\
         <meta http-equiv=\"refresh\" content=\"0; url={url}\">\n\
         <title>raybook lab</title></head>\n\
         <body><p><a href=\"{url}\">Open the lab</a></p></body></html>\n"
    )
}

/// The programs that open a file in the user's browser: xdg-open (macOS:
/// open). (Not `open` elsewhere: on Debian that is openvt.)
pub fn openers() -> &'static [&'static str] {
    if cfg!(target_os = "macos") {
        &["open"]
    } else {
        &["xdg-open"]
    }
}

/// Starts `program` on `path`, detached from the lab's terminal.
pub fn open_with(program: &str, path: &Path) -> std::io::Result<Child> {
    Command::new(program)
        .arg(path)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
}
