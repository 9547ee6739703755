//! The lab's server refuses what a local server must: requests without its
//! token, requests from another host name (DNS rebinding), paths that
//! escape (also percent-encoded), and answers bad input with a clear error
//! and never a panic. Plain HTTP over a socket, against a lab on a free
//! port that runs nothing in the background (no progress, no watching).

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::sync::OnceLock;

use lab::Lab;

/// One lab for the whole test binary.
fn lab() -> &'static Lab {
    static LAB: OnceLock<Lab> = OnceLock::new();
    LAB.get_or_init(|| {
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
        let lab = Lab::start(root, 0, false).expect("the lab starts");
        lab.serve_in_background();
        lab
    })
}

/// Sends a GET of `target` with the Host header `host` (none if None);
/// the status and the body.
fn get_with_host(target: &str, host: Option<&str>) -> (u16, String) {
    let mut stream = TcpStream::connect(("127.0.0.1", lab().port())).unwrap();
    let host = host.map(|h| format!("Host: {h}\r\n")).unwrap_or_default();
    write!(
        stream,
        "GET {target} HTTP/1.1\r\n{host}Connection: close\r\n\r\n"
    )
    .unwrap();
    let mut bytes = Vec::new();
    stream.read_to_end(&mut bytes).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    let status = text
        .split(' ')
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    let body = text.split_once("\r\n\r\n").map(|(_, b)| b).unwrap_or("");
    (status, body.to_owned())
}

fn get(target: &str) -> (u16, String) {
    let host = format!("127.0.0.1:{}", lab().port());
    get_with_host(target, Some(&host))
}

/// `target` below the lab's token.
fn below(path: &str) -> String {
    format!("/{}{path}", lab().token())
}

#[test]
fn the_page_needs_the_token() {
    let (status, body) = get(&below("/"));
    assert_eq!(status, 200);
    assert!(body.contains("<title>raybook lab</title>"), "{body}");
    assert_eq!(get(&below("/lab.js")).0, 200);
    assert_eq!(get("/").0, 404);
    assert_eq!(get("/lab.js").0, 404);
    let wrong = format!("/{}/", "0".repeat(32));
    assert_eq!(get(&wrong).0, 404);
    assert!(lab().url().starts_with("http://127.0.0.1:"));
}

#[test]
fn a_foreign_host_is_refused() {
    let port = lab().port();
    for host in [
        format!("evil.example:{port}"),
        format!("127.0.0.1.evil.example:{port}"),
        "evil.example".to_owned(),
    ] {
        let (status, body) = get_with_host(&below("/"), Some(&host));
        assert_eq!(status, 403, "{host}");
        assert!(body.contains("not the loopback address"), "{body}");
    }
    assert_eq!(get_with_host(&below("/"), None).0, 403, "no Host at all");
    let local = format!("localhost:{port}");
    assert_eq!(get_with_host(&below("/"), Some(&local)).0, 200);
}

#[test]
fn escaping_paths_get_404() {
    for path in [
        "/../Cargo.toml",
        "/%2e%2e/Cargo.toml",
        "/%2E%2E%2FCargo.toml",
        "/pictures/02-hits/../../../../etc/passwd",
        "/pictures/02-hits/%2e%2e%2f%2e%2e%2fCargo.toml",
        "/pictures/..%2f..%2fsnapshots/02-hits/flat.snap.png",
        "/pictures/02-hits/..%5c..%5cCargo.toml",
        "/Cargo.toml",
        "/snapshots/02-hits/flat.snap.png",
        "/pictures/02-hits/yours.png%00.png",
        "//etc/passwd",
    ] {
        let (status, _) = get(&below(path));
        assert_eq!(status, 404, "{path}");
    }
    // The reference pictures are its own.
    assert_eq!(get(&below("/pictures/02-hits/reference.png")).0, 200);
}

#[test]
fn bad_input_gets_a_clear_error() {
    let cases = [
        (
            "/api/pixel?chapter=99-nope&x=1&y=1",
            "no chapter \"99-nope\"; the chapters are 01-rays",
        ),
        (
            "/api/pixel?chapter=02-hits&x=abc&y=1",
            "whole number from 0 to 159",
        ),
        (
            "/api/pixel?chapter=02-hits&x=1&y=500",
            "outside the picture, which is 160×120",
        ),
        ("/api/pixel?chapter=02-hits&x=1", "the pixel's y is missing"),
        ("/api/pixel?x=1&y=1", "which chapter?"),
        (
            "/api/bench?chapter=..%2F02-hits",
            "no chapter \"../02-hits\"",
        ),
        ("/api/hint?id=ch02-nope", "no exercise \"ch02-nope\""),
        (
            "/api/hint?id=ch02-sphere&level=7",
            "a hint's level is 1, 2, 3 or 4",
        ),
        ("/api/hint?id=%ff", "not valid percent-encoded UTF-8"),
        (
            "/api/accuracy/run?max_depth=65&min_weight=0&rays=centre",
            "maximum depth is a whole number from 0 to 64",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=-1&rays=centre",
            "weight threshold is a number from 0 to 1",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=0&rays=3&seed=1",
            "a square number of jittered rays",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=0&rays=4",
            "the seed is a whole number",
        ),
        (
            "/api/accuracy/run?max_depth=1e309&min_weight=0&rays=centre",
            "maximum depth is a whole number from 0 to 64",
        ),
        (
            "/api/accuracy/run?max_depth=4294967296&min_weight=0&rays=centre",
            "maximum depth is a whole number from 0 to 64",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=1e309&rays=centre",
            "weight threshold is a number from 0 to 1",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=inf&rays=centre",
            "weight threshold is a number from 0 to 1",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=0&rays=4294967296&seed=1",
            "a square number of jittered rays",
        ),
        (
            "/api/accuracy/run?max_depth=6&min_weight=0&rays=16&seed=18446744073709551616",
            "the seed is a whole number",
        ),
    ];
    for (path, expected) in cases {
        let (status, body) = get(&below(path));
        assert_eq!(status, 400, "{path}: {body}");
        let error: serde_json::Value = serde_json::from_str(&body).unwrap();
        let error = error["error"].as_str().unwrap();
        assert!(error.contains(expected), "{path}: {error}");
    }
    // The server still answers after all of them.
    assert_eq!(get(&below("/api/state")).0, 200);
}

/// The page's answers tell the browser to run its own script only, never
/// to guess a type, never to keep a copy, and never to show the page in a
/// frame of another site's (a click there would be one it stole).
#[test]
fn answers_carry_the_safety_headers() {
    let port = lab().port();
    let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
    let target = below("/");
    write!(
        stream,
        "GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut text = String::new();
    stream.read_to_string(&mut text).unwrap();
    let head = text.split("\r\n\r\n").next().unwrap().to_ascii_lowercase();
    for header in [
        "x-content-type-options: nosniff",
        "cache-control: no-store",
        "referrer-policy: no-referrer",
        "content-security-policy: default-src 'self'",
        "frame-ancestors 'none'",
    ] {
        assert!(head.contains(header), "{header} missing from:\n{head}");
    }
}

/// A request that announces a body (even one too long to hold) is refused
/// with 413 before any of it is sent, and the lab answers on.
#[test]
fn an_announced_body_is_refused_unread() {
    let port = lab().port();
    for length in ["100000000000", "18446744073709551615", "5000", "1"] {
        let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
        stream
            .set_read_timeout(Some(std::time::Duration::from_secs(20)))
            .unwrap();
        let target = below("/api/state");
        write!(
            stream,
            "GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Length: {length}\r\n\r\n"
        )
        .unwrap();
        let mut text = String::new();
        let read = stream.read_to_string(&mut text);
        assert!(read.is_ok(), "no answer within 20 s: {read:?}");
        assert!(text.starts_with("HTTP/1.1 413"), "{length}: {text}");
    }
    assert_eq!(get(&below("/api/state")).0, 200);
}

/// The API answers the page's own requests, and the student's typed
/// address, but not a request the browser marks as another site's.
#[test]
fn the_api_refuses_other_sites_requests() {
    let port = lab().port();
    let ask = |site: &str| {
        let mut stream = TcpStream::connect(("127.0.0.1", port)).unwrap();
        let target = below("/api/state");
        write!(
            stream,
            "GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nSec-Fetch-Site: {site}\r\n\r\n"
        )
        .unwrap();
        let mut text = String::new();
        stream.read_to_string(&mut text).unwrap();
        text.split(' ').nth(1).unwrap_or("").to_owned()
    };
    assert_eq!(ask("same-origin"), "200");
    assert_eq!(ask("none"), "200");
    assert_eq!(ask("cross-site"), "403");
    assert_eq!(ask("same-site"), "403");
}
