//! `raybook bench`: times the SPD scenes, and POV-Ray on the same scenes.
//!
//! Each scene is rendered by running this very binary (`raybook render
//! SCENE.nff`) as a new process, so the time includes starting, parsing,
//! building the BVH, rendering and writing the PNG, as POV-Ray's does.
//! `--scaling` instead renders in this process and reports the BVH's build
//! time and the render time against the number of primitives, for the SPD
//! scenes and for larger sphereflakes and Sierpinski tetrahedra made here.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use ch08_bvh::Bvh;

use crate::toolkit::cli::with_threads;
use crate::toolkit::scene::{Object, Shape};
use crate::toolkit::{Scene, Vec3};

/// Arguments of `raybook bench`.
#[derive(clap::Args, Debug, Clone)]
pub struct BenchArgs {
    /// Folder of SPD scenes: NAME.nff, and NAME.pov for POV-Ray.
    #[arg(long, default_value = "scenes/spd")]
    pub scenes: PathBuf,

    /// Only the scenes whose names contain one of these (default: all).
    #[arg(long)]
    pub only: Vec<String>,

    /// Width and height of the pictures.
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub size: u32,

    /// Timed runs per scene; the median is reported.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub runs: u32,

    /// Threads for both tracers (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,

    /// Do not run POV-Ray even if it is installed.
    #[arg(long)]
    pub no_povray: bool,

    /// Report BVH build and render time against primitive count instead.
    #[arg(long)]
    pub scaling: bool,
}

/// Runs the benchmark and prints a Markdown table.
pub fn run(args: &BenchArgs) -> ExitCode {
    let threads = args
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get() as u32));
    let scenes = match spd_scenes(&args.scenes, &args.only) {
        Ok(scenes) if !scenes.is_empty() => scenes,
        Ok(_) => {
            eprintln!("error: no .nff scenes in {}", args.scenes.display());
            return ExitCode::FAILURE;
        }
        Err(e) => {
            eprintln!("error: cannot read {}: {e}", args.scenes.display());
            return ExitCode::FAILURE;
        }
    };
    let result = if args.scaling {
        scaling(args, threads, &scenes)
    } else {
        versus_povray(args, threads, &scenes)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The .nff files of a folder whose names contain one of `only`, sorted.
fn spd_scenes(dir: &Path, only: &[String]) -> std::io::Result<Vec<PathBuf>> {
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "nff"))
        .filter(|p| only.is_empty() || only.iter().any(|o| p.to_string_lossy().contains(o)))
        .collect();
    scenes.sort();
    Ok(scenes)
}

/// The median of some durations.
fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

/// Wall time of `command`, run to completion `runs` times: the median, and
/// the standard output of the last run.
fn time_process(mut command: Command, runs: u32) -> Result<(Duration, String), String> {
    let mut times = Vec::new();
    let mut stdout = String::new();
    for _ in 0..runs {
        let start = Instant::now();
        let output = command
            .stderr(Stdio::piped())
            .output()
            .map_err(|e| format!("cannot run {command:?}: {e}"))?;
        times.push(start.elapsed());
        if !output.status.success() {
            let err = String::from_utf8_lossy(&output.stderr);
            return Err(format!("{command:?} failed: {}", err.trim()));
        }
        stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    }
    Ok((median(times), stdout))
}

/// The table of raybook against POV-Ray, one row per scene.
fn versus_povray(args: &BenchArgs, threads: u32, scenes: &[PathBuf]) -> Result<(), String> {
    let povray = !args.no_povray && povray_installed();
    if !povray && !args.no_povray {
        eprintln!("note: povray is not installed; timing raybook alone");
    }
    let out = std::env::temp_dir().join(format!("raybook-bench-{}", std::process::id()));
    std::fs::create_dir_all(&out).map_err(|e| e.to_string())?;
    let (size, runs) = (args.size, args.runs);
    println!(
        "{size}×{size} pixels, 1 sample per pixel, {threads} threads, median of {runs} runs, whole process\n"
    );
    println!("| scene | primitives | raybook | rays | rays/s | POV-Ray 3.7 | POV-Ray / raybook |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for scene in scenes {
        let name = scene.file_stem().unwrap_or_default().to_string_lossy();
        let primitives = crate::nff::load(scene)
            .map_err(|e| e.to_string())?
            .objects
            .len();
        let mut ours = Command::new(std::env::current_exe().map_err(|e| e.to_string())?);
        ours.arg("render")
            .arg(scene)
            .arg("-o")
            .arg(out.join(format!("{name}.png")))
            .args([
                "--quiet",
                "--width",
                &size.to_string(),
                "--height",
                &size.to_string(),
            ])
            .args(["--threads", &threads.to_string()]);
        let (time, stdout) = time_process(ours, runs)?;
        let rays = rays_of(&stdout);
        let pov = match scene.with_extension("pov") {
            pov if povray && pov.exists() => {
                let image = out.join(format!("{name}-pov.png"));
                Some(time_process(povray_command(&pov, &image, size, threads), runs)?.0)
            }
            _ => None,
        };
        println!(
            "| {name} | {primitives} | {:.2} s | {:.1} M | {:.1} M | {} | {} |",
            time.as_secs_f64(),
            rays as f64 / 1e6,
            rays as f64 / time.as_secs_f64() / 1e6,
            pov.map_or("–".into(), |p| format!("{:.2} s", p.as_secs_f64())),
            pov.map_or("–".into(), |p| format!(
                "{:.2}",
                p.as_secs_f64() / time.as_secs_f64()
            )),
        );
    }
    println!("\npictures in {}", out.display());
    Ok(())
}

/// The ray count in `raybook render`'s report ("N rays: ...").
fn rays_of(report: &str) -> u64 {
    report
        .lines()
        .find_map(|l| {
            l.split_once(" rays: ")
                .and_then(|(n, _)| n.trim().parse().ok())
        })
        .unwrap_or(0)
}

fn povray_installed() -> bool {
    Command::new("povray")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok()
}

/// POV-Ray 3.7 rendering `pov` to `png`: no anti-aliasing (-A), no display
/// (-D), `threads` worker threads (+WT).
fn povray_command(pov: &Path, png: &Path, size: u32, threads: u32) -> Command {
    let mut command = Command::new("povray");
    command
        .arg(format!("+I{}", pov.display()))
        .arg(format!("+O{}", png.display()))
        .args([
            format!("+W{size}"),
            format!("+H{size}"),
            format!("+WT{threads}"),
        ])
        .args(["-A", "-D", "+FN", "-GA", "-V"])
        .stdout(Stdio::null());
    command
}

/// The table of BVH build time and render time against primitive count.
fn scaling(args: &BenchArgs, threads: u32, scenes: &[PathBuf]) -> Result<(), String> {
    let mut cases = Vec::new();
    for path in scenes {
        let name = path
            .file_stem()
            .unwrap_or_default()
            .to_string_lossy()
            .into_owned();
        cases.push((name, crate::nff::load(path).map_err(|e| e.to_string())?));
    }
    let base = |stem: &str| {
        cases
            .iter()
            .find(|(n, _)| n.starts_with(stem))
            .map(|(_, s)| s.clone())
    };
    let (flake, tetra) = (base("balls"), base("tetra"));
    for level in [5, 6] {
        if let Some(scene) = &flake {
            cases.push((
                format!("balls-{level} (generated)"),
                with_sphereflake(scene, level),
            ));
        }
    }
    for level in [7, 8, 9] {
        if let Some(scene) = &tetra {
            cases.push((
                format!("tetra-{level} (generated)"),
                with_tetrahedron(scene, level),
            ));
        }
    }
    cases.sort_by_key(|(_, s)| {
        (
            s.objects.len(),
            s.objects
                .iter()
                .any(|o| matches!(o.shape, Shape::Sphere { .. })),
        )
    });
    let size = args.size;
    println!(
        "{size}×{size} pixels, {threads} threads, in-process; median of {} runs\n",
        args.runs
    );
    println!(
        "| scene | primitives | BVH build | nodes | depth | render | rays | ns per ray·thread |"
    );
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for (name, scene) in cases {
        let scene = scene.with_size(size, size);
        let mut builds = Vec::new();
        let mut renders = Vec::new();
        let mut rays = 0;
        let mut summary = None;
        for _ in 0..args.runs {
            let start = Instant::now();
            let bvh = Bvh::build(&scene.objects);
            builds.push(start.elapsed());
            summary = Some(bvh.summary());
            let start = Instant::now();
            let termination = ch08_bvh::Termination::of(&scene);
            let (_, stats) = with_threads(Some(threads), || {
                ch08_bvh::render_complete(&scene, &bvh, termination, || {})
            })
            .map_err(|e| e.to_string())?;
            renders.push(start.elapsed());
            rays = stats.rays();
        }
        let (build, render) = (median(builds), median(renders));
        let summary = summary.expect("at least one run");
        println!(
            "| {name} | {} | {:.1} ms | {} | {} | {:.2} s | {:.1} M | {:.0} |",
            scene.objects.len(),
            build.as_secs_f64() * 1e3,
            summary.nodes,
            summary.depth,
            render.as_secs_f64(),
            rays as f64 / 1e6,
            render.as_secs_f64() * threads as f64 / rays as f64 * 1e9,
        );
    }
    Ok(())
}

/// `scene` with its spheres replaced by a sphereflake of `level` levels:
/// a sphere with nine spheres a third its size around it (six round the
/// equator, three above), each with nine around it, and so on; the first
/// sphere's centre, radius and material are kept.
pub fn with_sphereflake(scene: &Scene, level: u32) -> Scene {
    let mut scene = scene.clone();
    let first = scene
        .objects
        .iter()
        .position(|o| matches!(o.shape, Shape::Sphere { .. }));
    let Some(first) = first else { return scene };
    let Object {
        shape: Shape::Sphere { center, radius },
        material,
        ..
    } = scene.objects[first]
    else {
        unreachable!("found above");
    };
    scene
        .objects
        .retain(|o| !matches!(o.shape, Shape::Sphere { .. }));
    let mut spheres = Vec::new();
    flake(center, radius, Vec3::Z, level, &mut spheres);
    scene
        .objects
        .extend(spheres.into_iter().map(|(center, radius)| Object {
            shape: Shape::Sphere { center, radius },
            material,
            shadows: true,
        }));
    scene
}

fn flake(center: Vec3, radius: f32, up: Vec3, level: u32, out: &mut Vec<(Vec3, f32)>) {
    out.push((center, radius));
    if level == 0 {
        return;
    }
    let (u, v) = up.any_orthonormal_pair();
    let child = radius / 3.0;
    let ring = (0..6).map(|i| (i as f32 * std::f32::consts::TAU / 6.0, 0.0f32));
    let top = (0..3).map(|i| (i as f32 * std::f32::consts::TAU / 3.0 + 0.5, 0.955f32));
    for (around, elevation) in ring.chain(top) {
        let flat = around.cos() * u + around.sin() * v;
        let direction = elevation.cos() * flat + elevation.sin() * up;
        flake(
            center + direction * (radius + child),
            child,
            direction,
            level - 1,
            out,
        );
    }
}

/// `scene` with its triangles replaced by a Sierpinski tetrahedron of size
/// `level` as SPD counts it (4^(level − 1) tetrahedra of 4 triangles) in the
/// box the old triangles filled, with the first triangle's material.
pub fn with_tetrahedron(scene: &Scene, level: u32) -> Scene {
    let mut scene = scene.clone();
    let triangles: Vec<&Object> = scene
        .objects
        .iter()
        .filter(|o| matches!(o.shape, Shape::Triangle { .. }))
        .collect();
    let Some(material) = triangles.first().map(|o| o.material) else {
        return scene;
    };
    let corners = triangles.iter().flat_map(|o| match o.shape {
        Shape::Triangle { vertices } => vertices,
        _ => unreachable!("filtered above"),
    });
    let (low, high) = corners.fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(l, h), p| {
        (l.min(p), h.max(p))
    });
    let (center, half) = ((low + high) / 2.0, (high - low) / 2.0);
    let base = [
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, 1.0, -1.0),
    ]
    .map(|c| center + c * half);
    scene
        .objects
        .retain(|o| !matches!(o.shape, Shape::Triangle { .. }));
    let mut tetrahedra = Vec::new();
    sierpinski(base, level.saturating_sub(1), &mut tetrahedra);
    for [a, b, c, d] in tetrahedra {
        for vertices in [[a, b, c], [a, c, d], [a, d, b], [b, d, c]] {
            scene.objects.push(Object {
                shape: Shape::Triangle { vertices },
                material,
                shadows: true,
            });
        }
    }
    scene
}

fn sierpinski(corners: [Vec3; 4], level: u32, out: &mut Vec<[Vec3; 4]>) {
    if level == 0 {
        out.push(corners);
        return;
    }
    for keep in corners {
        sierpinski(corners.map(|c| (c + keep) / 2.0), level - 1, out);
    }
}
