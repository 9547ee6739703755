//! The lab's HTTP/1.1 server, small and bounded: one GET per connection,
//! answered and closed.
//!
//! Every limit is here, because a server on the loopback address answers
//! every local user and every page of the student's browser:
//!
//! * at most [`MAX_CONNECTIONS`] connections at once; one more is told
//!   `503` and closed at once (no thread, no buffer for it);
//! * a connection has [`HEAD_DEADLINE`] to send its request's line and
//!   headers, in all (not per byte: a client that sends one byte a second
//!   is cut off as surely as one that sends nothing): then `408`;
//! * a head is at most [`MAX_HEAD`] bytes: then `431`, without reading more;
//! * the lab takes no request body: one announced is refused with `413`
//!   before a byte of it is read;
//! * an answer the client does not read is given up after [`WRITE_TIMEOUT`],
//!   so that no worker waits longer on a client.
//!
//! A connection's head is read in a thread of its own, so that idle or
//! slow clients hold only their own threads (at most [`MAX_CONNECTIONS`]);
//! the lab's workers see only requests that have arrived whole.

use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::routes::Answer;

/// Connections open at once, at most: the page holds a few (its polls, its
/// pictures), the browser's other tabs of the lab a few more.
pub const MAX_CONNECTIONS: usize = 64;

/// The longest request head (line and headers): a browser's is under 2 KiB.
pub const MAX_HEAD: usize = 8 * 1024;

/// How long a client has to send its whole head: a browser sends it at once.
pub const HEAD_DEADLINE: Duration = Duration::from_secs(10);

/// How long writing an answer may take, in all, to a client that does not
/// read it (the lab's answers fit in the socket's buffers: never, in use).
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(10);

/// The headers on every answer, errors included: the page's own script and
/// nothing else, never a guessed type, never a copy kept, no address sent on
/// to another site, and no frame of another site's around the page (a click
/// there would be one it stole).
const SAFETY_HEADERS: [(&str, &str); 4] = [
    ("Cache-Control", "no-store"),
    ("X-Content-Type-Options", "nosniff"),
    ("Referrer-Policy", "no-referrer"),
    (
        "Content-Security-Policy",
        "default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; \
         frame-ancestors 'none'; base-uri 'none'; form-action 'none'",
    ),
];

/// A request's line and headers.
pub struct Request {
    pub method: String,
    /// The raw target, such as `/TOKEN/api/state?x=1`.
    pub target: String,
    headers: Vec<(String, String)>,
}

impl Request {
    /// The value of header `name` (any case), if sent.
    pub fn header(&self, name: &str) -> Option<&str> {
        (self.headers.iter())
            .find(|(field, _)| field.eq_ignore_ascii_case(name))
            .map(|(_, value)| value.as_str())
    }
}

/// An open connection, counted among [`MAX_CONNECTIONS`] until dropped.
struct Connection {
    stream: TcpStream,
    open: Arc<AtomicUsize>,
}

impl Drop for Connection {
    fn drop(&mut self) {
        self.open.fetch_sub(1, Ordering::SeqCst);
    }
}

/// A request that arrived whole, and the connection to answer it on.
type Job = (Request, Connection);

/// Accepts connections on `listener` for ever, in the background, and has
/// `workers` threads answer their requests with `handle`.
pub fn serve<H>(listener: TcpListener, workers: usize, handle: H)
where
    H: Fn(&Request) -> Answer + Send + Sync + 'static,
{
    let (jobs, waiting) = sync_channel::<Job>(MAX_CONNECTIONS);
    let (waiting, handle) = (Arc::new(Mutex::new(waiting)), Arc::new(handle));
    for _ in 0..workers {
        let (waiting, handle) = (waiting.clone(), handle.clone());
        std::thread::spawn(move || work(&waiting, &*handle));
    }
    std::thread::spawn(move || accept(&listener, &jobs));
}

/// A worker: answers the requests that have arrived, one after another.
fn work(waiting: &Mutex<Receiver<Job>>, handle: &dyn Fn(&Request) -> Answer) {
    loop {
        let job = match waiting.lock() {
            Ok(waiting) => waiting.recv(),
            Err(_) => return,
        };
        let Ok((request, mut connection)) = job else {
            return;
        };
        write_answer(&mut connection.stream, &handle(&request));
    }
}

/// The accepting loop. It never ends: a failed accept (no descriptor left,
/// say) is waited out, not taken as the end of the server.
fn accept(listener: &TcpListener, jobs: &SyncSender<Job>) {
    let open = Arc::new(AtomicUsize::new(0));
    loop {
        let Ok((stream, _)) = listener.accept() else {
            std::thread::sleep(Duration::from_millis(50));
            continue;
        };
        let connection = Connection {
            stream,
            open: open.clone(),
        };
        if open.fetch_add(1, Ordering::SeqCst) >= MAX_CONNECTIONS {
            // A few bytes into an empty socket: never blocks this loop.
            write_answer(&mut { connection }.stream, &too_many());
            continue;
        }
        let jobs = jobs.clone();
        // A thread that cannot start drops the connection it was given.
        let _ = std::thread::Builder::new().spawn(move || read_request(connection, &jobs));
    }
}

/// A connection's thread: reads its head within the limits and hands the
/// request to the workers, or answers why not.
fn read_request(mut connection: Connection, jobs: &SyncSender<Job>) {
    match read_head(&mut connection.stream).and_then(|head| parse_head(&head)) {
        Ok(request) => match refused_body(&request) {
            Some(answer) => refuse(connection, &answer),
            None => {
                let _ = jobs.send((request, connection));
            }
        },
        Err(Some(answer)) => refuse(connection, &answer),
        Err(None) => {}
    }
}

/// Answers `answer` and closes. What the client sent and the lab did not
/// read is read first (a little, briefly): a socket closed with unread
/// bytes is reset, and the reset can overtake the answer.
fn refuse(mut connection: Connection, answer: &Answer) {
    write_answer(&mut connection.stream, answer);
    let deadline = Instant::now() + Duration::from_millis(500);
    let (mut chunk, mut drained) = ([0u8; 4096], 0);
    while drained < 64 * 1024 {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() || connection.stream.set_read_timeout(Some(left)).is_err() {
            return;
        }
        match connection.stream.read(&mut chunk) {
            Ok(0) | Err(_) => return,
            Ok(read) => drained += read,
        }
    }
}

/// The answer when [`MAX_CONNECTIONS`] are open.
fn too_many() -> Answer {
    Answer::error(503, "the lab has too many connections open; ask again soon")
}

/// A request with a body, which the lab never reads: `413`.
fn refused_body(request: &Request) -> Option<Answer> {
    let length = request.header("Content-Length").map(str::trim);
    let announced = request.header("Transfer-Encoding").is_some()
        || length.is_some_and(|l| l != "0")
        || request.header("Expect").is_some();
    announced.then(|| Answer::error(413, "the lab takes no request body"))
}

/// The head's bytes, without the blank line that ends it; Err(None) if the
/// client left first, Err(Some(answer)) if it broke a limit.
fn read_head(stream: &mut TcpStream) -> Result<Vec<u8>, Option<Answer>> {
    let deadline = Instant::now() + HEAD_DEADLINE;
    let mut head = Vec::with_capacity(1024);
    let mut chunk = [0u8; 1024];
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            return Err(Some(Answer::error(
                408,
                "the request took too long to arrive",
            )));
        }
        stream.set_read_timeout(Some(left)).map_err(|_| None)?;
        let read = match stream.read(&mut chunk) {
            Ok(0) => return Err(None),
            Ok(read) => read,
            Err(e) if is_timeout(&e) => continue,
            Err(_) => return Err(None),
        };
        // Look for the end only where it can be new: the last 3 bytes and on.
        let from = head.len().saturating_sub(3);
        head.extend_from_slice(&chunk[..read]);
        if let Some(end) = (head[from..].windows(4)).position(|w| w == b"\r\n\r\n") {
            head.truncate(from + end);
            return Ok(head);
        }
        if head.len() > MAX_HEAD {
            return Err(Some(Answer::error(
                431,
                "the request's headers are too long",
            )));
        }
    }
}

fn is_timeout(e: &std::io::Error) -> bool {
    matches!(
        e.kind(),
        std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
    )
}

/// `GET /target HTTP/1.1` and `Name: value` lines, or `400`.
fn parse_head(head: &[u8]) -> Result<Request, Option<Answer>> {
    let bad = |why: &str| Some(Answer::error(400, format!("a malformed request: {why}")));
    let text = std::str::from_utf8(head).map_err(|_| bad("not UTF-8"))?;
    let mut lines = text.split("\r\n");
    let line = lines.next().unwrap_or("");
    let mut parts = line.split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(bad("its first line is not METHOD TARGET VERSION"));
    };
    if !version.starts_with("HTTP/1.") || !target.starts_with('/') {
        return Err(bad("not an HTTP/1 request for a path"));
    }
    let mut headers = Vec::new();
    for line in lines {
        let (field, value) = line
            .split_once(':')
            .ok_or_else(|| bad("a header without ':'"))?;
        headers.push((field.trim().to_owned(), value.trim().to_owned()));
    }
    Ok(Request {
        method: method.to_owned(),
        target: target.to_owned(),
        headers,
    })
}

/// Writes `answer` with the [`SAFETY_HEADERS`], and closes the sending side.
fn write_answer(stream: &mut TcpStream, answer: &Answer) {
    let mut head = format!(
        "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nConnection: close\r\n",
        answer.status,
        reason(answer.status),
        answer.content_type,
        answer.body.len()
    );
    for (field, value) in SAFETY_HEADERS {
        head.push_str(&format!("{field}: {value}\r\n"));
    }
    head.push_str("\r\n");
    let deadline = Instant::now() + WRITE_TIMEOUT;
    let _ = write_by(stream, head.as_bytes(), deadline)
        .and_then(|()| write_by(stream, &answer.body, deadline));
    let _ = stream.shutdown(Shutdown::Write);
}

/// Writes all of `bytes` before `deadline`, or fails: a client that reads
/// a byte now and then cannot stretch the answer past it.
fn write_by(stream: &mut TcpStream, mut bytes: &[u8], deadline: Instant) -> std::io::Result<()> {
    while !bytes.is_empty() {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            return Err(std::io::ErrorKind::TimedOut.into());
        }
        stream.set_write_timeout(Some(left))?;
        match stream.write(bytes) {
            Ok(0) => return Err(std::io::ErrorKind::WriteZero.into()),
            Ok(written) => bytes = &bytes[written..],
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(())
}

/// The reason phrase of the statuses the lab answers with.
fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        409 => "Conflict",
        413 => "Content Too Large",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "Internal Server Error",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_head_is_its_line_and_headers() {
        let head = b"GET /abc/api/state?x=1 HTTP/1.1\r\nHost: 127.0.0.1:8000\r\nX-A:  b ";
        let request = parse_head(head).ok().unwrap();
        assert_eq!(
            (request.method.as_str(), request.target.as_str()),
            ("GET", "/abc/api/state?x=1")
        );
        assert_eq!(request.header("host"), Some("127.0.0.1:8000"));
        assert_eq!(request.header("X-A"), Some("b"));
        assert_eq!(request.header("Cookie"), None);
        for bad in [
            &b"GET /"[..],
            b"GET / HTTP/2",
            b"GET x HTTP/1.1",
            b"GET / HTTP/1.1\r\nX",
            b"\xff",
        ] {
            assert!(matches!(parse_head(bad), Err(Some(_))), "{bad:?}");
        }
    }

    /// A client that never reads holds a writer no longer than its deadline.
    #[test]
    fn an_unread_answer_is_given_up_at_its_deadline() {
        let listener = TcpListener::bind(("127.0.0.1", 0)).unwrap();
        let _client = TcpStream::connect(listener.local_addr().unwrap()).unwrap();
        let (mut stream, _) = listener.accept().unwrap();
        let start = Instant::now();
        let bytes = vec![0u8; 256 << 20];
        let written = write_by(&mut stream, &bytes, start + Duration::from_millis(500));
        assert!(written.is_err(), "256 MiB fit in the buffers?");
        assert!(
            start.elapsed() < Duration::from_secs(3),
            "{:?}",
            start.elapsed()
        );
    }
}
