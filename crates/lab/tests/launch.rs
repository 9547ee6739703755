//! The browser is opened on a page only the student can read, which
//! redirects to the lab's address: the token is never on a command line,
//! where every local user reads it (`/proc/PID/cmdline`).

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

use lab::launch::{RedirectFile, open_with};

const URL: &str = "http://127.0.0.1:8000/0123456789abcdef0123456789abcdef/";
const TOKEN: &str = "0123456789abcdef0123456789abcdef";

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn mode(path: &Path) -> u32 {
    std::fs::metadata(path).unwrap().permissions().mode() & 0o777
}

#[test]
fn the_page_is_the_students_alone_and_leads_to_the_lab() {
    let base = scratch("launch-page");
    let page = RedirectFile::new_in(&base, URL).unwrap();
    let (file, folder) = (
        page.path().to_owned(),
        page.path().parent().unwrap().to_owned(),
    );
    assert_eq!(mode(&folder), 0o700);
    assert_eq!(mode(&file), 0o600);
    assert!(!file.to_string_lossy().contains(TOKEN), "{file:?}");
    let html = std::fs::read_to_string(&file).unwrap();
    assert!(
        html.contains(&format!("content=\"0; url={URL}\"")),
        "{html}"
    );
    let other = RedirectFile::new_in(&base, URL).unwrap();
    assert_ne!(other.path(), file, "each lab its own folder");
    drop(page);
    assert!(!file.exists() && !folder.exists(), "removed when dropped");
}

/// An opener that records its arguments is handed the page's path, and
/// nothing of the token.
#[test]
fn the_opener_is_not_given_the_token() {
    let base = scratch("launch-opener");
    let script = base.join("record-arguments");
    let record = base.join("arguments");
    let text = format!(
        "#!/bin/sh\nprintf '%s\\n' \"$@\" > '{}'\n",
        record.display()
    );
    std::fs::write(&script, text).unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o700)).unwrap();
    let page = RedirectFile::new_in(&base, URL).unwrap();
    let status = open_with(script.to_str().unwrap(), page.path())
        .unwrap()
        .wait()
        .unwrap();
    assert!(status.success());
    let arguments = std::fs::read_to_string(&record).unwrap();
    assert_eq!(arguments.trim_end(), page.path().to_str().unwrap());
    assert!(!arguments.contains(TOKEN), "{arguments}");
}
