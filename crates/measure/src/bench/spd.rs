//! The SPD scenes rendered whole-process, by raybook and by POV-Ray, and
//! tinyraytracer's scene by raybook and by tinyraytracer: one table row per
//! scene. The two tracers of a row run in alternation, run after run, so
//! that a shared machine's drift falls on both alike.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use super::{BenchArgs, median, povray, scene_name, scene_progress, table};

/// What the runs of every scene share.
struct Setup {
    size: u32,
    runs: u32,
    threads: u32,
    /// Where the pictures go.
    pictures: PathBuf,
    /// Whether POV-Ray renders too.
    povray: bool,
}

/// One scene's whole-process times.
struct SceneTiming {
    name: String,
    primitives: usize,
    /// raybook's median wall time.
    seconds: f64,
    /// Rays raybook traced in one run.
    rays: u64,
    /// The peer that rendered the scene too, and its median wall time.
    peer: Option<(&'static str, f64)>,
}

/// The table of raybook against POV-Ray, under a line saying how it was
/// measured, and where the pictures are.
pub(super) fn report(args: &BenchArgs, threads: u32, scenes: &[PathBuf]) -> Result<String, String> {
    let setup = Setup {
        size: args.size,
        runs: args.runs,
        threads,
        pictures: pictures_folder()?,
        povray: use_povray(args.no_povray),
    };
    let bar = scene_progress(scenes.len(), args.quiet);
    let mut timings = Vec::with_capacity(scenes.len() + 1);
    if let Some(tinyraytracer) = &args.tinyraytracer {
        bar.set_message("tinyraytracer");
        timings.push(time_tinyraytracer(tinyraytracer, &setup)?);
    }
    for scene in scenes {
        bar.set_message(scene_name(scene));
        timings.push(time_scene(scene, &setup)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let Setup { size, runs, .. } = setup;
    Ok(format!(
        "{size}×{size} pixels, 1 sample per pixel, {threads} threads, median of {runs} runs, \
         whole process\n\n{}\npictures in {}",
        timings_table(&timings),
        setup.pictures.display()
    ))
}

/// Whether to run POV-Ray: if installed, unless told not to.
fn use_povray(no_povray: bool) -> bool {
    if no_povray {
        return false;
    }
    let installed = povray::installed();
    if !installed {
        eprintln!("note: povray is not installed; timing raybook alone");
    }
    installed
}

/// A new folder for this run's pictures, in the system's temporary folder.
fn pictures_folder() -> Result<PathBuf, String> {
    let folder = std::env::temp_dir().join(format!("raybook-bench-{}", std::process::id()));
    std::fs::create_dir_all(&folder)
        .map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
    Ok(folder)
}

/// Times raybook on one scene, and POV-Ray on its .pov beside it if any.
fn time_scene(scene: &Path, setup: &Setup) -> Result<SceneTiming, String> {
    let name = scene_name(scene);
    let primitives = raybook::nff::load(scene)
        .map_err(|e| e.to_string())?
        .objects
        .len();
    let picture = setup.pictures.join(format!("{name}.png"));
    let mut ours = raybook_command(scene, &picture, setup)?;
    ours.args(["--width", &setup.size.to_string()])
        .args(["--height", &setup.size.to_string()]);
    let pov = scene.with_extension("pov");
    let theirs = (setup.povray && pov.exists()).then(|| {
        let picture = setup.pictures.join(format!("{name}-pov.png"));
        (
            "POV-Ray 3.7",
            povray::command(&pov, &picture, setup.size, setup.threads),
        )
    });
    time_side_by_side(name, primitives, ours, theirs, setup.runs)
}

/// tinyraytracer's scene, as this repository writes it for raybook
/// (scenes/peers/tinyraytracer.toml), at tinyraytracer's fixed 1024×768.
pub const TINYRAYTRACER_SCENE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../scenes/peers/tinyraytracer.toml"
);

/// Times raybook on tinyraytracer's scene, and the tinyraytracer binary
/// `program` (which renders its own scene to out.ppm in the folder it runs
/// in) with as many OpenMP threads.
fn time_tinyraytracer(program: &Path, setup: &Setup) -> Result<SceneTiming, String> {
    let scene = Path::new(TINYRAYTRACER_SCENE);
    let primitives = raybook::scene_files::load(scene)
        .map_err(|e| e.to_string())?
        .objects
        .len();
    let picture = setup.pictures.join("tinyraytracer.png");
    let ours = raybook_command(scene, &picture, setup)?;
    let mut theirs = Command::new(program);
    theirs
        .current_dir(&setup.pictures)
        .env("OMP_NUM_THREADS", setup.threads.to_string())
        .stdout(Stdio::null());
    let name = "tinyraytracer".to_string();
    time_side_by_side(
        name,
        primitives,
        ours,
        Some(("tinyraytracer", theirs)),
        setup.runs,
    )
}

/// Runs raybook's command and the peer's, if any, in alternation `runs`
/// times each: their median wall times, and the rays of raybook's report.
fn time_side_by_side(
    name: String,
    primitives: usize,
    mut ours: Command,
    mut theirs: Option<(&'static str, Command)>,
    runs: u32,
) -> Result<SceneTiming, String> {
    let (mut our_seconds, mut their_seconds) = (Vec::new(), Vec::new());
    let mut stdout = String::new();
    for _ in 0..runs {
        let (seconds, output) = time_process(&mut ours)?;
        our_seconds.push(seconds);
        stdout = output;
        if let Some((_, command)) = &mut theirs {
            their_seconds.push(time_process(command)?.0);
        }
    }
    Ok(SceneTiming {
        name,
        primitives,
        seconds: median(our_seconds),
        rays: rays_of(&stdout),
        peer: theirs.map(|(peer, _)| (peer, median(their_seconds))),
    })
}

/// This binary rendering `scene` to `png`: `raybook render` with the
/// set-up's threads.
fn raybook_command(scene: &Path, png: &Path, setup: &Setup) -> Result<Command, String> {
    let raybook = std::env::current_exe().map_err(|e| format!("cannot find raybook: {e}"))?;
    let threads = setup.threads.to_string();
    let mut command = Command::new(raybook);
    command
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(png)
        .arg("--quiet")
        .args(["--threads", &threads]);
    Ok(command)
}

/// Wall time of `command`, run to completion, in seconds, and its
/// standard output.
fn time_process(command: &mut Command) -> Result<(f64, String), String> {
    let start = Instant::now();
    let output = command
        .stderr(Stdio::piped())
        .output()
        .map_err(|e| format!("cannot run {command:?}: {e}"))?;
    let seconds = start.elapsed().as_secs_f64();
    if !output.status.success() {
        let err = String::from_utf8_lossy(&output.stderr);
        return Err(format!("{command:?} failed: {}", err.trim()));
    }
    Ok((
        seconds,
        String::from_utf8_lossy(&output.stdout).into_owned(),
    ))
}

/// The ray count in `raybook render`'s report ("N rays: ..."), or 0.
fn rays_of(report: &str) -> u64 {
    report
        .lines()
        .find_map(|l| {
            l.split_once(" rays: ")
                .and_then(|(n, _)| n.trim().parse().ok())
        })
        .unwrap_or(0)
}

/// The timings as a Markdown table, one row per scene.
fn timings_table(timings: &[SceneTiming]) -> String {
    let header = [
        "scene",
        "primitives",
        "raybook",
        "rays",
        "rays/s",
        "peer",
        "peer's time",
        "peer / raybook",
    ];
    table::markdown(header, timings.iter().map(SceneTiming::cells), 1)
}

impl SceneTiming {
    /// The table's cells for this scene; dashes where no peer ran.
    fn cells(&self) -> [String; 8] {
        let peer = |show: &dyn Fn(f64) -> String| self.peer.map_or("–".into(), |(_, t)| show(t));
        [
            self.name.clone(),
            self.primitives.to_string(),
            format!("{:.2} s", self.seconds),
            format!("{:.1} M", self.rays as f64 / 1e6),
            format!("{:.1} M", self.rays as f64 / self.seconds / 1e6),
            self.peer.map_or("–", |(name, _)| name).to_string(),
            peer(&|theirs| format!("{theirs:.2} s")),
            peer(&|theirs| format!("{:.2}", theirs / self.seconds)),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::rays_of;

    #[test]
    fn the_ray_count_is_read_from_the_render_report() {
        let report = "wrote x.png (64×64)\n  1234567 rays: 4096 primary, 8 shadow\n";
        assert_eq!(rays_of(report), 1_234_567);
        assert_eq!(rays_of("no count here"), 0);
    }
}
