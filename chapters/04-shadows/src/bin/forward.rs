//! Idea 1 against Idea 2: traces a scene forward from its lights and
//! compares the pictures with chapter 4's backward one.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use ch04_shadows::forward::{
    Forward, Settings, backward_image, check_scene, expected_image, rays_needed, trace_forward,
};
use ch04_shadows::toolkit::cli::progress_bar;
use ch04_shadows::toolkit::compare::{psnr, rmse, rmse_clamped};
use ch04_shadows::toolkit::{Color, Image, Scene};
use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};

const DEFAULT_SCENE_PATH: &str = "chapters/04-shadows/scenes/forward.toml";
const DEFAULT_SCENE: &str = include_str!("../../scenes/forward.toml");

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
    /// Without it, chapters/04-shadows/scenes/forward.toml.
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

/// One forward picture and how it measures up.
struct Run {
    rays: u64,
    forward: Forward,
    seconds: f64,
    /// RMSE against the backward picture, as the PNGs show them.
    error: f64,
    /// RMSE against the expected picture, unclamped: the noise alone.
    noise: f64,
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

fn load(args: &Args) -> Result<(Scene, String), String> {
    let (scene, name) = match &args.scene {
        Some(path) => (
            Scene::load(path).map_err(|e| e.to_string())?,
            path.display().to_string(),
        ),
        None => (
            Scene::parse(DEFAULT_SCENE, DEFAULT_SCENE_PATH).map_err(|e| e.to_string())?,
            DEFAULT_SCENE_PATH.to_owned(),
        ),
    };
    let scene = scene.with_size(args.width, args.height);
    check_scene(&scene)
        .map_err(|problems| format!("{name} cannot be traced forward:\n{problems}"))?;
    Ok((scene, name))
}

/// The pictures side by side, left to right, with a grey line between.
fn strip(images: &[&Image]) -> Image {
    const GAP: u32 = 2;
    let (w, h) = (images[0].width, images[0].height);
    let width = images.len() as u32 * (w + GAP) - GAP;
    let mut pixels = vec![Color::splat(0.5); (width * h) as usize];
    for (i, image) in images.iter().enumerate() {
        let left = i as u32 * (w + GAP);
        for y in 0..h {
            for x in 0..w {
                pixels[(y * width + left + x) as usize] = image.get(x, y);
            }
        }
    }
    Image {
        width,
        height: h,
        pixels,
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    let (scene, name) = match load(&args) {
        Ok(loaded) => loaded,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let (w, h) = (scene.image.width, scene.image.height);
    println!(
        "scene {name}, {w}×{h} pixels, aperture radius a = {}",
        args.aperture
    );

    let start = Instant::now();
    let backward = backward_image(&scene, || {});
    println!(
        "backward (Idea 2, chapter 4): one ray per pixel, {} s",
        fmt_seconds(start.elapsed().as_secs_f64())
    );

    let bar = progress_bar(h, args.quiet);
    let start = Instant::now();
    let expected = expected_image(&scene, args.aperture, args.samples, || bar.inc(1));
    bar.finish_and_clear();
    let floor = rmse_clamped(&backward, &expected);
    println!(
        "expected forward picture: {} backward rays per pixel over the pixel and the aperture, {} s;\n  \
         its RMSE against the backward picture is {floor:.5} ({:.1} dB): the error no number of photons removes",
        args.samples * args.samples,
        fmt_seconds(start.elapsed().as_secs_f64()),
        psnr(floor)
    );

    let strip_rays: Vec<u64> = std::iter::successors(Some(100_000u64), |n| n.checked_mul(10))
        .take_while(|&n| n <= args.strip_up_to)
        .collect();
    let mut all_rays = strip_rays.clone();
    all_rays.push(args.rays);
    all_rays.sort_unstable();
    all_rays.dedup();

    println!(
        "\n{:>9} {:>11} {:>10} {:>9} {:>10} {:>8} {:>10}",
        "photons", "reach image", "share", "time s", "RMSE", "PSNR dB", "noise RMSE"
    );
    let mut runs = Vec::new();
    for &rays in &all_rays {
        let settings = Settings {
            rays,
            aperture: args.aperture,
            seed: args.seed,
        };
        let bar = photon_bar(rays, args.quiet);
        let start = Instant::now();
        let traced = trace_forward(&scene, &settings, |n| bar.inc(n));
        let seconds = start.elapsed().as_secs_f64();
        bar.finish_and_clear();
        let run = Run {
            rays,
            error: rmse_clamped(&backward, &traced.image),
            noise: rmse(&expected, &traced.image),
            forward: traced,
            seconds,
        };
        println!(
            "{:>9} {:>11} {:>10.3e} {:>9} {:>10.5} {:>8.2} {:>10.4}{}",
            format!("{:e}", rays as f64),
            run.forward.counts.on_image,
            run.forward.share(),
            fmt_seconds(run.seconds),
            run.error,
            psnr(run.error),
            run.noise,
            if rays == args.rays { "  (--rays)" } else { "" }
        );
        runs.push(run);
    }
    println!(
        "RMSE and PSNR: against the backward picture, each channel clamped to [0, 1] as the PNG shows it;"
    );
    println!("noise RMSE: against the expected picture, unclamped.");

    let largest = runs.last().expect("at least one run");
    if largest.forward.counts.on_image == 0 {
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
    } else {
        let needed = rays_needed(largest.rays, largest.noise, TARGET);
        let rate = largest.rays as f64 / largest.seconds;
        println!(
            "\nnoise RMSE ≤ 1/255 (one 8-bit step) takes about {needed:.1e} photons \
             (N·noise² stays constant; from the run of {:e},\n  \
             whose {} photons on the image make this good to roughly ±{:.0}%),\n  \
             {:.0} photons reaching each pixel, about {} at this machine's {rate:.2e} photons/s;\n  \
             the backward picture needs one ray per pixel",
            largest.rays as f64,
            largest.forward.counts.on_image,
            100.0 / (largest.forward.counts.on_image as f64).sqrt(),
            needed * largest.forward.share() / f64::from(w * h),
            fmt_duration(needed / rate),
        );
    }

    let mut panels: Vec<&Image> = runs
        .iter()
        .filter(|run| strip_rays.contains(&run.rays))
        .map(|run| &run.forward.image)
        .collect();
    panels.push(&backward);
    let labels: Vec<String> = strip_rays
        .iter()
        .map(|&n| format!("forward {:e}", n as f64))
        .chain(["backward".to_owned()])
        .collect();
    if let Err(e) = strip(&panels).save_png(&args.output) {
        eprintln!("error: cannot write {}: {e}", args.output.display());
        return ExitCode::FAILURE;
    }
    println!(
        "wrote {} (left to right: {})",
        args.output.display(),
        labels.join(" | ")
    );
    ExitCode::SUCCESS
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
