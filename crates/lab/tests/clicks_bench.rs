//! The lab's benchmark: click-to-trees, the time from a pixel's request to
//! both trees and their comparison (the page's `api/pixel`: the student's
//! binary run with `--pixel X,Y --json --svg`, the reference's facts read,
//! `verify --tree`'s comparison), and save-to-picture, a chapter built and
//! rendered again after an edit, and request-to-point on chapter 7's
//! accuracy page (a render asked for, its error against the carried
//! reference shown). A measurement, not a check: it asserts
//! nothing about the time and runs only when asked, in this workspace
//! (where every chapter is solved):
//!
//! ```text
//! RAYBOOK_LAB_BENCH=1 cargo test -p lab --test clicks_bench -- --nocapture
//! ```

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Chapter 7's pixels: a miss, the floor, the mirror sphere, the glass
/// sphere (its deepest trees), and a walk along a row through both spheres.
fn pixels() -> Vec<(u32, u32)> {
    let mut pixels = vec![(80, 10), (75, 65), (45, 45), (95, 55)];
    pixels.extend((30..110).step_by(2).map(|x| (x, 55)));
    pixels
}

#[test]
fn click_to_trees_and_save_to_picture() {
    if std::env::var_os("RAYBOOK_LAB_BENCH").is_none() {
        eprintln!("clicks_bench: set RAYBOOK_LAB_BENCH=1 to measure the lab's answers");
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap();
    let lab = lab::Lab::start(root.clone(), 0, false).unwrap();
    lab.serve_in_background();
    let chapter = workbook::workbench::chapters::find("07-termination").unwrap();
    let started = Instant::now();
    lab::bench::build(&root, chapter).expect("chapter 7 builds");
    eprintln!(
        "chapter 7's debug binary built in {:.1?}",
        started.elapsed()
    );

    let mut times = Vec::new();
    for (x, y) in pixels() {
        let path = format!("api/pixel?chapter=07-termination&x={x}&y={y}");
        let start = Instant::now();
        let body = get(&lab, &path);
        times.push(start.elapsed());
        assert!(body.contains("\"comparison\""), "{body}");
    }
    report("click to trees, chapter 7", &mut times);

    // Save to picture: touch the chapter's source, then build and render
    // as the lab does on a save.
    let source = root.join("chapters/07-termination/src/lib.rs");
    let mut times = Vec::new();
    for _ in 0..3 {
        touch(&source);
        let start = Instant::now();
        let (bench, _) = lab::bench::run(&root, chapter, &root.join("target/lab"));
        times.push(start.elapsed());
        assert!(bench.passed, "{bench:?}");
    }
    report(
        "save to picture (build + render + verify), chapter 7",
        &mut times,
    );

    // Request to point on chapter 7's accuracy page: ask for a render, poll
    // (every 10 ms) until its point is there. Also the binary's own render
    // time, to say what the rest (starting it, writing and reading the PFM,
    // the MSE, the polling) costs.
    let settings = [
        ("centre", "max_depth=6&min_weight=0.001&rays=centre", 9),
        (
            "16 jittered",
            "max_depth=6&min_weight=0.001&rays=16&seed=1",
            5,
        ),
    ];
    for (name, query, runs) in settings {
        let mut times = Vec::new();
        let mut renders = Vec::new();
        for _ in 0..runs {
            let (took, point) = request_to_point(&lab, query);
            times.push(took);
            renders.push(Duration::from_secs_f64(point["seconds"].as_f64().unwrap()));
        }
        report(&format!("request to point, {name}"), &mut times);
        report(
            &format!("  of which the binary's render, {name}"),
            &mut renders,
        );
    }
}

/// Asks the accuracy page for `query` and waits for its point: the time
/// and the point.
fn request_to_point(lab: &lab::Lab, query: &str) -> (Duration, serde_json::Value) {
    let points = |body: &str| -> serde_json::Value {
        let json = body.split_once("\r\n\r\n").map_or("", |(_, b)| b);
        serde_json::from_str(json).unwrap()
    };
    let before = points(&get(lab, "api/accuracy"))["points"]
        .as_array()
        .unwrap()
        .len();
    let start = Instant::now();
    let asked = get(lab, &format!("api/accuracy/run?{query}"));
    assert!(asked.contains("\"asked\""), "{asked}");
    loop {
        let state = points(&get(lab, "api/accuracy"));
        let list = state["points"].as_array().unwrap();
        if list.len() > before {
            return (start.elapsed(), list[list.len() - 1].clone());
        }
        assert!(state["error"].is_null(), "{}", state["error"]);
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn touch(file: &PathBuf) {
    let text = std::fs::read(file).unwrap();
    std::fs::write(file, text).unwrap();
}

fn report(what: &str, times: &mut [Duration]) {
    times.sort();
    let at = |q: f64| times[((times.len() - 1) as f64 * q).round() as usize];
    eprintln!(
        "{what}: {} runs, median {:.1?}, 90th percentile {:.1?}, fastest {:.1?}, slowest {:.1?}",
        times.len(),
        at(0.5),
        at(0.9),
        times[0],
        times[times.len() - 1]
    );
}

/// The body of a GET below the lab's token.
fn get(lab: &lab::Lab, path: &str) -> String {
    let mut stream = TcpStream::connect(("127.0.0.1", lab.port())).unwrap();
    let host = format!("127.0.0.1:{}", lab.port());
    write!(
        stream,
        "GET /{}/{path} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n",
        lab.token()
    )
    .unwrap();
    let mut bytes = Vec::new();
    stream.read_to_end(&mut bytes).unwrap();
    String::from_utf8_lossy(&bytes).into_owned()
}
