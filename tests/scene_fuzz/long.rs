//! The long fuzz run, opt-in: mutated TOML scenes, NFF scenes and OBJ meshes
//! in turn, for as many seconds as `RAYBOOK_FUZZ_SECONDS` says, each batch
//! of cases from a new random seed (whatever `PROPTEST_RNG_SEED` says, so a
//! long run keeps finding new cases). Without the variable it does nothing,
//! so `cargo test` and CI never run it. Best in a release build:
//!
//! ```text
//! RAYBOOK_FUZZ_SECONDS=600 cargo test --release -p raybook --test scene_fuzz \
//!     fuzz_for_the_seconds_asked -- --nocapture
//! ```
//!
//! It stops at the first failure, with the smallest mutation proptest
//! found that still fails (a panic, a scene that renders to NaN, an error
//! that names the wrong file). A case that runs longer than a minute is a
//! hang: the watchdog prints it and ends the process.

use std::sync::Mutex;
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestError, TestRunner};

use super::mutate;

/// The variable that asks for a long run, in seconds.
const VARIABLE: &str = "RAYBOOK_FUZZ_SECONDS";

/// Cases in a batch: a batch ends within seconds, so the run ends close to
/// the time asked, and each batch draws from a new seed.
const BATCH: u32 = 200;

/// The case that is running and since when, for the watchdog.
static RUNNING: Mutex<Option<(Instant, String)>> = Mutex::new(None);

/// The formats fuzzed, in turn.
#[derive(Debug, Clone, Copy)]
pub enum Format {
    Toml,
    Nff,
    Obj,
}

/// Checks a mutated text of a format: `Ok(true)` if it rendered, `Ok(false)`
/// if it was refused well.
pub type Check = fn(Format, &str) -> Result<bool, TestCaseError>;

/// How many cases of a format ran, and how many of them rendered (the rest
/// were refused).
#[derive(Debug, Default, Clone, Copy)]
struct Counts {
    cases: u64,
    rendered: u64,
}

/// The test: runs batches until the time asked is up.
pub fn run(check: Check) {
    let Some(seconds) = std::env::var(VARIABLE)
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
    else {
        println!("set {VARIABLE}=N to fuzz the scene readers for N seconds");
        return;
    };
    start_watchdog();
    let (start, end) = (
        Instant::now(),
        Instant::now() + Duration::from_secs(seconds),
    );
    let mut counts = [Counts::default(); 3];
    let formats = [Format::Toml, Format::Nff, Format::Obj];
    for i in (0..formats.len()).cycle() {
        if Instant::now() >= end {
            break;
        }
        counts[i].rendered += batch(formats[i], check);
        counts[i].cases += u64::from(BATCH);
    }
    let total: u64 = counts.iter().map(|c| c.cases).sum();
    println!(
        "fuzzed {total} cases in {:.0} s, none failed",
        start.elapsed().as_secs_f64()
    );
    for (format, c) in formats.iter().zip(counts) {
        let refused = c.cases - c.rendered;
        println!(
            "{format:?}: {} cases, {} rendered, {refused} refused",
            c.cases, c.rendered
        );
    }
}

/// One batch of cases of `format`, from a new random seed: how many
/// rendered. Panics with the smallest failing case.
fn batch(format: Format, check: Check) -> u64 {
    let config = Config {
        cases: BATCH,
        rng_seed: RngSeed::Random,
        failure_persistence: None,
        ..Config::default()
    };
    let strategy = (
        any::<usize>(),
        prop::collection::vec(mutate::mutation(), 1..5),
    );
    let seeds = match format {
        Format::Toml => mutate::seeds(),
        Format::Nff => mutate::nff_seeds(),
        Format::Obj => mutate::obj_seeds(),
    };
    let tokens = match format {
        Format::Toml => mutate::TOKENS,
        Format::Nff => mutate::NFF_TOKENS,
        Format::Obj => mutate::OBJ_TOKENS,
    };
    let rendered = std::cell::Cell::new(0);
    let result = TestRunner::new(config).run(&strategy, |(seed, mutations)| {
        let text = mutate::mutated(&seeds, seed, &mutations, tokens);
        running(Some(format!("{format:?} seed {seed} {mutations:?}")));
        let checked = check(format, &text);
        running(None);
        rendered.set(rendered.get() + u64::from(checked?));
        Ok(())
    });
    match result {
        Ok(()) => rendered.get(),
        Err(TestError::Abort(reason)) => panic!("{format:?}: proptest gave up: {reason}"),
        Err(TestError::Fail(reason, (seed, mutations))) => {
            let text = mutate::mutated(&seeds, seed, &mutations, tokens);
            let kept = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
                .join(format!("scene_fuzz-failure-{}.txt", std::process::id()));
            std::fs::write(&kept, &text).ok();
            panic!(
                "{format:?} case failed: {reason}\nseed {seed}, mutations {mutations:?}; \
                 the mutated text is in {}",
                kept.display()
            );
        }
    }
}

/// Notes the case that starts (`Some`) or that ended (`None`).
fn running(case: Option<String>) {
    let mut running = RUNNING.lock().unwrap_or_else(|e| e.into_inner());
    *running = case.map(|case| (Instant::now(), case));
}

/// A thread that ends the process if a case runs longer than a minute.
fn start_watchdog() {
    std::thread::spawn(|| {
        loop {
            std::thread::sleep(Duration::from_secs(1));
            let running = RUNNING.lock().unwrap_or_else(|e| e.into_inner());
            if let Some((since, case)) = running.as_ref()
                && since.elapsed() > Duration::from_secs(60)
            {
                eprintln!("a case has run for a minute, a hang: {case}");
                std::process::abort();
            }
        }
    });
}
