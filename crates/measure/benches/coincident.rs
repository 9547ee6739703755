//! What chapter 2's rule for coincident surfaces costs: the closest hit of
//! every primary ray with the rule (`closest_hit`) against the nearest hit
//! alone (`nearest_hit`, or chapter 2's `closest_hit_by` for a list).
//!
//! The rule costs something only when the nearest hit's object is not the
//! first listed: a second look through the objects listed before it (a
//! list); for the wide BVH, the window of the nearest hit, worked out after
//! the one walk that found it and kept the hits that may lie in it
//! (`src/wide/rule.rs`), and, for the rare ray whose window reaches past
//! what the walk kept, a second walk. Rays that hit nothing cost nothing
//! more.
//!
//! Run with `cargo bench --bench coincident`. As in `--bench small`, the
//! two are timed in alternation, round after round, and the median of the
//! per-round ratios is printed; here the time is the thread's CPU time, and
//! each way goes first in every other round (on a machine shared with
//! other builds, wall times and a fixed order moved the ratios by ±10%).
//!
//! For instruction counts, which do not move with the machine's load, set
//! `BENCH_WAY` to `nearest`, `rule` or `none` (and optionally `BENCH_SCENE`
//! to one scene's name): each scene's rays are then traced once that way
//! only (`BENCH_ROUNDS` times, for a sampling profiler), with no table,
//! under `valgrind --tool=callgrind target/release/deps/coincident-…`. The rule's
//! cost in instructions is (rule − none) / (nearest − none): `none` counts
//! what loading the scene and building its tree take.

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;
#[cfg(not(unix))]
use std::time::Instant;

use measure::bench::median;
use raybook::scene_files::{self, nff};
use raybook::toolkit::Scene;
use raybook::toolkit::scene::{Object, Shape};
use raybook::tracer::{Camera, Hit, Ray, World, closest_hit, closest_hit_by, intersect};
use raybook::wide::WideBvh;

const INF: f32 = f32::INFINITY;

fn scenes() -> Vec<(&'static str, Scene)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let toml = |path: &str| scene_files::load(root.join(path)).unwrap();
    let spd = |name: &str| nff::load(root.join("scenes/spd").join(name)).unwrap();
    vec![
        (
            "chapter 2 coincident",
            toml("chapters/02-hits/scenes/coincident.toml"),
        ),
        (
            "chapter 5",
            toml("chapters/05-reflection/scenes/default.toml"),
        ),
        ("balls-4", spd("balls-4.nff")),
        ("tetra-6", spd("tetra-6.nff")),
        ("teapot-6", spd("teapot-6.nff")),
        ("mount-6", spd("mount-6.nff")),
    ]
}

/// One ray through each pixel's centre, at 256×192.
fn primary_rays(scene: &Scene) -> Vec<Ray> {
    let (width, height) = (256, 192);
    let camera = Camera::new(&scene.camera, width, height);
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| camera.primary_ray(x, y))
        .collect()
}

type Trace<'a> = Box<dyn Fn(&Ray) -> Option<Hit> + 'a>;

/// Median time of each way over the rays, in alternation, and the median
/// ratio of the second to the first within a round.
fn interleaved(rays: &[Ray], ways: &[Trace; 2]) -> (f64, f64, f64) {
    let mut times: [Vec<Duration>; 2] = Default::default();
    for round in 0..rounds() {
        // Each way goes first in every other round: neither gains from
        // following the other (caches, the clock's frequency).
        for i in [round % 2, 1 - round % 2] {
            let trace = &ways[i];
            let start = thread_time();
            for ray in rays {
                black_box(trace(ray));
            }
            times[i].push(thread_time() - start);
        }
    }
    let ms = |d: &Duration| d.as_secs_f64() * 1e3;
    let ratios = times[1].iter().zip(&times[0]).map(|(r, n)| ms(r) / ms(n));
    (
        median(times[0].iter().map(ms)),
        median(times[1].iter().map(ms)),
        median(ratios),
    )
}

/// The CPU time this thread has run: on a machine shared with other work,
/// the time the rays took, without the time the thread waited for a core
/// (wall time where there is no such clock).
#[cfg(unix)]
fn thread_time() -> Duration {
    let mut now = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime only writes the timespec it is given.
    let status = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut now) };
    assert_eq!(status, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID)");
    Duration::new(now.tv_sec as u64, now.tv_nsec as u32)
}

#[cfg(not(unix))]
fn thread_time() -> Duration {
    static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
    START.get_or_init(Instant::now).elapsed()
}

/// Rounds of the two ways in alternation: 15, or `BENCH_ROUNDS` (on a
/// loaded machine, more rounds give a steadier median).
fn rounds() -> usize {
    std::env::var("BENCH_ROUNDS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(15)
}

/// The share of rays whose nearest object is not the first listed, which
/// take the rule's second look.
fn second_looks(rays: &[Ray], objects: &[Object]) -> f64 {
    let looks = rays
        .iter()
        .filter(|ray| {
            closest_hit_by(intersect, objects, ray, 0.0, INF).is_some_and(|h| h.object > 0)
        })
        .count();
    looks as f64 / rays.len() as f64
}

/// `BENCH_WAY`'s tracing, for callgrind: each scene (or `BENCH_SCENE`'s
/// only) built, and its rays traced once by the nearest hit, by the rule,
/// or not at all.
fn one_way(way: &str) {
    let only = std::env::var("BENCH_SCENE").ok();
    for (name, scene) in scenes() {
        if only.as_deref().is_some_and(|only| only != name) {
            continue;
        }
        let rays = primary_rays(&scene);
        let wide = WideBvh::build(&scene.objects);
        let trace = |ray: &Ray| match way {
            "nearest" => wide.nearest_hit(ray, 0.0, INF),
            "rule" => wide.closest_hit(ray, 0.0, INF),
            "none" => None,
            other => panic!("BENCH_WAY is nearest, rule or none, not {other}"),
        };
        let times = std::env::var("BENCH_ROUNDS").map_or(1, |n| n.parse().unwrap());
        let mut hits = 0;
        for _ in 0..times {
            hits = rays.iter().filter_map(trace).count();
        }
        println!("{name}: {way}, {hits} hits");
    }
}

fn main() {
    if let Ok(way) = std::env::var("BENCH_WAY") {
        return one_way(&way);
    }
    println!("| scene | tracer | nearest hit | with the rule | ratio | rays that look twice |");
    println!("| --- | --- | ---: | ---: | ---: | ---: |");
    for (name, scene) in scenes() {
        let rays = primary_rays(&scene);
        let objects = &scene.objects[..];
        let wide = WideBvh::build(objects);
        let mut tracers: Vec<(&str, [Trace; 2])> = vec![(
            "wide BVH",
            [
                Box::new(|ray: &Ray| wide.nearest_hit(ray, 0.0, INF)),
                Box::new(|ray: &Ray| wide.closest_hit(ray, 0.0, INF)),
            ],
        )];
        if objects.len() <= 64 {
            tracers.push((
                "list",
                [
                    Box::new(|ray: &Ray| closest_hit_by(intersect, objects, ray, 0.0, INF)),
                    Box::new(|ray: &Ray| closest_hit(objects, ray, 0.0, INF)),
                ],
            ));
        }
        let share = 100.0 * second_looks(&rays, objects);
        let planes = objects
            .iter()
            .filter(|o| matches!(o.shape, Shape::Plane { .. }))
            .count();
        for (tracer, ways) in &tracers {
            let (nearest, rule, ratio) = interleaved(&rays, ways);
            println!(
                "| {name} ({} objects, {planes} planes) | {tracer} | {nearest:.2} ms | {rule:.2} ms | {ratio:.3} | {share:.0}% |",
                objects.len()
            );
        }
    }
    println!(
        "\n(256×192 primary rays, one thread's CPU time; median of {} rounds, the two ways in alternation)",
        rounds()
    );
    println!(
        "(wide BVH: the complete tracer's closest hit, the rule in the same walk. list: chapter 2's \
         closest_hit, the lesson's second look through the list, for comparison; the complete tracer \
         does not use it)"
    );
}
