//! Chapter 2's rule for coincident surfaces in the same walk as the nearest
//! hit.
//!
//! The rule (`first_coincident`) needs the nearest hit N first: its window
//! (lower, upper) = t_N ∓ τ_N, with τ_N from N's error bound and normal
//! (`coincidence_window`), says which other hits count, and of those the
//! first listed object wins. A second walk through the tree finds them,
//! and costs about as much as the first. Here the first walk keeps them as
//! it goes: every hit it meets below a limit that N's window cannot pass,
//! however the nearest hit still changes. At the end, with N and its window
//! known, the kept hits are filtered.
//!
//! N is not known during the walk, and its window could be as wide as a
//! grazing ray makes it; so the limit is a guess, t plus a slack of
//! [`SLACK`]·(|r0|∞ + t) (N's window is a few ε of that over |n·rd|), and
//! the guess is checked at the end: if N's window reaches beyond the limit
//! the walk had, or more hits had to be kept than there is room for, the
//! second walk is taken as before. The answer is the rule's either way.
//!
//! Most rays keep nothing, and for them the end is one question, asked
//! without the window's division ([`window_fits`]): does N's window end
//! below the limit, with room to spare? Only a ray in doubt, or with kept
//! hits, works out the window itself.

use arrayvec::ArrayVec;

use super::closest::{Found, Offer};
use super::primitive::Weights;
use crate::tracer::{Hit, Ray};

/// The relative slack of the walk's limit beyond the nearest hit: 2⁻¹².
/// A window τ = (2e + 8ε(|r0|∞ + t)) / |n·rd|, with e a few ε of the
/// point's coordinates, is about 16ε(|r0|∞ + t)/|n·rd| = 2⁻¹⁹(|r0|∞ + t)/|n·rd|:
/// within the slack unless |n·rd| < 2⁻⁷ (a ray grazing the surface), or
/// the object is far larger than its distance (a sphere's error grows with
/// its radius). Those take the second walk.
pub(super) const SLACK: f32 = 1.0 / 4096.0;

/// The nearest hit, and the hits that may lie in its window, as the walk
/// offers them.
#[derive(Debug, Clone)]
pub struct Candidates<const KEEP: usize> {
    /// The nearest hit so far, chosen as [`Closest`](super::closest::Closest)
    /// chooses: the smallest t, of equal t's the first listed.
    pub nearest: Option<Found>,
    /// The walk's limit: the smallest of each nearest hit's t + slack so
    /// far. Every hit below it has been offered.
    limit: f32,
    /// Hits at or beyond the nearest's t, each listed before the nearest
    /// hit of the time it was kept.
    kept: ArrayVec<Found, KEEP>,
    /// More hits were to be kept than there is room for.
    overflowed: bool,
    /// |r0|∞: the slack's scale.
    origin: f32,
}

impl<const KEEP: usize> Candidates<KEEP> {
    pub fn new(t_max: f32, origin: f32) -> Candidates<KEEP> {
        Candidates {
            nearest: None,
            limit: t_max,
            kept: ArrayVec::new(),
            overflowed: false,
            origin,
        }
    }

    /// The first listed hit in (lower, upper), the window of the nearest
    /// hit `nearest` (which is [`Self::nearest`]); `Err(())` if the walk
    /// may have missed one (the second walk must look).
    pub fn first_within(
        &self,
        nearest: u32,
        (lower, upper): (f32, f32),
    ) -> Result<Option<Found>, ()> {
        if self.overflowed || upper > self.limit {
            return Err(());
        }
        let within = |&&(t, object, _): &&Found| object < nearest && t > lower && t < upper;
        Ok(self
            .kept
            .iter()
            .filter(within)
            .min_by_key(|hit| hit.1)
            .copied())
    }

    /// Is `nearest` (the hit of [`Self::nearest`]) surely the rule's answer?
    /// Yes if nothing was kept and its window ends, with room to spare,
    /// below the walk's limit: then no hit that the walk did not offer can
    /// lie in it. Most rays end here, without the window's division
    /// ([`window_fits`]); a ray in doubt takes the exact way, whose answer
    /// is the same.
    pub fn surely_nearest(&self, nearest: &Hit, ray: &Ray) -> bool {
        self.kept.is_empty()
            && !self.overflowed
            && window_fits(nearest, ray, self.origin, self.limit - nearest.t)
    }

    /// Keeps `hit`, which lies at or beyond the nearest hit and is listed
    /// before it. When there is no room, the hits that can no longer count
    /// make room: beyond the limit, or listed after the nearest hit (which
    /// is nearer, and counts wherever they would). Out of line: most rays
    /// keep nothing, and the walk's offers stay small.
    #[inline(never)]
    fn keep(&mut self, hit: Found) {
        if self.kept.is_full() {
            let (limit, first) = (self.limit, self.nearest.map_or(u32::MAX, |n| n.1));
            self.kept
                .retain(|&mut (t, object, _)| t < limit && object < first);
        }
        self.overflowed |= self.kept.try_push(hit).is_err();
    }
}

/// The walk's limit for a nearest hit at `t`: t + [`SLACK`]·(|r0|∞ + |t|),
/// or the next number above t if that rounds to t (t is 0 or subnormal).
/// The same as the larger of the two, since a number above t is at least
/// the next one; but the next one is worked out only where it is needed
/// (`next_up` is a few branches, and this is in every offer of the walk).
pub(super) fn reach(t: f32, origin: f32) -> f32 {
    let reach = t + SLACK * (origin + t.abs());
    if reach > t { reach } else { t.next_up() }
}

/// Is chapter 2's window τ = (2e + 8ε(|r0|∞ + t)) / |n·rd| of `hit`
/// (`coincidence_window`) surely no wider than half of `room`, so that
/// t + τ, rounded, stays below t + `room`? Asked without the division:
/// 2·(2e + 8ε(|r0|∞ + t)) ≤ room·|n·rd|, with `origin` = |r0|∞.
///
/// After the walk, the division by |n·rd| is the last of a chain of slow
/// steps from the hit record to the answer (the hit's normal takes a square
/// root and a division of its own), and the answer waits for it. The factor
/// 2 leaves room for the rounding of both sides (a few ε), and makes the
/// test only stricter than the exact window: a ray it leaves in doubt (a
/// grazing one, |n·rd| < 2⁻⁶ or so) works the window out exactly.
/// `tests.rs` checks it against `coincident_range`, grazing rays included.
/// (A product room·|n·rd| below f32's normal numbers, rounded by more than
/// its ε, is left in doubt too.)
pub fn window_fits(hit: &Hit, ray: &Ray, origin: f32, room: f32) -> bool {
    let rounding = 8.0 * f32::EPSILON * (origin + hit.t);
    let bound = room * hit.normal.dot(ray.direction).abs();
    bound >= f32::MIN_POSITIVE && 2.0 * (2.0 * hit.error + rounding) <= bound
}

impl<const KEEP: usize> Offer for Candidates<KEEP> {
    #[inline]
    fn limit(&self) -> f32 {
        self.limit
    }

    /// A nearer hit (or as near, listed earlier) becomes the nearest, and
    /// lowers the limit to its own; the one it replaces is kept if listed
    /// before it and still below the limit. A hit beyond the nearest is kept if listed before it:
    /// one listed after it can never win, since the nearest hit, nearer and
    /// listed earlier, lies in every window that it lies in.
    ///
    /// The hit is put together where it is stored, not once for both arms:
    /// kept aside for [`Self::keep`] (out of line), it was copied into
    /// [`Self::nearest`] 16 bytes at a time from three smaller writes, and
    /// the record of the hit after the walk read it back 4 bytes at a time
    /// out of one 16-byte write; both wait for the writes to reach the cache.
    #[inline(always)]
    fn offer(&mut self, (t, weights): (f32, Weights), object: u32) {
        match self.nearest {
            Some((best, first, _)) if t > best || (t == best && object > first) => {
                if object < first {
                    self.keep((t, object, weights));
                }
            }
            previous => {
                self.nearest = Some((t, object, weights));
                self.limit = self.limit.min(reach(t, self.origin));
                let limit = self.limit;
                if let Some(previous) = previous.filter(|p| p.1 < object && p.0 < limit) {
                    self.keep(previous);
                }
            }
        }
    }
}
