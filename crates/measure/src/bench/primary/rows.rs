//! The report's table: one row per scene, raybook's side and Embree's.

use super::compare::Agreement;
use crate::bench::table;

/// One scene's row.
pub(super) struct PrimaryTiming {
    pub(super) name: String,
    pub(super) primitives: usize,
    pub(super) rays: usize,
    pub(super) hits: usize,
    /// raybook's median time on one thread.
    pub(super) serial_seconds: f64,
    /// The same with chapter 8's binary BVH, the lesson's.
    pub(super) chapter8_seconds: f64,
    /// raybook's median time on all the threads.
    pub(super) parallel_seconds: f64,
    pub(super) embree: EmbreeResult,
}

/// Embree's side of a row.
pub(super) enum EmbreeResult {
    /// Why Embree did not run.
    Skipped(String),
    Timed {
        /// Median time of one thread.
        seconds: f64,
        /// Median time of as many processes as raybook's threads, each
        /// tracing its share of the rays (one thread's time if that is 1).
        parallel_seconds: f64,
        /// How many times as long as the fastest process the slowest took.
        uneven: f64,
        /// How its answers agree with raybook's.
        agreement: Agreement,
    },
}

/// The timings as a Markdown table, one row per scene.
///
/// Each side has a one-thread column and a per-thread column at `threads`;
/// the ratios compare one thread with one thread, raybook's threads with
/// Embree's one thread (the bench's first measure, which charges raybook
/// alone for threads that slow each other down), and each side's threads
/// with the other's, run under the same contention.
pub(super) fn timings_table(timings: &[PrimaryTiming], threads: u32) -> String {
    let per_thread = format!("raybook Mrays/s per thread, {threads} threads");
    let embree_per_thread = format!("Embree Mrays/s per thread, {threads} threads");
    let old_ratio = format!("raybook per thread, {threads} threads / Embree 1 thread");
    let same_ratio = format!("raybook per thread / Embree per thread, {threads} threads");
    let header = [
        "scene",
        "primitives",
        "rays",
        "hits",
        "chapter 8's BVH Mrays/s, 1 thread",
        "raybook Mrays/s, 1 thread",
        &per_thread,
        "Embree Mrays/s, 1 thread",
        &embree_per_thread,
        "raybook 1 thread / Embree 1 thread",
        &old_ratio,
        &same_ratio,
        "hit/miss agree",
        "t agrees (1e-4)",
    ];
    table::markdown(header, timings.iter().map(|t| t.cells(threads)), 1)
}

impl PrimaryTiming {
    /// The table's cells for this scene; where Embree did not run, its
    /// throughput cells say why and the others are dashes.
    fn cells(&self, threads: u32) -> [String; 14] {
        let mrays = |seconds: f64| self.rays as f64 / seconds / 1e6;
        let threads = f64::from(threads);
        let per_thread = mrays(self.parallel_seconds) / threads;
        let [
            embree,
            embree_per_thread,
            serial_ratio,
            old_ratio,
            ratio,
            hits_agree,
            t_agrees,
        ] = match &self.embree {
            EmbreeResult::Skipped(why) => {
                let dash = || "–".to_owned();
                [
                    why.clone(),
                    why.clone(),
                    dash(),
                    dash(),
                    dash(),
                    dash(),
                    dash(),
                ]
            }
            EmbreeResult::Timed {
                seconds,
                parallel_seconds,
                agreement,
                ..
            } => {
                let (one, each) = (mrays(*seconds), mrays(*parallel_seconds) / threads);
                let percent =
                    |f: f64, differ: usize| format!("{:.3} % ({differ} differ)", f * 100.0);
                [
                    format!("{one:.2}"),
                    format!("{each:.2}"),
                    format!("{:.2}", mrays(self.serial_seconds) / one),
                    format!("{:.2}", per_thread / one),
                    format!("{:.2}", per_thread / each),
                    percent(agreement.hit_or_miss(), agreement.hit_or_miss_differs),
                    percent(agreement.t(), agreement.t_differs),
                ]
            }
        };
        [
            self.name.clone(),
            self.primitives.to_string(),
            self.rays.to_string(),
            self.hits.to_string(),
            format!("{:.2}", mrays(self.chapter8_seconds)),
            format!("{:.2}", mrays(self.serial_seconds)),
            format!("{per_thread:.2}"),
            embree,
            embree_per_thread,
            serial_ratio,
            old_ratio,
            ratio,
            hits_agree,
            t_agrees,
        ]
    }
}
