//! The page's renders, each on a thread of its own, so that a slow
//! setting never blocks the page: it asks, then polls [`Runs::snapshot`].

use std::path::Path;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use serde_json::{Value, json};

use super::{CHAPTER, Point, Settings, measure_telling};

/// The page's renders: the one running, and the points measured.
#[derive(Default)]
struct Inner {
    running: Option<(Settings, Instant)>,
    /// What the running render does now: `building` or `rendering`.
    phase: &'static str,
    points: Vec<Point>,
    error: Option<String>,
    /// The latest render's picture, as PNG.
    picture: Option<Vec<u8>>,
}

/// The page's renders, shared with the thread that runs them.
#[derive(Clone, Default)]
pub struct Runs(Arc<Mutex<Inner>>);

impl Runs {
    fn lock(&self) -> MutexGuard<'_, Inner> {
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Starts a render of `settings` on a thread of its own, unless one
    /// runs: then Err says so.
    pub fn start(&self, root: &Path, settings: Settings) -> Result<(), String> {
        {
            let mut inner = self.lock();
            if let Some((running, _)) = &inner.running {
                return Err(format!(
                    "a render runs already ({}); wait for it",
                    running.name()
                ));
            }
            inner.running = Some((settings, Instant::now()));
            inner.phase = "starting";
            inner.error = None;
        }
        let (runs, root) = (self.clone(), root.to_owned());
        std::thread::spawn(move || {
            let work = root.join("target/lab");
            let phase = |now: &'static str| runs.lock().phase = now;
            let measured = measure_telling(&root, &settings, &work, &phase);
            let picture = std::fs::read(work.join(CHAPTER).join("accuracy.png")).ok();
            let mut inner = runs.lock();
            inner.running = None;
            match measured {
                Ok(point) => {
                    inner.points.push(point);
                    inner.picture = picture;
                }
                Err(e) => inner.error = Some(e),
            }
        });
        Ok(())
    }

    /// What the page shows: the render running (and for how long), the
    /// points, the last error.
    pub fn snapshot(&self) -> Value {
        let inner = self.lock();
        let running = inner.running.as_ref().map(|(settings, since)| {
            json!({
                "name": settings.name(),
                "phase": inner.phase,
                "seconds": since.elapsed().as_secs_f64(),
            })
        });
        json!({
            "running": running,
            "points": inner.points,
            "error": inner.error,
            "picture": inner.picture.is_some(),
        })
    }

    /// The latest render's picture.
    pub fn picture(&self) -> Option<Vec<u8>> {
        self.lock().picture.clone()
    }
}
