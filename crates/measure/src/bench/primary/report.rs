//! Timing each scene's primary rays with raybook, and Embree where it can,
//! and the report: how it was measured, the table, and its warnings.

use std::path::PathBuf;
use std::time::Instant;

use super::compare::agreement;
use super::embree::Embree;
use super::rows::{EmbreeResult, PrimaryTiming, timings_table};
use super::trace::{primary_rays, primary_world, trace_parallel, trace_serial};
use crate::bench::{BenchArgs, median, scene_name, scene_progress};
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Shape;

/// What the Embree column says for a scene with spheres or planes.
const TRIANGLES_ONLY: &str = "n/a (embreex has triangles only)";

/// Above this ratio of Embree's slowest process's time to its fastest's,
/// the report notes how unevenly its shares of the rays cost.
const UNEVEN: f64 = 1.1;

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
pub(in crate::bench) fn report(
    args: &BenchArgs,
    threads: u32,
    scenes: &[PathBuf],
) -> Result<String, String> {
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
    let lanes = match raybook::wide::Width::detect() {
        raybook::wide::Width::Four => "four",
        raybook::wide::Width::Eight => "eight",
    };
    let embree_line = match &embree {
        Ok(e) => format!(
            "Embree 4 through {} ({}), one thread and {threads} processes at once",
            e.version, e.python
        ),
        Err(why) => format!("Embree: {why}"),
    };
    let mut out = format!(
        "{size}×{size} primary rays (one per pixel, through its centre), closest hit against \
         the complete tracer's {lanes}-wide BVH, 1 and {threads} threads; {embree_line}; median of {runs} runs, \
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
