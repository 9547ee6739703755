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
//! # The HTTP server: its own, in [`http`]
//!
//! The lab needs a few GET routes on the loopback address, answered from a
//! handful of threads: no async runtime, no routing framework, and no HTTP
//! crate. Earlier rounds used tiny_http 0.12; it offers no bound at all: no
//! read or write timeout, no cap on a header's length, a thread for every
//! connection with no cap on their number, a body drained with one buffer
//! of whatever length it announces, and an accept loop that ends for good
//! the first time accept fails (no descriptor left). A local user could stop
//! the lab or exhaust its memory. rouille is built on tiny_http and shares
//! all of it; hyper bounds each of these, but needs an async runtime (tokio),
//! tens of seconds of building before a student's first page. [`http`]
//! reads one request per connection within stated limits and answers it,
//! in about 300 lines a student reads.
//!
//! # Safety
//!
//! The server binds 127.0.0.1 only; every path starts with a random 128-bit
//! token (from the system's generator, compared in constant time) that is in
//! the address it prints; a request whose Host header is not the loopback
//! address is refused (a page of another site that rebinds its name to
//! 127.0.0.1 sends its own name); the API refuses a request the browser
//! marks as sent by another site (`Sec-Fetch-Site`), and answers GET only;
//! it serves only its own page and the pictures it rendered, never a file
//! named by the request ([`guard`]). Every answer, errors included, carries
//! a content security policy that allows the page's own script and nothing
//! else, and no page of another site may frame it (`frame-ancestors
//! 'none'`: no click on the page can be one a hidden frame stole).
//!
//! Idle and slow clients cannot stop it: connections, the time to send a
//! request, its length and the time to take an answer are all bounded, and
//! a request body is refused unread ([`http`]). The browser is not handed
//! the token on its command line (which every local user can read in
//! `/proc`): it opens a file only the student can read, which redirects to
//! the address ([`launch`]).

pub mod accuracy;
pub mod bench;
pub mod chapter;
pub mod guard;
pub mod http;
pub mod launch;
pub mod pixel;
pub mod reference_svg;
pub mod routes;
pub mod work;

use std::net::TcpListener;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use guard::Verdict;
use routes::Answer;
use work::State;

/// A lab serving on the loopback address.
pub struct Lab {
    listener: Mutex<Option<TcpListener>>,
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
        let listener = TcpListener::bind(("127.0.0.1", port))
            .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
        let port = (listener.local_addr())
            .map_err(|e| format!("the server has no address: {e}"))?
            .port();
        let (state, queues) = State::new(root);
        state.start_workers(queues, live)?;
        Ok(Lab {
            listener: Mutex::new(Some(listener)),
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

    /// Answers requests in [`THREADS`] threads, in the background (once:
    /// a second call does nothing).
    pub fn serve_in_background(&self) {
        let Some(listener) = self.listener.lock().ok().and_then(|mut l| l.take()) else {
            return;
        };
        let (state, token, port) = (self.state.clone(), self.token.clone(), self.port);
        http::serve(listener, THREADS, move |request| {
            respond(request, &state, &token, port)
        });
    }

    /// Answers requests until the process ends.
    pub fn serve(&self) {
        self.serve_in_background();
        loop {
            std::thread::park();
        }
    }
}

/// Checks and answers one request.
fn respond(request: &http::Request, state: &State, token: &str, port: u16) -> Answer {
    if request.method != "GET" {
        return Answer::error(405, "the lab answers GET requests only");
    }
    match guard::check(&request.target, request.header("Host"), token, port) {
        Verdict::Allowed { path, .. }
            if path.starts_with("/api/")
                && guard::sent_by_another_site(request.header("Sec-Fetch-Site")) =>
        {
            Answer::error(403, "refused: the lab's API answers its own page only")
        }
        Verdict::Allowed { path, query } => routes::answer(state, &path, query),
        Verdict::ForeignHost => Answer::error(
            403,
            "refused: the Host header is not the loopback address (127.0.0.1 or localhost)",
        ),
        Verdict::NotFound => Answer::not_found(),
    }
}
