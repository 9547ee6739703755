//! Idle, slow, long-winded and too many clients cannot stop the lab: each
//! is cut off within its limit (`lab::http`), and the page is answered
//! meanwhile. Real sockets against a lab of each test's own, on a free port.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use lab::Lab;
use lab::http::{HEAD_DEADLINE, MAX_CONNECTIONS, MAX_HEAD};

fn lab() -> Lab {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let lab = Lab::start(root, 0, false).expect("the lab starts");
    lab.serve_in_background();
    lab
}

fn connect(lab: &Lab) -> TcpStream {
    TcpStream::connect(("127.0.0.1", lab.port())).unwrap()
}

/// The status `stream` is answered with within `patience` (0: none came),
/// and how long it took.
fn status_of(mut stream: TcpStream, patience: Duration) -> (u16, Duration) {
    let start = Instant::now();
    stream.set_read_timeout(Some(patience)).unwrap();
    let mut bytes = Vec::new();
    let _ = stream.read_to_end(&mut bytes);
    let text = String::from_utf8_lossy(&bytes);
    let status = (text.strip_prefix("HTTP/1.1 "))
        .and_then(|rest| rest.get(..3))
        .and_then(|code| code.parse().ok())
        .unwrap_or(0);
    (status, start.elapsed())
}

/// The page's state asked for on a new connection: its status.
fn the_page_asks(lab: &Lab) -> u16 {
    let mut stream = connect(lab);
    let (port, token) = (lab.port(), lab.token());
    write!(
        stream,
        "GET /{token}/api/state HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n"
    )
    .unwrap();
    status_of(stream, Duration::from_secs(5)).0
}

/// More silent connections than the lab has threads, and some that send
/// their head a byte at a time, do not keep the page from its answers.
#[test]
fn idle_and_slow_clients_leave_the_lab_answering() {
    let lab = lab();
    let mut held: Vec<TcpStream> = (0..16).map(|_| connect(&lab)).collect();
    for _ in 0..4 {
        let mut slow = connect(&lab);
        slow.write_all(b"GET /").unwrap();
        held.push(slow);
    }
    for _ in 0..8 {
        assert_eq!(the_page_asks(&lab), 200);
    }
    drop(held);
}

/// A client that sends nothing, and one that sends a byte every 200 ms, are
/// both told 408 when [`HEAD_DEADLINE`] has passed, and closed.
#[test]
fn a_head_that_does_not_arrive_in_time_is_given_up() {
    let lab = lab();
    let silent = connect(&lab);
    let mut dribbling = connect(&lab);
    let dribbler = std::thread::spawn(move || {
        let start = Instant::now();
        for byte in b"GET / HTTP/1.1\r\nX-Slow: ".iter().cycle() {
            if dribbling.write_all(&[*byte]).is_err() {
                break;
            }
            std::thread::sleep(Duration::from_millis(200));
        }
        start.elapsed()
    });
    let patience = HEAD_DEADLINE + Duration::from_secs(5);
    let (status, waited) = status_of(silent, patience);
    assert_eq!(status, 408, "after {waited:?}");
    assert!(
        waited < HEAD_DEADLINE + Duration::from_secs(2),
        "{waited:?}"
    );
    let cut_off = dribbler.join().unwrap();
    assert!(
        cut_off < HEAD_DEADLINE + Duration::from_secs(3),
        "{cut_off:?}"
    );
}

/// A head longer than [`MAX_HEAD`] is refused with 431 once that much has
/// arrived; a request announcing a body is refused with 413 before any of
/// it is sent.
#[test]
fn long_heads_and_bodies_are_refused_unread() {
    let lab = lab();
    let mut long = connect(&lab);
    let filler = "a".repeat(MAX_HEAD + 10);
    write!(long, "GET / HTTP/1.1\r\nX-Long: {filler}").unwrap();
    let (status, waited) = status_of(long, Duration::from_secs(5));
    assert_eq!(status, 431);
    assert!(waited < Duration::from_secs(2), "{waited:?}");
    for announced in [
        "Content-Length: 100000000000",
        "Content-Length: 18446744073709551615",
        "Content-Length: 5",
        "Transfer-Encoding: chunked",
    ] {
        let mut stream = connect(&lab);
        write!(stream, "POST / HTTP/1.1\r\n{announced}\r\n\r\n").unwrap();
        let (status, waited) = status_of(stream, Duration::from_secs(5));
        assert_eq!(status, 413, "{announced}");
        assert!(waited < Duration::from_secs(2), "{announced}: {waited:?}");
    }
    assert_eq!(the_page_asks(&lab), 200);
}

/// One connection more than [`MAX_CONNECTIONS`] is told 503 at once; when
/// the others close, the page is answered again.
#[test]
fn connections_beyond_the_cap_are_turned_away() {
    let lab = lab();
    let held: Vec<TcpStream> = (0..MAX_CONNECTIONS).map(|_| connect(&lab)).collect();
    std::thread::sleep(Duration::from_millis(200));
    let (status, waited) = status_of(connect(&lab), Duration::from_secs(5));
    assert_eq!(status, 503);
    assert!(waited < Duration::from_secs(2), "{waited:?}");
    drop(held);
    let start = Instant::now();
    while the_page_asks(&lab) != 200 {
        assert!(start.elapsed() < Duration::from_secs(5), "still refused");
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Malformed heads get 400 with the safety headers, as every answer does.
#[test]
fn malformed_heads_get_400_with_the_safety_headers() {
    let lab = lab();
    for head in [
        "NONSENSE",
        "GET http://evil.example/ HTTP/1.1",
        "GET / HTTP/1.1\r\nNoColon",
    ] {
        let mut stream = connect(&lab);
        write!(stream, "{head}\r\n\r\n").unwrap();
        stream
            .set_read_timeout(Some(Duration::from_secs(5)))
            .unwrap();
        let mut text = String::new();
        let _ = stream.read_to_string(&mut text);
        assert!(text.starts_with("HTTP/1.1 400"), "{head}: {text}");
        let lower = text.to_ascii_lowercase();
        for header in ["x-content-type-options: nosniff", "frame-ancestors 'none'"] {
            assert!(lower.contains(header), "{head}: {header} missing");
        }
    }
}
