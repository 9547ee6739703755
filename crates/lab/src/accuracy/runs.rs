//! The page's renders, each on a thread of its own, so that a slow
//! setting never blocks the page: it asks, then polls [`Runs::snapshot`].

use std::path::Path;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use serde_json::{Value, json};

use super::{CHAPTER, Point, Settings, measure_telling};

/// The most points the page keeps (the latest): every poll sends them
/// all, so a page left asking for renders all day would otherwise grow the
/// lab's memory and each answer without end.
const MOST_POINTS: usize = 200;

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
        self.claim(settings)?;
        let root = root.to_owned();
        let runs = self.clone();
        self.run_in_background(move || {
            let work = root.join("target/lab");
            let phase = |now: &'static str| runs.lock().phase = now;
            let measured = measure_telling(&root, &settings, &work, &phase);
            let picture = std::fs::read(work.join(CHAPTER).join("accuracy.png")).ok();
            measured.map(|point| (point, picture))
        });
        Ok(())
    }

    /// Marks `settings` as the render running, unless one runs already.
    fn claim(&self, settings: Settings) -> Result<(), String> {
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
        Ok(())
    }

    /// Runs `job` on a thread of its own and records what it gives. A
    /// panic of the job is recorded as an error too: the render is over
    /// either way, or the page would wait for it, and refuse every other
    /// setting, until the lab stops.
    fn run_in_background(
        &self,
        job: impl FnOnce() -> Result<(Point, Option<Vec<u8>>), String> + Send + 'static,
    ) {
        let runs = self.clone();
        std::thread::spawn(move || {
            let measured = std::panic::catch_unwind(std::panic::AssertUnwindSafe(job))
                .unwrap_or_else(|_| {
                    Err("the render stopped on a panic of the lab's own (see its terminal)".into())
                });
            let mut inner = runs.lock();
            inner.running = None;
            match measured {
                Ok((point, picture)) => {
                    if inner.points.len() == MOST_POINTS {
                        inner.points.remove(0);
                    }
                    inner.points.push(point);
                    inner.picture = picture;
                }
                Err(e) => inner.error = Some(e),
            }
        });
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::accuracy::Rays;

    const SETTINGS: Settings = Settings {
        max_depth: 2,
        min_weight: 0.0,
        rays: Rays::Centre,
        seed: 0,
    };

    /// Waits (at most 10 s) until no render runs; the snapshot then.
    fn when_done(runs: &Runs) -> Value {
        let started = Instant::now();
        while runs.lock().running.is_some() {
            assert!(started.elapsed().as_secs() < 10, "the render never ended");
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        runs.snapshot()
    }

    #[test]
    fn a_render_that_panics_ends_and_frees_the_page() {
        let runs = Runs::default();
        runs.claim(SETTINGS).unwrap();
        assert!(runs.claim(SETTINGS).unwrap_err().contains("runs already"));
        runs.run_in_background(|| panic!("a bug of the lab's"));
        let snapshot = when_done(&runs);
        assert!(snapshot["running"].is_null());
        assert!(snapshot["error"].as_str().unwrap().contains("panic"));
        assert!(runs.claim(SETTINGS).is_ok(), "another setting may run");
    }

    #[test]
    fn the_page_keeps_the_latest_points_only() {
        let runs = Runs::default();
        for rays in 0..MOST_POINTS as u64 + 3 {
            runs.claim(SETTINGS).unwrap();
            let point = Point {
                settings: SETTINGS,
                name: SETTINGS.name(),
                rmse: 0.0,
                mse: 0.0,
                rays,
                seconds: 0.0,
                wall_seconds: 0.0,
            };
            runs.run_in_background(move || Ok((point, None)));
            when_done(&runs);
        }
        let points = runs.snapshot()["points"].as_array().unwrap().clone();
        assert_eq!(points.len(), MOST_POINTS);
        assert_eq!(points[0]["rays"], 3, "the oldest went first");
    }
}
