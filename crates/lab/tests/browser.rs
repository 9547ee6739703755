//! The lab in a real browser: headless Chromium (Debian's `chromium`),
//! driven through the DevTools protocol over `--remote-debugging-pipe`
//! (JSON messages ended by a NUL on file descriptors 3 and 4: no websocket
//! client, no crate that downloads a browser).
//!
//! In a fresh handout with chapter 2 solved and one mistake planted (the
//! sphere's c = |f|² − ρ, the radius not squared), it opens the page,
//! waits for the student's wrong picture and the difference, clicks a
//! differing pixel, checks that both trees show with the first difference
//! highlighted, then fixes the mistake on disk and checks that the page
//! shows the passing picture by itself, without a reload.
//!
//! It takes minutes (the handout's first build), so it runs only with
//! `RAYBOOK_LAB_BROWSER=1`, as .ci/run sets it:
//! `RAYBOOK_LAB_BROWSER=1 cargo test -q -p lab --test browser -- --nocapture`.

use std::io::{BufRead, BufReader, Write};
use std::os::fd::AsRawFd;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

/// The two tests one after the other: each starts a lab, a Chromium and
/// cargo builds, and side by side on a loaded 2-core machine the handout's
/// click once waited out its minute behind the other's build (CI, this
/// stop); a student runs one lab at a time too.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Holds [`ONE_AT_A_TIME`] (a test that failed while holding it must not
/// fail the other).
fn one_at_a_time() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

const MISTAKE: (&str, &str) = (
    "let c = f.dot(f) - radius * radius;",
    "let c = f.dot(f) - radius;",
);

#[test]
fn a_student_clicks_a_wrong_pixel_and_sees_the_page_follow_the_fix() {
    if std::env::var_os("RAYBOOK_LAB_BROWSER").is_none() {
        eprintln!(
            "browser: set RAYBOOK_LAB_BROWSER=1 to drive the lab in headless Chromium (minutes)"
        );
        return;
    }
    let _one = one_at_a_time();
    let started = Instant::now();
    let handout = handout_with_a_mistake();
    let lab = lab::Lab::start(handout.clone(), 0, true).expect("the lab starts");
    lab.serve_in_background();
    let mut browser = Browser::open(&format!("{}#02-hits", lab.url()));

    // The student's wrong picture and the difference appear.
    let minutes = Duration::from_secs(900);
    browser.wait_for(
        "document.getElementById('difference').naturalWidth > 0",
        minutes,
    );
    let message = browser.eval("document.getElementById('bench-message').textContent");
    assert!(message.as_str().unwrap().contains("FAIL"), "{message}");
    eprintln!(
        "browser: the wrong picture shows after {:.0?}",
        started.elapsed()
    );

    // Click a pixel that differs (not the one the page picked by itself).
    let (x, y) = differing_pixel(&lab, &mut browser);
    browser.click_pixel("difference", x, y);
    let label = format!("({x}, {y})");
    browser.wait_for(
        &format!(
            "document.getElementById('pixel').dataset.shown === '{x},{y}' \
             && document.querySelector('#tree-yours details') !== null \
             && document.querySelector('#tree-reference details') !== null \
             && document.getElementById('first-difference').textContent.startsWith('first difference')"
        ),
        Duration::from_secs(180),
    );
    let mut highlighted = |side: &str| {
        browser
            .eval(&format!(
                "document.querySelectorAll('#tree-{side} tr.differs, #tree-{side} details.differs').length"
            ))
            .as_u64()
            .unwrap()
    };
    assert!(
        highlighted("yours") >= 1 && highlighted("reference") >= 1,
        "the first difference is highlighted in both trees"
    );
    let first = browser.eval("document.getElementById('first-difference').textContent");
    eprintln!("browser: clicked {label}: {first}");

    // Fix the mistake on disk, once the first run of progress is over (as
    // a student's next save usually comes): the page updates by itself.
    browser.wait_for(
        "lab.state && lab.state.rows && lab.state.busy.length === 0",
        Duration::from_secs(600),
    );
    browser.eval("window.notReloaded = true");
    let sphere = handout.join("chapters/02-hits/src/sphere.rs");
    let source = std::fs::read_to_string(&sphere).unwrap();
    std::fs::write(&sphere, source.replace(MISTAKE.1, MISTAKE.0)).unwrap();
    let saved = Instant::now();
    browser.wait_for(
        "document.getElementById('bench-message').textContent.startsWith('PASS')",
        Duration::from_secs(300),
    );
    assert_eq!(browser.eval("window.notReloaded === true"), json!(true));
    eprintln!(
        "browser: the page shows the passing picture {:.1?} after the save",
        saved.elapsed()
    );
}

/// Chapter 7's accuracy page in this workspace (chapter 7 solved): a
/// setting picked in the form and rendered by pressing the button shows
/// its point, in the table and on both plots beside the study's curves,
/// with the same RMSE the server measured.
#[test]
fn the_accuracy_page_adds_a_rendered_point_to_the_studys_curves() {
    if std::env::var_os("RAYBOOK_LAB_BROWSER").is_none() {
        return;
    }
    let _one = one_at_a_time();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap();
    let entry = lab::chapter::bench_chapter(lab::accuracy::CHAPTER).unwrap();
    lab::bench::build(&root, entry).expect("chapter 7 builds");
    let lab = lab::Lab::start(root, 0, false).expect("the lab starts");
    lab.serve_in_background();
    let mut browser = Browser::open(&format!("{}#07-termination", lab.url()));
    browser.wait_for(
        "!document.getElementById('accuracy').hidden \
         && document.querySelectorAll('#accuracy-rays polyline.study').length === 12",
        Duration::from_secs(60),
    );
    browser.eval(
        "(() => { const f = document.getElementById('accuracy-form'); \
         f.elements.max_depth.value = '2'; f.elements.min_weight.value = '0.01'; \
         f.elements.rays.value = '4'; f.elements.seed.disabled = false; f.elements.seed.value = '3'; \
         document.getElementById('accuracy-render').click(); return true; })()",
    );
    browser.wait_for(
        "document.querySelectorAll('#accuracy-points tbody tr').length === 1 \
         && document.querySelectorAll('#accuracy-rays circle.yours.last').length === 1 \
         && document.querySelectorAll('#accuracy-time circle.yours.last').length === 1",
        Duration::from_secs(120),
    );
    let row = browser.eval("document.querySelector('#accuracy-points tbody tr').textContent");
    let row = row.as_str().unwrap();
    assert!(
        row.starts_with("depth 2, threshold 0.01, 4 jittered, seed 3"),
        "{row}"
    );
    let state: Value =
        serde_json::from_slice(&http_get(&format!("{}api/accuracy", lab.url()))).unwrap();
    let rmse = state["points"][0]["rmse"].as_f64().unwrap();
    let shown =
        browser.eval("document.querySelector('#accuracy-points tbody tr').cells[1].textContent");
    let shown: f64 = shown.as_str().unwrap().parse().unwrap();
    assert!(
        (shown - rmse).abs() < 1e-3 * rmse,
        "the page shows {shown}, the server measured {rmse}"
    );
    let chosen = browser.eval("document.querySelectorAll('#accuracy-rays .study.chosen').length");
    assert!(
        chosen.as_u64().unwrap() >= 1,
        "the study's curve of depth 2, threshold 0.01"
    );
    eprintln!("browser: the accuracy page shows {row}");
}

/// A fresh handout (under the test's temporary folder) with chapters 1
/// and 2 solved and the sphere's radius not squared.
fn handout_with_a_mistake() -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("lab-browser-handout");
    let _ = std::fs::remove_dir_all(&dir);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(cargo)
        .args(["run", "-q", "-p", "workbook", "--", "handout"])
        .arg(&dir)
        .args(["--solved-through", "2"])
        .current_dir(&root)
        .stdout(Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "the handout is written");
    let sphere = dir.join("chapters/02-hits/src/sphere.rs");
    let source = std::fs::read_to_string(&sphere).unwrap();
    assert!(
        source.contains(MISTAKE.0),
        "the sphere's solution changed: update MISTAKE"
    );
    std::fs::write(&sphere, source.replace(MISTAKE.0, MISTAKE.1)).unwrap();
    dir
}

/// A pixel of the difference map that differs (red) and is not the one the
/// page shows already.
fn differing_pixel(lab: &lab::Lab, browser: &mut Browser) -> (u32, u32) {
    let shown = browser.eval("JSON.stringify(lab.pixel)");
    let url = format!("{}pictures/02-hits/difference.png", lab.url());
    let png = http_get(&url);
    let map = image::load_from_memory(&png).unwrap().to_rgb8();
    map.enumerate_pixels()
        .filter(|(_, _, p)| p[0] >= 128 && p[1] == 0)
        .map(|(x, y, _)| (x, y))
        .find(|(x, y)| shown.as_str() != Some(&format!("[{x},{y}]")))
        .expect("a differing pixel")
}

/// The body of a GET of `url` on 127.0.0.1.
fn http_get(url: &str) -> Vec<u8> {
    let rest = url.strip_prefix("http://").unwrap();
    let (host, path) = rest.split_once('/').unwrap();
    let mut stream = std::net::TcpStream::connect(host).unwrap();
    write!(
        stream,
        "GET /{path} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut bytes = Vec::new();
    std::io::Read::read_to_end(&mut stream, &mut bytes).unwrap();
    let start = bytes.windows(4).position(|w| w == b"\r\n\r\n").unwrap() + 4;
    bytes[start..].to_vec()
}

/// Headless Chromium on a DevTools pipe, with one page.
struct Browser {
    child: Child,
    to: std::io::PipeWriter,
    from: BufReader<std::io::PipeReader>,
    session: String,
    next_id: u64,
}

impl Browser {
    fn open(url: &str) -> Browser {
        let program = ["chromium", "chromium-browser"]
            .into_iter()
            .find(|p| Command::new(p).arg("--version").output().is_ok())
            .expect("no chromium: apt-get install -y chromium");
        // A profile of its own per browser: the two tests run at once.
        static OPENED: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
        let n = OPENED.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let profile =
            PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("lab-browser-profile-{n}"));
        let _ = std::fs::remove_dir_all(&profile);
        // The browser reads commands on fd 3 and writes answers on fd 4.
        let (commands, to) = std::io::pipe().unwrap();
        let (from, answers) = std::io::pipe().unwrap();
        let (read_end, write_end) = (commands.as_raw_fd(), answers.as_raw_fd());
        let mut command = Command::new(program);
        command
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--remote-debugging-pipe",
            ])
            .args(["--window-size=1280,800", "--no-first-run"])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null());
        // SAFETY: between fork and exec only async-signal-safe calls (fcntl,
        // dup2) on descriptors this process owns.
        unsafe {
            command.pre_exec(move || {
                let high_read = libc::fcntl(read_end, libc::F_DUPFD, 10);
                let high_write = libc::fcntl(write_end, libc::F_DUPFD, 10);
                if high_read < 0
                    || high_write < 0
                    || libc::dup2(high_read, 3) < 0
                    || libc::dup2(high_write, 4) < 0
                {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        let child = command.spawn().expect("chromium starts");
        drop((commands, answers));
        let mut browser = Browser {
            child,
            to,
            from: BufReader::new(from),
            session: String::new(),
            next_id: 0,
        };
        let target = browser.call("Target.createTarget", json!({"url": url}), false);
        let target = target["targetId"].as_str().unwrap().to_owned();
        let attached = browser.call(
            "Target.attachToTarget",
            json!({"targetId": target, "flatten": true}),
            false,
        );
        browser.session = attached["sessionId"].as_str().unwrap().to_owned();
        browser
    }

    /// Sends a command (to the page's session if `page`) and returns its result.
    fn call(&mut self, method: &str, params: Value, page: bool) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let mut message = json!({"id": id, "method": method, "params": params});
        if page {
            message["sessionId"] = json!(self.session);
        }
        let mut bytes = message.to_string().into_bytes();
        bytes.push(0);
        self.to.write_all(&bytes).unwrap();
        loop {
            let mut answer = Vec::new();
            let read = self.from.read_until(0, &mut answer).unwrap();
            assert!(read > 0, "chromium closed its pipe");
            answer.pop();
            let answer: Value = serde_json::from_slice(&answer).unwrap();
            if answer["id"] == json!(id) {
                assert!(answer.get("error").is_none(), "{method}: {answer}");
                return answer["result"].clone();
            }
        }
    }

    /// The value of a JavaScript expression in the page.
    fn eval(&mut self, expression: &str) -> Value {
        let result = self.call(
            "Runtime.evaluate",
            json!({"expression": expression, "returnByValue": true}),
            true,
        );
        result["result"]["value"].clone()
    }

    /// Waits until `condition` (JavaScript) is true in the page.
    fn wait_for(&mut self, condition: &str, patience: Duration) {
        let start = Instant::now();
        while self.eval(&format!("Boolean({condition})")) != json!(true) {
            assert!(
                start.elapsed() < patience,
                "waited {patience:?} for {condition}; the page says: {}",
                self.eval("document.getElementById('bench-message').textContent")
            );
            std::thread::sleep(Duration::from_millis(250));
        }
    }

    /// Clicks pixel (x, y) of one of the bench's pictures, as a mouse does.
    fn click_pixel(&mut self, picture: &str, x: u32, y: u32) {
        let rect = self.eval(&format!(
            "(() => {{ const i = document.getElementById('{picture}'); i.scrollIntoView(); \
             const r = i.getBoundingClientRect(); return [r.left, r.top, r.width]; }})()"
        ));
        let [left, top, width] = [0, 1, 2].map(|i| rect[i].as_f64().unwrap());
        let scale = width / 160.0;
        let (cx, cy) = (
            left + (x as f64 + 0.5) * scale,
            top + (y as f64 + 0.5) * scale,
        );
        for kind in ["mousePressed", "mouseReleased"] {
            self.call(
                "Input.dispatchMouseEvent",
                json!({"type": kind, "x": cx, "y": cy, "button": "left", "clickCount": 1}),
                true,
            );
        }
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
