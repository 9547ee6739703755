//! Unused effects cost nothing: the complete tracer (chapter 7) against
//! chapter 3's own tracer, on chapter 3's default scene.
//!
//! Run with `cargo bench --bench effects`. Three measurements:
//! * `chapter 3`: chapter 3's tracer (Lambert, ambient, point and spot lights);
//! * `complete, chapter 3's effects`: the complete tracer on the scene with
//!   the effects chapter 3 cannot simulate switched off (here: shadows): the
//!   same picture, so any difference is the price of unused machinery;
//! * `complete, all effects`: the complete tracer on the whole scene, which
//!   also traces shadow rays.
//!
//! Both tracers test every object in turn (no BVH), so that only the
//! effects differ.

use ch03_lambert::render_lambert;
use criterion::{Criterion, criterion_group, criterion_main};
use raybook::toolkit::Scene;
use raybook::toolkit::cli::EffectPlan;
use raybook::tracer::{Termination, render_terminated};

fn scene() -> Scene {
    ch03_lambert::CHAPTER.default_scene().unwrap()
}

fn effects(c: &mut Criterion) {
    let full = scene();
    let chapter3 = ch03_lambert::CHAPTER;
    let plan = EffectPlan::new(&raybook::CHAPTER, &full, &[]);
    let switched_off = plan.simulated.minus(chapter3.effects);
    let reduced = full.clone().without(switched_off);
    assert_eq!(
        render_lambert(&full, || {}).0,
        render_terminated(&reduced, Termination::of(&reduced), || {}).0,
        "the two tracers must make the same picture"
    );

    let mut group = c.benchmark_group("chapter 3's default scene, 320x240");
    group.sample_size(30);
    group.bench_function("chapter 3", |b| b.iter(|| render_lambert(&full, || {})));
    group.bench_function("complete, chapter 3's effects", |b| {
        b.iter(|| render_terminated(&reduced, Termination::of(&reduced), || {}))
    });
    group.bench_function("complete, all effects", |b| {
        b.iter(|| render_terminated(&full, Termination::of(&full), || {}))
    });
    group.finish();
}

criterion_group!(benches, effects);
criterion_main!(benches);
