//! The lab's routes, below `/TOKEN`: its own page, script and style (built
//! into the binary), the pictures it rendered (from memory), and a small
//! JSON API. Nothing else: no route reads a file named by the request.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::{Value, json};
use workbook::hint::{HintArgs, hint};

use crate::accuracy;
use crate::bench::reference_of;
use crate::chapter::bench_chapter;
use crate::pixel::{parse_pixel, trees};
use crate::work::State;

/// An answer: status, content type, body.
pub struct Answer {
    pub status: u16,
    pub content_type: &'static str,
    pub body: Vec<u8>,
}

impl Answer {
    fn ok(content_type: &'static str, body: impl Into<Vec<u8>>) -> Answer {
        Answer {
            status: 200,
            content_type,
            body: body.into(),
        }
    }

    fn json(value: &Value) -> Answer {
        Answer::ok("application/json", value.to_string())
    }

    /// A clear error for the page: `{"error": "..."}`.
    pub fn error(status: u16, message: impl Into<String>) -> Answer {
        Answer {
            status,
            content_type: "application/json",
            body: json!({"error": message.into()}).to_string().into_bytes(),
        }
    }

    pub fn not_found() -> Answer {
        Answer::error(404, "no such page")
    }
}

const PAGE: &str = include_str!("../assets/index.html");
const SCRIPT: &str = include_str!("../assets/lab.js");
const STYLE: &str = include_str!("../assets/lab.css");
const ACCURACY_SCRIPT: &str = include_str!("../assets/accuracy.js");

/// The query `a=1&b=2` as a map (values percent-decoded; `+` is a space).
fn query_map(query: &str) -> Result<BTreeMap<String, String>, String> {
    let mut map = BTreeMap::new();
    for pair in query.split('&').filter(|p| !p.is_empty()) {
        let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
        let decode = |s: &str| {
            crate::guard::percent_decoded(&s.replace('+', " "))
                .ok_or_else(|| format!("the query's {key:?} is not valid percent-encoded UTF-8"))
        };
        map.insert(decode(key)?, decode(value)?);
    }
    Ok(map)
}

/// Answers a request for `path` (below the token) with `query`.
pub fn answer(state: &State, path: &str, query: &str) -> Answer {
    let query = match query_map(query) {
        Ok(query) => query,
        Err(e) => return Answer::error(400, e),
    };
    let get = |key: &str| query.get(key).map(String::as_str);
    match path {
        "/" => Answer::ok("text/html; charset=utf-8", PAGE),
        "/lab.js" => Answer::ok("text/javascript; charset=utf-8", SCRIPT),
        "/accuracy.js" => Answer::ok("text/javascript; charset=utf-8", ACCURACY_SCRIPT),
        "/lab.css" => Answer::ok("text/css; charset=utf-8", STYLE),
        "/api/state" => Answer::json(&state.snapshot()),
        "/api/chapters" => Answer::json(&chapters()),
        "/api/bench" => with_chapter(get("chapter"), |folder| {
            state.want_bench(folder, get("again").is_some());
            Answer::json(&json!({"asked": folder, "version": state.version()}))
        }),
        "/api/pixel" => with_chapter(get("chapter"), |folder| {
            match (parse_pixel(get("x"), get("y")), bench_chapter(folder)) {
                (Ok(pixel), Ok(entry)) => match state.slow.take() {
                    Some(_slot) => Answer::json(&trees(&state.root, entry, pixel)),
                    None => Slots::busy(),
                },
                (Err(e), _) | (_, Err(e)) => Answer::error(400, e),
            }
        }),
        "/api/hint" => hint_answer(&state.slow, get("id"), get("level")),
        "/api/accuracy" => Answer::json(&state.accuracy.snapshot()),
        "/api/accuracy/study" => match accuracy::study(&state.root) {
            Ok(study) => Answer::json(&study),
            Err(e) => Answer::error(500, e),
        },
        "/api/accuracy/run" => match accuracy::Settings::parse(get) {
            Ok(settings) => match state.accuracy.start(&state.root, settings) {
                Ok(()) => Answer::json(&json!({"asked": settings.name()})),
                Err(e) => Answer::error(409, e),
            },
            Err(e) => Answer::error(400, e),
        },
        "/api/accuracy/picture.png" => match state.accuracy.picture() {
            Some(bytes) => Answer::ok("image/png", bytes),
            None => Answer::not_found(),
        },
        _ => picture(state, path),
    }
}

/// How many requests that run a process of the student's (a pixel's
/// trees, a level-3 hint's tests) are answered at once: two of the lab's
/// four threads. Each may take a minute (`chapter::PATIENCE`: code that
/// loops for ever), and every arrow key the page sees asks for a pixel: the
/// other two threads keep answering the page's polls, whatever the
/// student's code does.
pub const SLOW_AT_ONCE: usize = 2;

/// The slow requests running, at most [`SLOW_AT_ONCE`].
#[derive(Default)]
pub struct Slots(AtomicUsize);

/// A slow request's place among [`SLOW_AT_ONCE`], given back when dropped.
pub struct Slot<'a>(&'a AtomicUsize);

impl Slots {
    /// A place for a slow request, if one is free.
    pub fn take(&self) -> Option<Slot<'_>> {
        (self.0)
            .fetch_update(Ordering::SeqCst, Ordering::SeqCst, |n| {
                (n < SLOW_AT_ONCE).then_some(n + 1)
            })
            .ok()
            .map(|_| Slot(&self.0))
    }

    /// The answer when none is free: `busy`, so that the page asks again
    /// while it still wants this answer.
    fn busy() -> Answer {
        let error = "the lab is still working out two earlier answers (a pixel's trees or a \
                     hint's tests, with your code); ask again when one has arrived";
        Answer {
            status: 503,
            content_type: "application/json",
            body: json!({"error": error, "busy": true})
                .to_string()
                .into_bytes(),
        }
    }
}

impl Drop for Slot<'_> {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// The chapters with a bench, for the page before progress has run.
fn chapters() -> Value {
    let list: Vec<Value> = crate::chapter::benches()
        .iter()
        .map(|c| json!({"folder": c.folder, "number": c.number(), "title": c.title}))
        .collect();
    Value::Array(list)
}

/// Runs `then` with a valid chapter folder, or answers with the error.
fn with_chapter(name: Option<&str>, then: impl FnOnce(&str) -> Answer) -> Answer {
    let Some(name) = name else {
        return Answer::error(400, "which chapter? add ?chapter=02-hits");
    };
    match bench_chapter(name) {
        Ok(chapter) => then(&chapter.folder),
        Err(e) => Answer::error(400, e),
    }
}

/// The workbook's own hint of exercise `id` at `level` (1 to 4: level 4,
/// the answer, is refused by `hint` itself until the student has tried).
fn hint_answer(slow: &Slots, id: Option<&str>, level: Option<&str>) -> Answer {
    let Some(id) = id else {
        return Answer::error(400, "which exercise? add ?id=ch02-sphere");
    };
    let level = match level.unwrap_or("1").parse::<u8>() {
        Ok(level @ 1..=4) => level,
        _ => {
            return Answer::error(
                400,
                format!(
                    "a hint's level is 1, 2, 3 or 4 (the answer, after an attempt), not {:?}",
                    level.unwrap_or("")
                ),
            );
        }
    };
    // Level 3 runs the chapter's tests.
    let _slot = match level {
        3.. => match slow.take() {
            Some(slot) => Some(slot),
            None => return Slots::busy(),
        },
        _ => None,
    };
    let args = HintArgs {
        id: id.to_owned(),
        level,
    };
    match hint(&args) {
        Ok(text) => Answer::json(&json!({"id": id, "level": level, "text": text})),
        Err(e) => Answer::error(400, e),
    }
}

/// `/pictures/FOLDER/{yours,reference,difference}.png`: a picture the lab
/// holds in memory, or the reference built into the workbook.
fn picture(state: &State, path: &str) -> Answer {
    let Some(rest) = path.strip_prefix("/pictures/") else {
        return Answer::not_found();
    };
    let Some((folder, file)) = rest.split_once('/') else {
        return Answer::not_found();
    };
    let Ok(chapter) = bench_chapter(folder) else {
        return Answer::not_found();
    };
    let bytes = match file {
        "reference.png" => reference_of(chapter).ok().map(|r| r.png.to_vec()),
        "yours.png" => state.picture(folder, "yours"),
        "difference.png" => state.picture(folder, "difference"),
        _ => None,
    };
    match bytes {
        Some(bytes) => Answer::ok("image/png", bytes),
        None => Answer::not_found(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slow_requests_leave_threads_for_the_page() {
        let slots = Slots::default();
        let first = slots.take().expect("a first place");
        let second = slots.take().expect("a second place");
        assert!(slots.take().is_none(), "no third at once");
        drop(first);
        let third = slots.take().expect("a place given back is free again");
        assert!(slots.take().is_none());
        drop((second, third));
        assert_eq!(slots.0.load(Ordering::SeqCst), 0);
        let busy: Value = serde_json::from_slice(&Slots::busy().body).unwrap();
        assert_eq!(busy["busy"], true, "the page asks again");
    }
}
