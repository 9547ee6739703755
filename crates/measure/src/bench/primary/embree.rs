//! Embree's side: finding a Python that imports embreex, running
//! `embree_primary.py` on a scene's triangles and rays, and reading the
//! times and answers it reports.

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::bench::median;
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Shape;
use raybook::tracer::Ray;

/// The script that runs Embree; written next to the rays it reads, so the
/// bench works from any folder.
const SCRIPT: &str = include_str!("../embree_primary.py");

/// The environment variable naming the Python that runs Embree.
pub const PYTHON_VAR: &str = "RAYBOOK_PYTHON";

/// What the Embree column says where embreex cannot be imported.
const NOT_INSTALLED: &str = "not installed: pip install embreex numpy";

/// What Embree's script measured on one scene.
pub(super) struct EmbreeTimes {
    /// Median time of one thread.
    pub(super) seconds: f64,
    /// Median time of the processes at once, from the first one's start to
    /// the last one's end.
    pub(super) parallel_seconds: f64,
    /// The median over the runs of how many times as long as the fastest
    /// process the slowest took on its share (1 for one process). The
    /// slowest sets the time, while raybook's threads share out the work as
    /// they go (rayon).
    pub(super) uneven: f64,
    /// Each ray's hit distance, +∞ for a miss (from the one thread).
    pub(super) t: Vec<f32>,
}

/// Where Embree can run: a Python that imports embreex, and the script.
pub(super) struct Embree {
    pub(super) python: String,
    /// A temporary folder holding the script, and each scene's files while
    /// it is timed; removed when dropped.
    folder: PathBuf,
    /// embreex's version, as the script reports it.
    pub(super) version: String,
}

impl Drop for Embree {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.folder);
    }
}

impl Embree {
    /// Embree, if a Python ($RAYBOOK_PYTHON, else python3) can import
    /// embreex and numpy; else why not.
    pub(super) fn find() -> Result<Embree, String> {
        let python = std::env::var(PYTHON_VAR).unwrap_or_else(|_| "python3".into());
        let folder = std::env::temp_dir().join(format!("raybook-primary-{}", std::process::id()));
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
        let mut embree = Embree {
            python,
            folder,
            version: String::new(),
        };
        std::fs::write(embree.script(), SCRIPT)
            .map_err(|e| format!("cannot write {}: {e}", embree.script().display()))?;
        let check = Command::new(&embree.python)
            .arg(embree.script())
            .arg("--check")
            .stderr(Stdio::null())
            .output();
        match check {
            Ok(out) if out.status.success() => {
                embree.version = String::from_utf8_lossy(&out.stdout).trim().to_owned();
                Ok(embree)
            }
            _ => Err(NOT_INSTALLED.to_owned()),
        }
    }

    fn script(&self) -> PathBuf {
        self.folder.join("embree_primary.py")
    }

    /// Embree tracing `rays` against the triangles of `scene`, `runs` times
    /// on one thread and `runs` times in `processes` processes at once.
    pub(super) fn trace(
        &self,
        scene: &Scene,
        rays: &[Ray],
        runs: u32,
        processes: u32,
    ) -> Result<EmbreeTimes, String> {
        let folder = self.folder.join("scene");
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
        let result = self.trace_in(&folder, scene, rays, runs, processes);
        let _ = std::fs::remove_dir_all(&folder);
        result
    }

    fn trace_in(
        &self,
        folder: &Path,
        scene: &Scene,
        rays: &[Ray],
        runs: u32,
        processes: u32,
    ) -> Result<EmbreeTimes, String> {
        let corners = scene.objects.iter().flat_map(|o| match o.shape {
            Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => vertices,
            Shape::Sphere { .. } | Shape::Plane { .. } | Shape::Cone { .. } => {
                unreachable!("triangles only")
            }
        });
        write_f32(
            &folder.join("triangles.f32"),
            corners.flat_map(|v| v.to_array()),
        )?;
        let origins = rays.iter().flat_map(|r| r.origin.to_array());
        write_f32(&folder.join("origins.f32"), origins)?;
        let directions = rays.iter().flat_map(|r| r.direction.to_array());
        write_f32(&folder.join("directions.f32"), directions)?;
        let output = Command::new(&self.python)
            .arg(self.script())
            .arg(folder)
            .arg(runs.to_string())
            .arg(processes.to_string())
            .output()
            .map_err(|e| format!("cannot run {}: {e}", self.python))?;
        if !output.status.success() {
            let err = String::from_utf8_lossy(&output.stderr);
            return Err(format!("Embree's script failed: {}", err.trim()));
        }
        let report = String::from_utf8_lossy(&output.stdout);
        let seconds = median_seconds(&report, "seconds ", 1)?;
        // One process is the one thread: the script runs no more.
        let parallel = format!("parallel {processes} seconds ");
        let (parallel_seconds, uneven) = if processes > 1 {
            let uneven = busy_ratios(&report, &parallel);
            let uneven = if uneven.is_empty() {
                1.0
            } else {
                median(uneven)
            };
            (median_seconds(&report, &parallel, processes)?, uneven)
        } else {
            (seconds, 1.0)
        };
        let t = read_f32(&folder.join("t.f32"))?;
        if t.len() != rays.len() {
            return Err(format!(
                "Embree answered {} rays of {}",
                t.len(),
                rays.len()
            ));
        }
        Ok(EmbreeTimes {
            seconds,
            parallel_seconds,
            uneven,
            t,
        })
    }
}

/// The median wall time of the report's lines that start with `prefix`
/// (`seconds S cpu C`, or `parallel N seconds S cpu C ..`: the wall time
/// follows the prefix, the CPU time comes two words later). Warns if the
/// `cores` that were meant to trace used more than their time of CPU: then
/// more threads than those did the work.
fn median_seconds(report: &str, prefix: &str, cores: u32) -> Result<f64, String> {
    let wall = report_field(report, prefix, 0);
    let cpu = report_field(report, prefix, 2);
    if wall.is_empty() {
        return Err(format!(
            "Embree's script reported no `{}` times",
            prefix.trim()
        ));
    }
    if cpu
        .iter()
        .zip(&wall)
        .any(|(cpu, wall)| *cpu > 1.2 * f64::from(cores) * wall)
    {
        eprintln!("warning: Embree used more than {cores} cores' time while timed");
    }
    Ok(median(wall))
}

/// For each of the report's lines that start with `prefix` and end in
/// `busy B1 .. BN` (each process's time on its share), the slowest's time
/// over the fastest's.
fn busy_ratios(report: &str, prefix: &str) -> Vec<f64> {
    let ratio = |rest: &str| {
        let busy = rest.split_whitespace().skip_while(|w| *w != "busy").skip(1);
        let busy: Vec<f64> = busy.filter_map(|w| w.parse().ok()).collect();
        let slowest = busy.iter().copied().reduce(f64::max)?;
        let fastest = busy.iter().copied().reduce(f64::min)?;
        Some(slowest / fastest)
    };
    report
        .lines()
        .filter_map(|l| l.strip_prefix(prefix))
        .filter_map(ratio)
        .collect()
}

/// Writes numbers as raw little-endian f32.
fn write_f32(path: &Path, values: impl Iterator<Item = f32>) -> Result<(), String> {
    let fail = |e: std::io::Error| format!("cannot write {}: {e}", path.display());
    let mut file = BufWriter::new(std::fs::File::create(path).map_err(fail)?);
    for v in values {
        file.write_all(&v.to_le_bytes()).map_err(fail)?;
    }
    file.flush().map_err(fail)
}

/// Reads raw little-endian f32.
fn read_f32(path: &Path) -> Result<Vec<f32>, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    Ok(bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect())
}

/// In the lines of the script's report that start with `prefix`, the
/// number `index` words after the prefix.
fn report_field(report: &str, prefix: &str, index: usize) -> Vec<f64> {
    report
        .lines()
        .filter_map(|l| l.strip_prefix(prefix))
        .filter_map(|rest| rest.split_whitespace().nth(index)?.parse().ok())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{busy_ratios, median_seconds, report_field};

    #[test]
    fn the_times_are_read_from_the_scripts_report() {
        let report = "seconds 0.5 cpu 0.25\nnoise\nseconds 1.25 cpu 1.5\n\
                      parallel 2 seconds 0.75 cpu 1.5 busy 0.7 0.75\n\
                      parallel 3 seconds 9 cpu 9\n";
        assert_eq!(report_field(report, "seconds ", 0), [0.5, 1.25]);
        assert_eq!(report_field(report, "seconds ", 2), [0.25, 1.5]);
        let two = "parallel 2 seconds ";
        assert_eq!(report_field(report, two, 0), [0.75], "not 3 processes'");
        assert_eq!(report_field(report, two, 2), [1.5]);
        assert_eq!(median_seconds(report, "seconds ", 1), Ok(0.875));
        assert!(median_seconds("nothing", "seconds ", 1).is_err());
        assert!(median_seconds(report, "parallel 4 seconds ", 4).is_err());
        assert_eq!(busy_ratios(report, two), [0.75 / 0.7]);
        assert!(
            busy_ratios(report, "parallel 3 seconds ").is_empty(),
            "no busy times"
        );
    }
}
