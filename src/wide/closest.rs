//! The closest hit found so far while a ray walks the tree, as the leaves'
//! packets offer their hits.

use super::primitive::Weights;

/// A hit a packet found: t, the object's index, and the hit's barycentric
/// weights if a triangle's.
pub type Found = (f32, u32, Weights);

/// What a walk through the tree offers its hits to: the nearest hit alone
/// ([`Closest`]), or the nearest with the hits that may coincide with it
/// (`rule.rs`).
pub trait Offer {
    /// Hits are looked for below this; the walk skips every box the ray
    /// enters only beyond it.
    fn limit(&self) -> f32;

    /// A hit at t < limit() of `object`.
    fn offer(&mut self, hit: (f32, Weights), object: u32);
}

/// The closest hit so far, chosen as chapter 2's loop chooses: the smallest
/// t, and of equal t's the object that comes first in the scene. Or, for
/// the second look that chapter 2's rule for coincident surfaces takes
/// (`first_coincident`), the first listed object hit below a fixed limit.
#[derive(Debug, Clone, Copy)]
pub struct Closest {
    /// Where hits are looked for: below t_max or, once one is found, up to
    /// and including its t (a tie may still win by its index). Kept, not
    /// worked out at each test: `next_up` is a few branches. For the rule,
    /// the end of the window, fixed.
    limit: f32,
    /// For the rule: only objects listed before this one can win.
    before: Option<u32>,
    pub found: Option<Found>,
}

impl Closest {
    pub fn new(t_max: f32) -> Closest {
        Closest {
            limit: t_max,
            before: None,
            found: None,
        }
    }

    /// The rule's search: of the objects listed before `before`, the first
    /// hit below `upper`.
    pub fn first_before(before: u32, upper: f32) -> Closest {
        Closest {
            limit: upper,
            before: Some(before),
            found: None,
        }
    }
}

impl Offer for Closest {
    #[inline]
    fn limit(&self) -> f32 {
        self.limit
    }

    /// Kept if nearer, or as near and earlier; for the rule, if listed
    /// before every other found.
    #[inline]
    fn offer(&mut self, (t, weights): (f32, Weights), object: u32) {
        if let Some(before) = self.before {
            if object < before {
                self.found = Some((t, object, weights));
                self.before = Some(object);
            }
            return;
        }
        if self
            .found
            .is_none_or(|(best, first, _)| t < best || object < first)
        {
            self.found = Some((t, object, weights));
            self.limit = t.next_up();
        }
    }
}
