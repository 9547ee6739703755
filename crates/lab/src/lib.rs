//! The lab: the student's bench in the browser. `cargo run -q -p lab`
//! serves a page on this machine that shows
//!
//! * the chapters in order with `workbook progress`'s findings (passed,
//!   failed, the next exercise, the first failure) and `workbook hint`'s
//!   three levels one click away;
//! * a chapter's bench: the student's picture of its default scene,
//!   rendered by their own chapter binary at the snapshot size (160×120),
//!   the reference picture, a map of where they differ with the regions
//!   outlined, and `workbook verify`'s diagnosis;
//! * any pixel's ray tree, clicked in any of the three pictures (or moved to
//!   with the arrow keys): the student's from their binary's `--pixel X,Y
//!   --json` beside the reference's from the facts committed beside the
//!   snapshots (`workbook::verify::tree::facts`), the first difference
//!   highlighted as `verify --tree` finds it;
//! * on chapter 7's bench, what accuracy costs, live ([`accuracy`]): the
//!   student's chapter-7 binary renders a depth, threshold, rays per pixel
//!   and seed in the background, and the page plots its error against the
//!   carried reference (the study's MSE), its rays and its time beside the
//!   study's curves from `accuracy.csv`;
//! * live: a save under `chapters/` rebuilds and renders the edited chapter
//!   and runs progress again; the page polls and updates by itself.
//!
//! It is a crate of its own, so that `progress` in a fresh handout builds
//! nothing more; everything it knows comes from the workbook's library
//! (progress, hint, verify), so that when they change, the lab follows.
//!
//! # The HTTP server: tiny_http
//!
//! The lab needs a few routes on the loopback address, answered from a
//! handful of threads: no async runtime, no routing framework. tiny_http
//! (0.12, of the tiny-http organisation, used by many tools for exactly
//! this) is a blocking HTTP/1.1 server with four small dependencies (ascii,
//! chunked_transfer, httpdate, log). Measured in a fresh target folder on
//! this 2-core machine under load: `cargo build -p tiny_http` took 1.6 s
//! of CPU (4.0 s wall), where an async stack (tokio, hyper) costs tens of
//! seconds; the lab's own code then adds about 1 s to what `progress` has
//! built already (the workbook and its dependencies, which it reuses).
//!
//! # Safety
//!
//! The server binds 127.0.0.1 only; every path starts with a random 128-bit
//! token that is in the address it prints; a request whose Host header is
//! not the loopback address is refused (a page of another site that
//! rebinds its name to 127.0.0.1 sends its own name); it serves only its own
//! page and the pictures it rendered, never a file named by the request
//! ([`guard`]). Answers carry a content security policy that allows the
//! page's own script and nothing else, and no page of another site may
//! frame it (`frame-ancestors 'none'`: no click on the page can be one a
//! hidden frame stole).

pub mod accuracy;
pub mod bench;
pub mod chapter;
pub mod guard;
pub mod pixel;
pub mod reference_svg;
pub mod routes;
pub mod work;

use std::path::PathBuf;
use std::sync::Arc;

use tiny_http::{Header, Request, Response, Server};

use guard::Verdict;
use routes::Answer;
use work::State;

/// A lab serving on the loopback address.
pub struct Lab {
    server: Arc<Server>,
    state: Arc<State>,
    token: String,
    port: u16,
}

/// How many requests are answered at once: a pixel's trees take a process
/// of the student's (about 10 ms), a level-3 hint a test run.
const THREADS: usize = 4;

impl Lab {
    /// Binds 127.0.0.1:`port` (0: any free port) for the workspace at
    /// `root`. With `live`, runs progress at once and watches `chapters/`
    /// for saves; without, works only when the page asks (the tests).
    pub fn start(root: PathBuf, port: u16, live: bool) -> Result<Lab, String> {
        let server = Server::http(("127.0.0.1", port))
            .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = server
            .server_addr()
            .to_ip()
            .map(|a| a.port())
            .ok_or("the server has no IP address")?;
        let (state, queues) = State::new(root);
        state.start_workers(queues, live)?;
        Ok(Lab {
            server: Arc::new(server),
            state,
            token: guard::new_token()?,
            port,
        })
    }

    /// The page's address, with its token.
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/{}/", self.port, self.token)
    }

    pub fn port(&self) -> u16 {
        self.port
    }

    pub fn token(&self) -> &str {
        &self.token
    }

    /// Answers requests in [`THREADS`] threads, in the background.
    pub fn serve_in_background(&self) {
        for _ in 0..THREADS {
            let (server, state) = (self.server.clone(), self.state.clone());
            let (token, port) = (self.token.clone(), self.port);
            std::thread::spawn(move || {
                for request in server.incoming_requests() {
                    respond(request, &state, &token, port);
                }
            });
        }
    }

    /// Answers requests until the process ends.
    pub fn serve(&self) {
        self.serve_in_background();
        loop {
            std::thread::park();
        }
    }
}

/// Bodies up to this length tiny_http reads into memory at once (and
/// drops safely); a longer one, or one after `Expect: 100-continue`, is
/// read from the connection only when asked, or when the request drops.
const BUFFERED_BODY: usize = 1024;

/// Does `request` announce a body that tiny_http would stream, not buffer?
fn announces_a_streamed_body(request: &Request) -> bool {
    let expects = (request.headers().iter()).any(|h| h.field.equiv("Expect"));
    match request.body_length() {
        Some(length) => length > BUFFERED_BODY || (expects && length > 0),
        None => false,
    }
}

/// Checks and answers one request.
fn respond(request: Request, state: &State, token: &str, port: u16) {
    if announces_a_streamed_body(&request) {
        // tiny_http 0.12 drains an unread body when the request is dropped
        // (as `respond` does) with one buffer of the whole announced length:
        // `Content-Length: 100000000000` aborts the process, and a body
        // announced and never sent holds this thread for ever. The lab
        // reads no body; such a request is left unanswered, its connection
        // open: what any idle connection costs, and no more.
        std::mem::forget(request);
        return;
    }
    let host = request
        .headers()
        .iter()
        .find(|h| h.field.equiv("Host"))
        .map(|h| h.value.as_str().to_owned());
    let answer = if *request.method() != tiny_http::Method::Get {
        Answer::error(405, "the lab answers GET requests only")
    } else {
        match guard::check(request.url(), host.as_deref(), token, port) {
            Verdict::Allowed { path, query } => routes::answer(state, &path, query),
            Verdict::ForeignHost => Answer::error(
                403,
                "refused: the Host header is not the loopback address (127.0.0.1 or localhost)",
            ),
            Verdict::NotFound => Answer::not_found(),
        }
    };
    let mut response = Response::from_data(answer.body).with_status_code(answer.status);
    for (field, value) in [
        ("Content-Type", answer.content_type),
        ("Cache-Control", "no-store"),
        ("X-Content-Type-Options", "nosniff"),
        ("Referrer-Policy", "no-referrer"),
        (
            "Content-Security-Policy",
            "default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; \
             frame-ancestors 'none'; base-uri 'none'",
        ),
    ] {
        if let Ok(header) = Header::from_bytes(field.as_bytes(), value.as_bytes()) {
            response.add_header(header);
        }
    }
    let _ = request.respond(response);
}
