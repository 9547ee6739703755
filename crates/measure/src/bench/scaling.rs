//! `bench --scaling`: the BVH's build time and the render time against the
//! number of primitives, measured in this process with the tracer that
//! `raybook render` uses: the complete tracer against the wide BVH
//! ([`raybook::world`]).

use std::path::PathBuf;
use std::time::Instant;

use super::{
    BenchArgs, median, scene_name, scene_progress, table, with_sphereflake, with_tetrahedron,
};
use raybook::toolkit::Scene;
use raybook::toolkit::scene::Shape;
use raybook::tracer::{Termination, render_complete};
use raybook::workbench::cli::with_threads;

/// Sphereflake levels generated beyond the SPD files (balls-5, balls-6).
const FLAKE_LEVELS: [u32; 2] = [5, 6];
/// Sierpinski tetrahedron levels generated beyond the SPD files.
const TETRAHEDRON_LEVELS: [u32; 3] = [7, 8, 9];

/// A scene to time, and its name in the table.
type Case = (String, Scene);

/// One scene's in-process times.
struct ScalingTiming {
    name: String,
    primitives: usize,
    /// Median time to build the BVH.
    build_seconds: f64,
    /// Nodes of the wide BVH (eight or four wide).
    nodes: usize,
    /// Median time to render, not counting the build.
    render_seconds: f64,
    /// Rays traced in one render.
    rays: u64,
}

/// The table of BVH build time and render time against primitive count,
/// under a line saying how it was measured.
pub(super) fn report(args: &BenchArgs, threads: u32, scenes: &[PathBuf]) -> Result<String, String> {
    let cases = cases(scenes)?;
    let bar = scene_progress(cases.len(), args.quiet);
    let mut timings = Vec::with_capacity(cases.len());
    for (name, scene) in cases {
        bar.set_message(name.clone());
        let scene = scene.with_size(args.size, args.size);
        timings.push(time_case(name, &scene, threads, args.runs)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let (size, runs) = (args.size, args.runs);
    Ok(format!(
        "{size}×{size} pixels, {threads} threads, in-process; median of {runs} runs\n\n{}",
        timings_table(&timings, threads)
    ))
}

/// The SPD scenes and the larger ones generated from them, fewest
/// primitives first (triangles before spheres at equal counts).
fn cases(scenes: &[PathBuf]) -> Result<Vec<Case>, String> {
    let mut cases = Vec::with_capacity(scenes.len());
    for path in scenes {
        let scene = raybook::nff::load(path).map_err(|e| e.to_string())?;
        cases.push((scene_name(path), scene));
    }
    cases.extend(generated(&cases));
    cases.sort_by_key(|(_, s)| (s.objects.len(), has_spheres(s)));
    Ok(cases)
}

/// Larger sphereflakes and tetrahedra in the settings of the first SPD
/// scene of each kind among `cases` (balls-…, tetra-…), if there is one.
fn generated(cases: &[Case]) -> Vec<Case> {
    let first = |stem: &str| cases.iter().find(|(n, _)| n.starts_with(stem));
    let mut made = Vec::new();
    if let Some((_, balls)) = first("balls") {
        made.extend(FLAKE_LEVELS.map(|level| {
            let name = format!("balls-{level} (generated)");
            (name, with_sphereflake(balls, level))
        }));
    }
    if let Some((_, tetra)) = first("tetra") {
        made.extend(TETRAHEDRON_LEVELS.map(|level| {
            let name = format!("tetra-{level} (generated)");
            (name, with_tetrahedron(tetra, level))
        }));
    }
    made
}

fn has_spheres(scene: &Scene) -> bool {
    scene
        .objects
        .iter()
        .any(|o| matches!(o.shape, Shape::Sphere { .. }))
}

/// Builds the BVH of `scene` and renders it with the complete tracer on
/// `threads` threads, `runs` times, timing each part.
fn time_case(
    name: String,
    scene: &Scene,
    threads: u32,
    runs: u32,
) -> Result<ScalingTiming, String> {
    let termination = Termination::of(scene);
    let (mut builds, mut renders) = (Vec::new(), Vec::new());
    let (mut nodes, mut rays) = (0, 0);
    for _ in 0..runs {
        let start = Instant::now();
        let bvh = raybook::world(scene);
        builds.push(start.elapsed().as_secs_f64());
        nodes = bvh.node_count();
        let start = Instant::now();
        let (_, stats) = with_threads(Some(threads), || {
            render_complete(scene, &bvh, termination, || {})
        })
        .map_err(|e| e.to_string())?;
        renders.push(start.elapsed().as_secs_f64());
        rays = stats.rays();
    }
    Ok(ScalingTiming {
        name,
        primitives: scene.objects.len(),
        build_seconds: median(builds),
        nodes,
        render_seconds: median(renders),
        rays,
    })
}

/// The timings as a Markdown table, one row per scene.
fn timings_table(timings: &[ScalingTiming], threads: u32) -> String {
    let header = [
        "scene",
        "primitives",
        "BVH build",
        "4-wide nodes",
        "render",
        "rays",
        "ns per ray·thread",
    ];
    table::markdown(header, timings.iter().map(|t| t.cells(threads)), 1)
}

impl ScalingTiming {
    /// The table's cells for this scene; the cost of a ray counts every
    /// one of the `threads` threads' time.
    fn cells(&self, threads: u32) -> [String; 7] {
        let ns_per_ray = self.render_seconds * f64::from(threads) / self.rays as f64 * 1e9;
        [
            self.name.clone(),
            self.primitives.to_string(),
            format!("{:.1} ms", self.build_seconds * 1e3),
            self.nodes.to_string(),
            format!("{:.2} s", self.render_seconds),
            format!("{:.1} M", self.rays as f64 / 1e6),
            format!("{ns_per_ray:.0}"),
        ]
    }
}
