//! `bench --primary`: how many primary rays a second one thread traces with
//! raybook's BVH, and with Embree 4 on the same rays and the same triangles.
//!
//! The rays are the renderer's own: one per pixel, through its centre, from
//! chapter 1's [`Camera`] ([`primary_rays`]). raybook traces them with
//! `closest_hit` against [`primary_world`] (the complete tracer's four-wide
//! BVH, [`raybook::wide`]), on one thread
//! and on `--threads` threads; Embree traces them through the PyPI package
//! embreex, run by `crates/measure/src/bench/embree_primary.py` in a Python that can import
//! it, on one thread and in `--threads` processes at once. Only the tracing
//! is timed on either side: not making the rays, not building either BVH,
//! not passing the files. The two answers are compared ray by ray (hit or
//! miss, and the distance), so that the table shows they did the same work.
//!
//! Why Embree runs in `--threads` processes too: on a machine whose cores
//! slow each other down (hyperthreads sharing a core, or a VM's cores when
//! its host is busy), a thread traces fewer rays a second while the others
//! are busy. raybook's throughput per thread on
//! `--threads` threads is then fairly compared only with Embree's per
//! process on as many processes, both under the same contention; the table
//! keeps the comparison with Embree's one thread beside it. Each process
//! traces blocks of 256 rays dealt out in turn, so that the shares cost
//! alike (contiguous shares, the busier rows in one, took up to 1.4 times
//! as long as the other), as raybook's threads share out the work as they
//! go: the report notes where Embree's slowest process still took more
//! than 1.1 times its fastest's time, since that lowers Embree's
//! throughput on the threads.

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use rayon::prelude::*;

use super::{BenchArgs, median, scene_name, scene_progress, table};
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Shape;
use raybook::tracer::{Camera, Ray, World};

/// The script that runs Embree; written next to the rays it reads, so the
/// bench works from any folder.
const SCRIPT: &str = include_str!("embree_primary.py");

/// The environment variable naming the Python that runs Embree.
pub const PYTHON_VAR: &str = "RAYBOOK_PYTHON";

/// What the Embree column says where embreex cannot be imported.
const NOT_INSTALLED: &str = "not installed: pip install embreex numpy";

/// What the Embree column says for a scene with spheres or planes.
const TRIANGLES_ONLY: &str = "n/a (embreex has triangles only)";

/// Above this ratio of Embree's slowest process's time to its fastest's,
/// the report notes how unevenly its shares of the rays cost.
const UNEVEN: f64 = 1.1;

/// Two distances agree if they differ by at most this fraction.
const T_TOLERANCE: f32 = 1e-4;

/// The world primary rays are traced against: the complete tracer's
/// ([`raybook::world`]), the one `raybook render` uses.
pub fn primary_world(scene: &Scene) -> impl World + '_ {
    raybook::world(scene)
}

/// The primary rays of `scene` at its image size, row by row from the top
/// left: one per pixel, through the pixel's centre, as the renderer makes
/// them with one sample per pixel ([`Camera::primary_ray`]).
pub fn primary_rays(scene: &Scene) -> Vec<Ray> {
    let (width, height) = (scene.image.width, scene.image.height);
    let camera = Camera::new(&scene.camera, width, height);
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| camera.primary_ray(x, y))
        .collect()
}

/// The distance to the closest hit of each ray, +∞ where it hits nothing:
/// `closest_hit` for t in [0, ∞), as the tracer asks for a primary ray.
pub fn hit_distances(world: &(impl World + ?Sized), rays: &[Ray]) -> Vec<f32> {
    let mut t = vec![0.0; rays.len()];
    trace_serial(world, rays, &mut t);
    t
}

fn closest_t(world: &(impl World + ?Sized), ray: &Ray) -> f32 {
    world
        .closest_hit(ray, 0.0, f32::INFINITY)
        .map_or(f32::INFINITY, |hit| hit.t)
}

/// On this thread, one ray after the other.
fn trace_serial(world: &(impl World + ?Sized), rays: &[Ray], t: &mut [f32]) {
    for (ray, t) in rays.iter().zip(t) {
        *t = closest_t(world, ray);
    }
}

/// On the current rayon pool's threads.
fn trace_parallel(world: &(impl World + ?Sized), rays: &[Ray], t: &mut [f32]) {
    rays.par_iter()
        .zip(t.par_iter_mut())
        .for_each(|(ray, t)| *t = closest_t(world, ray));
}

/// One scene's row.
struct PrimaryTiming {
    name: String,
    primitives: usize,
    rays: usize,
    hits: usize,
    /// raybook's median time on one thread.
    serial_seconds: f64,
    /// The same with chapter 8's binary BVH, the lesson's.
    chapter8_seconds: f64,
    /// raybook's median time on all the threads.
    parallel_seconds: f64,
    embree: EmbreeResult,
}

/// Embree's side of a row.
enum EmbreeResult {
    /// Why Embree did not run.
    Skipped(String),
    Timed {
        /// Median time of one thread.
        seconds: f64,
        /// Median time of as many processes as raybook's threads, each
        /// tracing its share of the rays (one thread's time if that is 1).
        parallel_seconds: f64,
        /// How many times as long as the fastest process the slowest took.
        uneven: f64,
        /// How its answers agree with raybook's.
        agreement: Agreement,
    },
}

/// What Embree's script measured on one scene.
struct EmbreeTimes {
    /// Median time of one thread.
    seconds: f64,
    /// Median time of the processes at once, from the first one's start to
    /// the last one's end.
    parallel_seconds: f64,
    /// The median over the runs of how many times as long as the fastest
    /// process the slowest took on its share (1 for one process). The
    /// slowest sets the time, while raybook's threads share out the work as
    /// they go (rayon).
    uneven: f64,
    /// Each ray's hit distance, +∞ for a miss (from the one thread).
    t: Vec<f32>,
}

/// Where Embree can run: a Python that imports embreex, and the script.
struct Embree {
    python: String,
    /// A temporary folder holding the script, and each scene's files while
    /// it is timed; removed when dropped.
    folder: PathBuf,
    /// embreex's version, as the script reports it.
    version: String,
}

impl Drop for Embree {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.folder);
    }
}

impl Embree {
    /// Embree, if a Python ($RAYBOOK_PYTHON, else python3) can import
    /// embreex and numpy; else why not.
    fn find() -> Result<Embree, String> {
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
    fn trace(
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

/// How far two tracers' answers to the same rays agree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Agreement {
    pub rays: usize,
    /// Rays one tracer calls a hit and the other a miss.
    pub hit_or_miss_differs: usize,
    /// Rays both hit.
    pub both_hit: usize,
    /// Rays both hit whose distances differ by more than `T_TOLERANCE` (10⁻⁴)
    /// of the larger.
    pub t_differs: usize,
}

impl Agreement {
    /// The fraction of rays both call a hit or both a miss.
    pub fn hit_or_miss(&self) -> f64 {
        fraction_but(self.hit_or_miss_differs, self.rays)
    }

    /// Of the rays both hit, the fraction whose distances agree (1 if none).
    pub fn t(&self) -> f64 {
        fraction_but(self.t_differs, self.both_hit)
    }
}

/// The fraction of `of` things that are not among `but`; 1 of none.
fn fraction_but(but: usize, of: usize) -> f64 {
    if of == 0 {
        1.0
    } else {
        (of - but) as f64 / of as f64
    }
}

/// Compares two tracers' hit distances for the same rays (+∞ for a miss).
pub fn agreement(ours: &[f32], theirs: &[f32]) -> Agreement {
    assert_eq!(ours.len(), theirs.len(), "the same rays");
    let pairs = || ours.iter().zip(theirs);
    let both = || pairs().filter(|(a, b)| a.is_finite() && b.is_finite());
    Agreement {
        rays: ours.len(),
        hit_or_miss_differs: pairs()
            .filter(|(a, b)| a.is_finite() != b.is_finite())
            .count(),
        both_hit: both().count(),
        t_differs: both()
            .filter(|&(a, b)| (a - b).abs() > T_TOLERANCE * a.max(*b))
            .count(),
    }
}

/// Whether every object is a triangle, which is all embreex can trace.
fn triangles_only(scene: &Scene) -> bool {
    scene.objects.iter().all(|o| {
        matches!(
            o.shape,
            Shape::Triangle { .. } | Shape::SmoothTriangle { .. }
        )
    })
}

/// The table of primary-ray throughput, under lines saying how it was
/// measured.
pub(super) fn report(args: &BenchArgs, threads: u32, scenes: &[PathBuf]) -> Result<String, String> {
    let embree = if args.no_embree {
        Err("not run (--no-embree)".to_owned())
    } else {
        Embree::find()
    };
    if let Err(why) = &embree {
        eprintln!("note: Embree: {why}; timing raybook alone");
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads as usize)
        .build()
        .map_err(|e| e.to_string())?;
    let bar = scene_progress(scenes.len(), args.quiet);
    let mut timings = Vec::with_capacity(scenes.len());
    for path in scenes {
        bar.set_message(scene_name(path));
        let scene = raybook::nff::load(path)
            .map_err(|e| e.to_string())?
            .with_size(args.size, args.size);
        timings.push(time_scene(
            scene_name(path),
            &scene,
            args.runs,
            &pool,
            &embree,
        )?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let (size, runs) = (args.size, args.runs);
    let embree_line = match &embree {
        Ok(e) => format!(
            "Embree 4 through {} ({}), one thread and {threads} processes at once",
            e.version, e.python
        ),
        Err(why) => format!("Embree: {why}"),
    };
    let mut out = format!(
        "{size}×{size} primary rays (one per pixel, through its centre), closest hit against \
         the complete tracer's four-wide BVH, 1 and {threads} threads; {embree_line}; median of {runs} runs, \
         tracing only (no ray making, no BVH build)\n\n{}",
        timings_table(&timings, threads)
    );
    for t in &timings {
        if let EmbreeResult::Timed { agreement, .. } = t.embree
            && agreement.hit_or_miss() < 0.999
        {
            out += &format!(
                "\nwarning: {}: raybook and Embree agree on hit or miss for only {:.3} % of the rays",
                t.name,
                agreement.hit_or_miss() * 100.0
            );
        }
    }
    for t in &timings {
        if let EmbreeResult::Timed { uneven, .. } = t.embree
            && uneven > UNEVEN
        {
            out += &format!(
                "\nnote: {}: Embree's slowest process took {uneven:.2} times as long as its \
                 fastest (median of the runs), and its time on {threads} threads is the \
                 slowest's",
                t.name
            );
        }
    }
    Ok(out)
}

/// Times raybook, and Embree if it can, on the primary rays of `scene`.
fn time_scene(
    name: String,
    scene: &Scene,
    runs: u32,
    pool: &rayon::ThreadPool,
    embree: &Result<Embree, String>,
) -> Result<PrimaryTiming, String> {
    let rays = primary_rays(scene);
    let world = primary_world(scene);
    let binary = ch08_bvh::Bvh::build(&scene.objects);
    let (mut serial, mut parallel, mut chapter8) = (Vec::new(), Vec::new(), Vec::new());
    let mut t = vec![0.0f32; rays.len()];
    let mut t_parallel = vec![0.0f32; rays.len()];
    let mut t_chapter8 = vec![0.0f32; rays.len()];
    for _ in 0..runs {
        let start = Instant::now();
        trace_serial(&world, &rays, &mut t);
        serial.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        trace_serial(&binary, &rays, &mut t_chapter8);
        chapter8.push(start.elapsed().as_secs_f64());
        let start = Instant::now();
        pool.install(|| trace_parallel(&world, &rays, &mut t_parallel));
        parallel.push(start.elapsed().as_secs_f64());
    }
    if t != t_parallel {
        return Err(format!(
            "{name}: the threads found other hits than one thread"
        ));
    }
    if t != t_chapter8 {
        return Err(format!("{name}: chapter 8's BVH found other hits"));
    }
    let embree = match embree {
        Err(why) => EmbreeResult::Skipped(why.clone()),
        Ok(_) if !triangles_only(scene) => EmbreeResult::Skipped(TRIANGLES_ONLY.into()),
        Ok(embree) => {
            let threads = pool.current_num_threads() as u32;
            let theirs = embree.trace(scene, &rays, runs, threads)?;
            EmbreeResult::Timed {
                seconds: theirs.seconds,
                parallel_seconds: theirs.parallel_seconds,
                uneven: theirs.uneven,
                agreement: agreement(&t, &theirs.t),
            }
        }
    };
    Ok(PrimaryTiming {
        name,
        primitives: scene.objects.len(),
        rays: rays.len(),
        hits: t.iter().filter(|t| t.is_finite()).count(),
        serial_seconds: median(serial),
        chapter8_seconds: median(chapter8),
        parallel_seconds: median(parallel),
        embree,
    })
}

/// The timings as a Markdown table, one row per scene.
///
/// Each side has a one-thread column and a per-thread column at `threads`;
/// the ratios compare one thread with one thread, raybook's threads with
/// Embree's one thread (the bench's first measure, which charges raybook
/// alone for threads that slow each other down), and each side's threads
/// with the other's, run under the same contention.
fn timings_table(timings: &[PrimaryTiming], threads: u32) -> String {
    let per_thread = format!("raybook Mrays/s per thread, {threads} threads");
    let embree_per_thread = format!("Embree Mrays/s per thread, {threads} threads");
    let old_ratio = format!("raybook per thread, {threads} threads / Embree 1 thread");
    let same_ratio = format!("raybook per thread / Embree per thread, {threads} threads");
    let header = [
        "scene",
        "primitives",
        "rays",
        "hits",
        "chapter 8's BVH Mrays/s, 1 thread",
        "raybook Mrays/s, 1 thread",
        &per_thread,
        "Embree Mrays/s, 1 thread",
        &embree_per_thread,
        "raybook 1 thread / Embree 1 thread",
        &old_ratio,
        &same_ratio,
        "hit/miss agree",
        "t agrees (1e-4)",
    ];
    table::markdown(header, timings.iter().map(|t| t.cells(threads)), 1)
}

impl PrimaryTiming {
    /// The table's cells for this scene; where Embree did not run, its
    /// throughput cells say why and the others are dashes.
    fn cells(&self, threads: u32) -> [String; 14] {
        let mrays = |seconds: f64| self.rays as f64 / seconds / 1e6;
        let threads = f64::from(threads);
        let per_thread = mrays(self.parallel_seconds) / threads;
        let [
            embree,
            embree_per_thread,
            serial_ratio,
            old_ratio,
            ratio,
            hits_agree,
            t_agrees,
        ] = match &self.embree {
            EmbreeResult::Skipped(why) => {
                let dash = || "–".to_owned();
                [
                    why.clone(),
                    why.clone(),
                    dash(),
                    dash(),
                    dash(),
                    dash(),
                    dash(),
                ]
            }
            EmbreeResult::Timed {
                seconds,
                parallel_seconds,
                agreement,
                ..
            } => {
                let (one, each) = (mrays(*seconds), mrays(*parallel_seconds) / threads);
                let percent =
                    |f: f64, differ: usize| format!("{:.3} % ({differ} differ)", f * 100.0);
                [
                    format!("{one:.2}"),
                    format!("{each:.2}"),
                    format!("{:.2}", mrays(self.serial_seconds) / one),
                    format!("{:.2}", per_thread / one),
                    format!("{:.2}", per_thread / each),
                    percent(agreement.hit_or_miss(), agreement.hit_or_miss_differs),
                    percent(agreement.t(), agreement.t_differs),
                ]
            }
        };
        [
            self.name.clone(),
            self.primitives.to_string(),
            self.rays.to_string(),
            self.hits.to_string(),
            format!("{:.2}", mrays(self.chapter8_seconds)),
            format!("{:.2}", mrays(self.serial_seconds)),
            format!("{per_thread:.2}"),
            embree,
            embree_per_thread,
            serial_ratio,
            old_ratio,
            ratio,
            hits_agree,
            t_agrees,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::{agreement, busy_ratios, median_seconds, report_field};

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

    #[test]
    fn agreement_counts_hits_misses_and_distances() {
        let inf = f32::INFINITY;
        let ours = [1.0, 2.0, inf, inf, 4.0];
        let theirs = [1.0, 2.1, inf, 3.0, 4.0001];
        let a = agreement(&ours, &theirs);
        assert_eq!(a.hit_or_miss_differs, 1, "a miss against a hit");
        assert_eq!(a.hit_or_miss(), 0.8);
        assert_eq!((a.both_hit, a.t_differs), (3, 1), "2.0 against 2.1 differs");
        assert_eq!(a.t(), 2.0 / 3.0, "4.0 against 4.0001 is within 1e-4");
        let none = agreement(&[inf], &[inf]);
        assert_eq!(
            (none.hit_or_miss(), none.t()),
            (1.0, 1.0),
            "no hits: all agree"
        );
    }
}
