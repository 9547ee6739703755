//! Unused effects cost nothing: the complete tracer (chapter 7) against
//! chapter 3's own tracer, on chapter 3's default scene.
//!
//! Run with `cargo bench --bench effects`. Four renders are measured:
//! * `chapter 3`: chapter 3's tracer (Lambert, ambient, point and spot lights);
//! * `complete, chapter 3's effects`: the complete tracer on the scene with
//!   the effects chapter 3 cannot simulate switched off (here: shadows): the
//!   same picture, so any difference is the price of unused machinery. The
//!   scene calls for no secondary ray, so the complete tracer renders it
//!   with `Direct`;
//! * `Whitted tracer forced, chapter 3's effects`: the same, but with the
//!   full `Tracer` whatever the scene calls for: what that choice saves;
//! * `complete, all effects`: the complete tracer on the whole scene, which
//!   also traces shadow rays.
//!
//! Both tracers test every object in turn (no BVH), so that only the
//! effects differ.
//!
//! On a shared machine the speed drifts over the minutes a measurement
//! takes, so the renders are timed in alternation, round after round, and
//! the median of the per-round ratios is printed: drift affects both sides
//! of a ratio alike. (A plain harness: criterion's statistics add nothing
//! to that, and its build was a sixth of a fresh `cargo test`.)

use std::hint::black_box;
use std::time::{Duration, Instant};

use ch03_lambert::render_lambert;
use measure::bench::median;
use raybook::toolkit::{Image, Scene};
use raybook::tracer::{Termination, Tracer, render_complete, render_whitted};
use raybook::workbench::cli::EffectPlan;

/// Chapter 3's default scene, whole and with the effects chapter 3 cannot
/// simulate switched off.
fn scenes() -> (Scene, Scene) {
    let full = ch03_lambert::CHAPTER.default_scene().unwrap();
    let plan = EffectPlan::new(&raybook::CHAPTER, &full, &[]);
    let switched_off = plan.simulated.minus(ch03_lambert::CHAPTER.effects());
    let reduced = full.clone().without(switched_off);
    (full, reduced)
}

/// A render to time, and its name.
type Render<'a> = (&'static str, Box<dyn Fn() -> Image + 'a>);

/// The renders renders.
fn renders<'a>(full: &'a Scene, reduced: &'a Scene) -> Vec<Render<'a>> {
    let forced = Tracer {
        termination: Termination::of(reduced),
    };
    vec![
        ("chapter 3", Box::new(|| render_lambert(full, || {}).0)),
        (
            "complete, chapter 3's effects",
            Box::new(|| {
                render_complete(
                    reduced,
                    &reduced.objects[..],
                    Termination::of(reduced),
                    || {},
                )
                .0
            }),
        ),
        (
            "Whitted tracer forced, chapter 3's effects",
            Box::new(move || render_whitted(&forced, reduced, &reduced.objects[..], || {}).0),
        ),
        (
            "complete, all effects",
            Box::new(|| render_complete(full, &full.objects[..], Termination::of(full), || {}).0),
        ),
    ]
}

/// Times the renders in alternation and prints, for each, the median time
/// and the median ratio to chapter 3 within a round.
fn interleaved(renders: &[Render]) {
    const ROUNDS: usize = 21;
    const RENDERS_PER_ROUND: u32 = 10;
    let mut times = vec![Vec::new(); renders.len()];
    for _ in 0..ROUNDS {
        for (i, (_, render)) in renders.iter().enumerate() {
            let start = Instant::now();
            for _ in 0..RENDERS_PER_ROUND {
                black_box(render());
            }
            times[i].push(start.elapsed() / RENDERS_PER_ROUND);
        }
    }
    let ms = |d: &Duration| d.as_secs_f64() * 1e3;
    println!("\nin alternation, {ROUNDS} rounds of {RENDERS_PER_ROUND} renders each:");
    println!("| render | median time | median ratio to chapter 3 |");
    println!("| --- | ---: | ---: |");
    for (i, (name, _)) in renders.iter().enumerate() {
        let ratios = (times[i].iter().zip(&times[0])).map(|(t, base)| ms(t) / ms(base));
        let time = median(times[i].iter().map(ms));
        println!("| {name} | {time:.3} ms | {:.3} |", median(ratios));
    }
}

fn main() {
    let (full, reduced) = scenes();
    let renders = renders(&full, &reduced);
    assert_eq!(
        renders[0].1(),
        renders[1].1(),
        "the two tracers must make the same picture"
    );
    assert_eq!(renders[1].1(), renders[2].1(), "the choice changes nothing");
    interleaved(&renders);
}
