//! Small scenes cost no more than brute force: the complete tracer's BVH
//! (built anew for every render, as `raybook render` builds it) against
//! testing every object in turn, and against chapter 8's binary BVH, on
//! scenes of a handful to a few dozen objects.
//!
//! Run with `cargo bench --bench small`. Like `cargo bench --bench
//! effects`, the renders are timed in alternation, round after round, and
//! the median of the per-round ratios is printed, so that a shared
//! machine's drift affects both sides of a ratio alike. Each render must
//! make the same picture as brute force's, or the bench stops.

use raybook::scene_files;
use std::hint::black_box;
use std::path::Path;
use std::time::{Duration, Instant};

use measure::bench::median;
use raybook::scene_files::nff;
use raybook::toolkit::{Image, Scene};
use raybook::tracer::{Termination, render_complete};

/// Small scenes, at 256×192: tinyraytracer's, the SPD's smallest, and two
/// of the chapters'.
fn scenes() -> Vec<(String, Scene)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let toml = |path: &str| scene_files::load(root.join(path)).unwrap();
    let spd = |name: &str| nff::load(root.join("scenes/spd").join(name)).unwrap();
    let scenes = [
        ("tinyraytracer", toml("scenes/peers/tinyraytracer.toml")),
        ("balls-1", spd("balls-1.nff")),
        ("tetra-3", spd("tetra-3.nff")),
        (
            "chapter 5",
            toml("chapters/05-reflection/scenes/default.toml"),
        ),
        (
            "chapter 7",
            toml("chapters/07-termination/scenes/default.toml"),
        ),
    ];
    scenes
        .into_iter()
        .map(|(name, scene)| {
            let name = format!("{name} ({} objects)", scene.objects.len());
            (name, scene.with_size(256, 192))
        })
        .collect()
}

/// The three ways to trace a scene, each building its world inside the
/// render.
fn renders(scene: &Scene) -> [Box<dyn Fn() -> Image + '_>; 3] {
    let termination = Termination::of(scene);
    [
        Box::new(move || render_complete(scene, &scene.objects[..], termination, || {}).0),
        Box::new(move || {
            let bvh = ch08_bvh::Bvh::build(&scene.objects);
            render_complete(scene, &bvh, termination, || {}).0
        }),
        Box::new(move || render_complete(scene, &raybook::world(scene), termination, || {}).0),
    ]
}

/// Median times of the three renders in alternation, and the median ratio
/// of each to brute force's within a round.
fn interleaved(renders: &[Box<dyn Fn() -> Image + '_>; 3]) -> [(f64, f64); 3] {
    const ROUNDS: usize = 15;
    const RENDERS_PER_ROUND: u32 = 5;
    let mut times: [Vec<Duration>; 3] = Default::default();
    for _ in 0..ROUNDS {
        for (i, render) in renders.iter().enumerate() {
            let start = Instant::now();
            for _ in 0..RENDERS_PER_ROUND {
                black_box(render());
            }
            times[i].push(start.elapsed() / RENDERS_PER_ROUND);
        }
    }
    let ms = |d: &Duration| d.as_secs_f64() * 1e3;
    std::array::from_fn(|i| {
        let ratios = times[i].iter().zip(&times[0]).map(|(t, b)| ms(t) / ms(b));
        (median(times[i].iter().map(ms)), median(ratios))
    })
}

fn main() {
    // `cargo bench --bench small -- NAME`: only the scenes whose names
    // contain NAME.
    let only: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    println!(
        "| scene | brute force | chapter 8's BVH | complete tracer's BVH | BVH / brute force |"
    );
    println!("| --- | ---: | ---: | ---: | ---: |");
    for (name, scene) in scenes() {
        if !only.is_empty() && !only.iter().any(|o| name.contains(o.as_str())) {
            continue;
        }
        let renders = renders(&scene);
        let brute = renders[0]();
        for render in &renders[1..] {
            assert!(render() == brute, "{name}: a BVH changed the picture");
        }
        let [(brute, _), (binary, _), (wide, ratio)] = interleaved(&renders);
        println!("| {name} | {brute:.2} ms | {binary:.2} ms | {wide:.2} ms | {ratio:.2} |");
    }
    println!(
        "\n(256×192, median of 15 rounds of 5 renders each; the BVHs are built in every render)"
    );
}
