//! Idea 1 against Idea 2: traces a scene forward from its lights and
//! compares the pictures with chapter 4's backward one.

use ch04_shadows::scene_files;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use ch04_shadows::toolkit::{Image, Scene};
use ch04_shadows::workbench::cli::progress_bar;
use ch04_shadows::workbench::compare::{psnr, rmse_clamped};
use ch04b_forward::{
    Run, Settings, backward_image, check_scene, expected_image, measure, rays_needed, strip,
};
use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};

const DEFAULT_SCENE_PATH: &str = "chapters/04b-forward/scenes/forward.toml";
const DEFAULT_SCENE: &str = include_str!("../scenes/forward.toml");

/// The quality to reach: a noise of one step of the 8-bit picture.
const TARGET: f64 = 1.0 / 255.0;

/// Idea 1: light traced forward, from the lights. Emits photons from the
/// point lights in random directions; each reflects once, diffusely, and
/// colours the pixel it lands on if it passes through the camera's aperture,
/// a disc of radius A around the eye. Reports how many arrive, how long it
/// took and how far the picture is from chapter 4's backward one (Idea 2),
/// and writes a strip: the forward pictures for 1e5, 1e6, 1e7 photons, then
/// the backward picture.
#[derive(Parser)]
#[command(version)]
struct Args {
    /// Scene file (TOML): diffuse materials, point lights, black background.
    /// Without it, chapters/04b-forward/scenes/forward.toml.
    scene: Option<PathBuf>,

    /// Photons to emit, over all lights (1e6 and 1000000 both work). This
    /// run is measured beside those of the strip.
    #[arg(long, value_name = "N", default_value = "1e6", value_parser = parse_count)]
    rays: u64,

    /// Radius of the aperture disc around the eye, in scene units. 0 is a
    /// true pinhole, through which no photon passes.
    #[arg(long, value_name = "A", default_value_t = 0.05, value_parser = parse_aperture)]
    aperture: f32,

    /// The strip shows the forward pictures for 1e5, 1e6, … photons, up to
    /// this many (1e9 takes minutes).
    #[arg(long, value_name = "N", default_value = "1e7", value_parser = parse_count)]
    strip_up_to: u64,

    /// Where to write the strip.
    #[arg(
        short,
        long,
        value_name = "OUT.png",
        default_value = "04-shadows-forward.png"
    )]
    output: PathBuf,

    /// Image width in pixels.
    #[arg(long, default_value_t = 160, value_parser = clap::value_parser!(u32).range(1..=4096))]
    width: u32,

    /// Image height in pixels.
    #[arg(long, default_value_t = 120, value_parser = clap::value_parser!(u32).range(1..=4096))]
    height: u32,

    /// Seed of the random numbers: the same seed gives the same pictures.
    #[arg(long, default_value_t = 1)]
    seed: u64,

    /// The expected picture (what the forward one converges to) averages
    /// SAMPLES² backward rays over each pixel and the aperture.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=64))]
    samples: u32,

    /// No progress bars.
    #[arg(short, long)]
    quiet: bool,
}

/// A count of photons: an integer, in plain or scientific notation.
fn parse_count(text: &str) -> Result<u64, String> {
    let value: f64 = text
        .replace('_', "")
        .parse()
        .map_err(|_| format!("expected a number such as 1000000 or 1e6, found {text:?}"))?;
    if !(1.0..=1e13).contains(&value) || value.fract() != 0.0 {
        return Err(format!(
            "expected a whole number from 1 to 1e13, found {text}"
        ));
    }
    Ok(value as u64)
}

fn parse_aperture(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(a) if a.is_finite() && a >= 0.0 => Ok(a),
        _ => Err(format!("expected a radius of 0 or more, found {text:?}")),
    }
}

fn main() -> ExitCode {
    match run(&Args::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The whole program, step by step.
fn run(args: &Args) -> Result<(), String> {
    let (scene, name) = load(args)?;
    let (w, h) = (scene.image.width, scene.image.height);
    println!(
        "scene {name}, {w}×{h} pixels, aperture radius a = {}",
        args.aperture
    );
    let backward = trace_backward(&scene);
    let expected = trace_expected(&scene, args, &backward);
    let strip_rays = strip_counts(args.strip_up_to);
    let runs = measure_all(&scene, args, &backward, &expected, &strip_rays);
    let largest = runs.last().expect("at least one run");
    conclude(args, largest, w * h);
    write_strip(args, &runs, &strip_rays, &backward)
}

/// The scene named on the command line (or the default), at the size asked
/// for, if the forward tracer can render it; and its name.
fn load(args: &Args) -> Result<(Scene, String), String> {
    let (scene, name) = match &args.scene {
        Some(path) => (
            scene_files::load(path).map_err(|e| e.to_string())?,
            path.display().to_string(),
        ),
        None => (
            scene_files::parse(DEFAULT_SCENE, DEFAULT_SCENE_PATH).map_err(|e| e.to_string())?,
            DEFAULT_SCENE_PATH.to_owned(),
        ),
    };
    let scene = scene.with_size(args.width, args.height);
    check_scene(&scene)
        .map_err(|problems| format!("{name} cannot be traced forward:\n{problems}"))?;
    Ok((scene, name))
}

/// Idea 2: chapter 4's picture, timed.
fn trace_backward(scene: &Scene) -> Image {
    let start = Instant::now();
    let backward = backward_image(scene, || {});
    println!(
        "backward (Idea 2, chapter 4): one ray per pixel, {} s",
        fmt_seconds(start.elapsed().as_secs_f64())
    );
    backward
}

/// What the forward picture converges to, and how far that is from the
/// backward picture: the floor of the forward picture's error.
fn trace_expected(scene: &Scene, args: &Args, backward: &Image) -> Image {
    let bar = progress_bar(scene.image.height, args.quiet);
    let start = Instant::now();
    let expected = expected_image(scene, args.aperture, args.samples, || bar.inc(1));
    bar.finish_and_clear();
    let floor = rmse_clamped(backward, &expected);
    println!(
        "expected forward picture: {} backward rays per pixel over the pixel and the aperture, {} s;\n  \
         its RMSE against the backward picture is {floor:.5} ({:.1} dB): the error no number of photons removes",
        args.samples * args.samples,
        fmt_seconds(start.elapsed().as_secs_f64()),
        psnr(floor)
    );
    expected
}

/// The photons of the strip's forward pictures: 1e5, 1e6, … up to `up_to`.
fn strip_counts(up_to: u64) -> Vec<u64> {
    std::iter::successors(Some(100_000u64), |n| n.checked_mul(10))
        .take_while(|&n| n <= up_to)
        .collect()
}

/// Traces forward with the strip's numbers of photons and `--rays`, fewest
/// first, and prints a table row for each.
fn measure_all(
    scene: &Scene,
    args: &Args,
    backward: &Image,
    expected: &Image,
    strip_rays: &[u64],
) -> Vec<Run> {
    let mut all_rays = strip_rays.to_vec();
    all_rays.push(args.rays);
    all_rays.sort_unstable();
    all_rays.dedup();
    println!(
        "\n{:>9} {:>11} {:>10} {:>9} {:>10} {:>8} {:>10}",
        "photons", "reach image", "share", "time s", "RMSE", "PSNR dB", "noise RMSE"
    );
    let mut runs = Vec::new();
    for rays in all_rays {
        let settings = Settings {
            rays,
            aperture: args.aperture,
            seed: args.seed,
        };
        let bar = photon_bar(rays, args.quiet);
        let run = measure(scene, &settings, backward, expected, |n| bar.inc(n));
        bar.finish_and_clear();
        print_row(&run, rays == args.rays);
        runs.push(run);
    }
    println!(
        "RMSE and PSNR: against the backward picture, each channel clamped to [0, 1] as the PNG shows it;"
    );
    println!("noise RMSE: against the expected picture, unclamped.");
    runs
}

fn photon_bar(rays: u64, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template(
        "{spinner} tracing forward [{bar:40}] {human_pos}/{human_len} photons, {eta} left",
    )
    .expect("a valid template")
    .progress_chars("=> ");
    ProgressBar::new(rays).with_style(style)
}

/// One row of the table; `asked` marks the run of `--rays`.
fn print_row(run: &Run, asked: bool) {
    println!(
        "{:>9} {:>11} {:>10.3e} {:>9} {:>10.5} {:>8.2} {:>10.4}{}",
        format!("{:e}", run.rays as f64),
        run.forward.counts.on_image,
        run.forward.share(),
        fmt_seconds(run.seconds),
        run.error,
        psnr(run.error),
        run.noise,
        if asked { "  (--rays)" } else { "" }
    );
}

/// The conclusion, from the largest run: how many photons a good picture of
/// `pixels` pixels takes, or why no number of them makes one.
fn conclude(args: &Args, largest: &Run, pixels: u32) {
    let on_image = largest.forward.counts.on_image;
    if on_image == 0 {
        if args.aperture == 0.0 {
            println!(
                "\nno photon passes a true pinhole (a = 0): the share is exactly zero, \
                 and no number of photons makes a picture"
            );
        } else {
            println!(
                "\nno photon reached the image: with a = {} the share is too small to measure \
                 with {:e} photons",
                args.aperture, largest.rays as f64
            );
        }
        return;
    }
    let needed = rays_needed(largest.rays, largest.noise, TARGET);
    let rate = largest.rays as f64 / largest.seconds;
    println!(
        "\nnoise RMSE ≤ 1/255 (one 8-bit step) takes about {needed:.1e} photons \
         (N·noise² stays constant; from the run of {:e},\n  \
         whose {on_image} photons on the image make this good to roughly ±{:.0}%),\n  \
         {:.0} photons reaching each pixel, about {} at this machine's {rate:.2e} photons/s;\n  \
         the backward picture needs one ray per pixel",
        largest.rays as f64,
        100.0 / (on_image as f64).sqrt(),
        needed * largest.forward.share() / f64::from(pixels),
        fmt_duration(needed / rate),
    );
}

/// Writes the strip: the forward pictures of `strip_rays` photons, then the
/// backward one.
fn write_strip(
    args: &Args,
    runs: &[Run],
    strip_rays: &[u64],
    backward: &Image,
) -> Result<(), String> {
    let mut panels: Vec<&Image> = runs
        .iter()
        .filter(|run| strip_rays.contains(&run.rays))
        .map(|run| &run.forward.image)
        .collect();
    panels.push(backward);
    let labels: Vec<String> = strip_rays
        .iter()
        .map(|&n| format!("forward {:e}", n as f64))
        .chain(["backward".to_owned()])
        .collect();
    strip(&panels)
        .save_png(&args.output)
        .map_err(|e| format!("cannot write {}: {e}", args.output.display()))?;
    println!(
        "wrote {} (left to right: {})",
        args.output.display(),
        labels.join(" | ")
    );
    Ok(())
}

fn fmt_seconds(seconds: f64) -> String {
    format!("{seconds:.3}")
}

/// A long time in the unit that reads best.
fn fmt_duration(seconds: f64) -> String {
    const UNITS: [(f64, &str); 5] = [
        (365.25 * 86400.0, "years"),
        (86400.0, "days"),
        (3600.0, "hours"),
        (60.0, "minutes"),
        (1.0, "seconds"),
    ];
    for (size, unit) in UNITS {
        if seconds >= size {
            return format!("{:.1} {unit}", seconds / size);
        }
    }
    format!("{seconds:.2} seconds")
}
