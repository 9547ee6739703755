//! The lab's work, in the background so that the page never waits on it:
//! one thread runs `progress` (each chapter's tests), another builds and
//! renders the chapter the page shows, and a third watches `chapters/` for
//! saves and asks both again. The page polls [`State::snapshot`], which
//! carries a version that grows with every change.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use serde_json::{Value, json};
use workbook::hint::offered;
use workbook::progress::{self, ChapterResult, ProgressArgs};

use crate::bench::{self, Bench, Pictures};
use crate::chapter;

/// What the page can see, shared by the threads.
#[derive(Default)]
struct Inner {
    version: u64,
    /// What runs now: shown as the progress indicator.
    busy: BTreeMap<&'static str, String>,
    /// The progress table's rows and its advice, once run.
    rows: Option<Value>,
    advice: Option<String>,
    progress_error: Option<String>,
    benches: BTreeMap<String, Bench>,
    pictures: BTreeMap<String, Pictures>,
    /// The chapter the page shows, rendered again on a save.
    shown: Option<String>,
    /// A picture asked for by a save and not rendered yet: progress waits
    /// for it, so that its build does not hold cargo's lock first.
    picture_pending: bool,
}

/// The lab's state and the queues of its workers.
pub struct State {
    pub root: PathBuf,
    /// Chapter 7's accuracy page: its renders, on threads of their own.
    pub accuracy: crate::accuracy::Runs,
    /// The requests that run a process of the student's, answered at once.
    pub slow: crate::routes::Slots,
    inner: Mutex<Inner>,
    benches: Sender<(String, Option<Instant>)>,
    tests: Sender<Option<PathBuf>>,
}

impl State {
    /// The state of a lab for the workspace at `root`, and its two workers'
    /// queues (started by [`State::start_workers`]).
    pub fn new(root: PathBuf) -> (Arc<State>, Queues) {
        let (benches, bench_jobs) = mpsc::channel();
        let (tests, test_jobs) = mpsc::channel();
        let state = Arc::new(State {
            root,
            accuracy: Default::default(),
            slow: Default::default(),
            inner: Mutex::default(),
            benches,
            tests,
        });
        (
            state,
            Queues {
                bench_jobs,
                test_jobs,
            },
        )
    }

    fn lock(&self) -> MutexGuard<'_, Inner> {
        self.inner.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Changes the state and tells the page so.
    fn change(&self, change: impl FnOnce(&mut Inner)) {
        let mut inner = self.lock();
        change(&mut inner);
        inner.version += 1;
    }

    /// The page asks for a chapter's bench: it is rendered unless it was
    /// (or `again`).
    pub fn want_bench(&self, folder: &str, again: bool) {
        let queue = {
            let mut inner = self.lock();
            inner.shown = Some(folder.to_owned());
            again || !inner.benches.contains_key(folder)
        };
        if queue {
            let _ = self.benches.send((folder.to_owned(), None));
        }
    }

    /// Asks for progress to run again (after a save of `saved`).
    pub fn want_progress(&self, saved: Option<PathBuf>) {
        let _ = self.tests.send(saved);
    }

    /// A picture of a chapter's bench: `yours` or `difference`.
    pub fn picture(&self, folder: &str, which: &str) -> Option<Vec<u8>> {
        let inner = self.lock();
        let pictures = inner.pictures.get(folder)?;
        match which {
            "yours" => pictures.student.clone(),
            "difference" => pictures.difference.clone(),
            _ => None,
        }
    }

    /// Everything the page shows but the pictures and trees.
    pub fn snapshot(&self) -> Value {
        let inner = self.lock();
        json!({
            "version": inner.version,
            "busy": inner.busy.values().collect::<Vec<_>>(),
            "rows": inner.rows,
            "advice": inner.advice,
            "progress_error": inner.progress_error,
            "benches": inner.benches,
            "shown": inner.shown,
        })
    }

    pub fn version(&self) -> u64 {
        self.lock().version
    }

    /// Starts the workers on `queues`; with `live`, runs progress now and
    /// watches `chapters/` for saves.
    pub fn start_workers(self: &Arc<Self>, queues: Queues, live: bool) -> Result<(), String> {
        let state = self.clone();
        std::thread::spawn(move || state.bench_worker(queues.bench_jobs));
        let state = self.clone();
        std::thread::spawn(move || state.test_worker(queues.test_jobs));
        if live {
            self.want_progress(None);
            let (watcher, saves) = progress::watch::saves(&self.root)?;
            let state = self.clone();
            std::thread::spawn(move || {
                let _watcher = watcher;
                while let Ok(saved) = progress::watch::next_save(&saves) {
                    state.saved(saved);
                }
            });
        }
        Ok(())
    }

    /// A file under chapters/ was saved: its chapter (or the one shown) is
    /// rendered again, and progress runs again.
    fn saved(&self, saved: Option<PathBuf>) {
        let at = Instant::now();
        let edited = saved.as_deref().and_then(|p| chapter_of(&self.root, p));
        let folder = edited.or_else(|| self.lock().shown.clone());
        if let Some(folder) = folder {
            let mut inner = self.lock();
            inner.shown = Some(folder.clone());
            inner.picture_pending = true;
            let _ = self.benches.send((folder, Some(at)));
        }
        self.want_progress(saved);
    }

    fn bench_worker(&self, jobs: Receiver<(String, Option<Instant>)>) {
        while let Ok(job) = jobs.recv() {
            // Those asked meanwhile, each chapter once (the earliest save).
            let mut queue = vec![job];
            while let Ok((folder, saved_at)) = jobs.try_recv() {
                match queue.iter_mut().find(|(f, _)| *f == folder) {
                    Some(queued) => queued.1 = queued.1.or(saved_at),
                    None => queue.push((folder, saved_at)),
                }
            }
            for (folder, saved_at) in queue {
                self.bench(folder, saved_at);
            }
        }
    }

    /// Builds and renders a chapter's bench.
    fn bench(&self, folder: String, saved_at: Option<Instant>) {
        let Ok(entry) = chapter::bench_chapter(&folder) else {
            return;
        };
        self.change(|i| {
            i.busy
                .insert("bench", format!("building and rendering chapter {folder}…"));
        });
        let (mut bench, pictures) = bench::run(&self.root, entry, &self.root.join("target/lab"));
        bench.since_save = saved_at.map(|t| t.elapsed().as_secs_f64());
        self.change(|i| {
            i.busy.remove("bench");
            i.benches.insert(folder.clone(), bench);
            i.pictures.insert(folder, pictures);
            i.picture_pending = false;
        });
    }

    fn test_worker(&self, jobs: Receiver<Option<PathBuf>>) {
        while let Ok(mut saved) = jobs.recv() {
            while let Ok(later) = jobs.try_recv() {
                saved = later.or(saved);
            }
            // The saved chapter's picture first (at most a minute).
            let waiting = Instant::now();
            while self.lock().picture_pending && waiting.elapsed().as_secs() < 60 {
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            self.change(|i| {
                i.busy
                    .insert("tests", "testing the chapters (progress)…".into());
            });
            let results = progress::results(&self.root, &ProgressArgs::default(), saved.as_deref());
            self.change(|i| {
                i.busy.remove("tests");
                match results {
                    Ok(results) => {
                        i.rows = Some(rows(&results, &self.root));
                        let here = progress::here(&results);
                        i.advice = Some(progress::next_step(&results, here, &self.root));
                        i.progress_error = None;
                    }
                    Err(e) => i.progress_error = Some(e),
                }
            });
        }
    }
}

/// The workers' queues, until they start.
pub struct Queues {
    bench_jobs: Receiver<(String, Option<Instant>)>,
    test_jobs: Receiver<Option<PathBuf>>,
}

/// The chapter folder a saved file belongs to, if it is a bench chapter's.
fn chapter_of(root: &Path, file: &Path) -> Option<String> {
    let relative = file.strip_prefix(root).unwrap_or(file);
    let mut parts = relative.components();
    (parts.next()?.as_os_str() == "chapters").then_some(())?;
    let folder = parts.next()?.as_os_str().to_str()?;
    chapter::bench_chapter(folder)
        .ok()
        .map(|c| c.folder.clone())
}

/// The progress table's rows, as the page shows them.
fn rows(results: &[ChapterResult], root: &Path) -> Value {
    let here = progress::here(results);
    let rows: Vec<Value> = results
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let output = r.output.as_ref();
            let next = r.next_exercise(root).map(|(file, line, region)| {
                json!({"id": region.id, "file": file, "line": line, "hint": region.hint})
            });
            // The answer (hint level 4) is offered as `workbook hint` offers
            // it: after an attempt that compiles (`hint::offered`).
            let answer = |region| output.is_some_and(|o| offered(region, o).is_ok());
            let exercises: Vec<Value> = (r.exercises.iter())
                .map(|(_, _, region)| {
                    json!({"id": region.id, "open": region.is_open(), "answer": answer(region)})
                })
                .collect();
            json!({
                "folder": r.chapter.folder,
                "number": r.chapter.number(),
                "title": r.chapter.title,
                "run": output.is_some(),
                "passed": output.map(|o| o.passed),
                "failed": output.map(|o| o.failed),
                "passes": output.is_some_and(|o| o.passed_all()),
                "exercises": r.exercises_done(),
                "exercise_list": exercises,
                "failure": r.first_failure(root),
                "reused": r.reused,
                "here": Some(i) == here,
                "next": next,
                "bench": r.chapter.verify.is_some(),
            })
        })
        .collect();
    Value::Array(rows)
}
