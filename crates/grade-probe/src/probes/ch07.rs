//! Chapter 7: the weight criterion and the tracer's decision whether a ray
//! may go on.

use super::Probe;
use super::ch03::color;
use super::ch04::counts;
use crate::Case;
use crate::draw::{Rng, chance, number, show, whole};
use ch07_termination::toolkit::{Color, Stats};
use ch07_termination::{Termination, Tracer, Whitted};
use serde_json::json;

pub fn probes() -> Vec<Probe> {
    let probe = |id, case| Probe {
        id,
        chapter: "07-termination",
        tolerance: 1e-4,
        case,
    };
    vec![
        probe("ch07-below-threshold", below_threshold),
        probe("ch07-may-trace", may_trace),
    ]
}

/// A threshold: 0 one time in ten, else up to 0.2.
fn threshold(rng: &mut Rng) -> f32 {
    match chance(rng, 0.1) {
        true => 0.0,
        false => number(rng, 1e-3, 0.2),
    }
}

/// A weight whose channels lie around `min_weight`: each below it or
/// above it, so that the channels' maximum, minimum and mean disagree.
fn weight(rng: &mut Rng, min_weight: f32) -> Color {
    let mut channel = || match chance(rng, 0.4) {
        true => number(rng, 1.05, 3.0) * min_weight.max(1e-3),
        false => number(rng, 0.0, 0.95) * min_weight,
    };
    Color::new(channel(), channel(), channel())
}

/// `weight` with its largest channel set exactly to `min_weight`: not
/// below it.
fn at_threshold(weight: Color, min_weight: f32) -> Color {
    let largest = weight.max_element();
    Color::select(
        weight.cmpeq(Color::splat(largest)),
        Color::splat(min_weight),
        weight.min(Color::splat(min_weight)),
    )
}

/// One case in four has a channel exactly at the threshold (not below it).
fn below_threshold(rng: &mut Rng) -> Option<Case> {
    let min_weight = threshold(rng);
    let weight = weight(rng, min_weight);
    let weight = match chance(rng, 0.25) {
        true => at_threshold(weight, min_weight),
        false => weight,
    };
    let below = ch07_termination::below_threshold(weight, min_weight);
    Some(Case {
        input: format!("weight {}, min_weight {min_weight:?}", show(weight)),
        value: json!(below),
    })
}

/// The values: the answer and the counters (within the depth, relative to
/// the student's own `below_threshold`). Some rays are exactly at the
/// maximum depth, some weights exactly at the threshold: both may go on.
fn may_trace(rng: &mut Rng) -> Option<Case> {
    let termination = Termination {
        max_depth: whole(rng, 0, 6),
        min_weight: threshold(rng),
    };
    let depth = match chance(rng, 0.25) {
        true => termination.max_depth.max(1),
        false => whole(rng, 1, 8),
    };
    let weight = match whole(rng, 0, 9) {
        0..=2 => color(rng, 0.3, 1.0),
        3 | 4 => at_threshold(weight(rng, termination.min_weight), termination.min_weight),
        _ => weight(rng, termination.min_weight),
    };
    let mut stats = Stats::default();
    let tracer = Tracer { termination };
    let may = tracer.may_trace(depth, weight, &mut stats);
    let value = match depth > termination.max_depth {
        true => json!([may, counts(&stats)]),
        false => {
            // Within the depth, relative to the student's own
            // `below_threshold` (a mistake there costs that exercise
            // alone): whether the answer is its negation (may != below), and the
            // counters with the path it ends by the threshold taken off.
            let below = ch07_termination::below_threshold(weight, termination.min_weight);
            let mut counted = counts(&stats);
            counted[6] = json!(stats.ended_threshold as i64 - below as i64);
            json!([may != below, counted])
        }
    };
    Some(Case {
        input: format!(
            "depth {depth}, weight {}; max_depth {}, min_weight {:?}",
            show(weight),
            termination.max_depth,
            termination.min_weight
        ),
        value,
    })
}
