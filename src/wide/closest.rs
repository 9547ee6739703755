//! The closest hit found so far while a ray walks the tree, as the leaves'
//! packets offer their hits.

use super::primitive::Weights;

/// The closest hit so far, chosen as chapter 2's loop chooses: the smallest
/// t, and of equal t's the object that comes first in the scene.
#[derive(Debug, Clone, Copy)]
pub struct Closest {
    /// Where hits are looked for: below t_max or, once one is found, up to
    /// and including its t (a tie may still win by its index). Kept, not
    /// worked out at each test: `next_up` is a few branches.
    limit: f32,
    /// t, object index, and the hit's barycentric weights if a triangle's.
    pub found: Option<(f32, u32, Weights)>,
}

impl Closest {
    pub fn new(t_max: f32) -> Closest {
        Closest {
            limit: t_max,
            found: None,
        }
    }

    /// Hits are looked for below this.
    #[inline]
    pub fn limit(&self) -> f32 {
        self.limit
    }

    /// A hit at t < limit(): kept if nearer, or as near and earlier.
    #[inline]
    pub fn offer(&mut self, (t, weights): (f32, Weights), object: u32) {
        if self
            .found
            .is_none_or(|(best, first, _)| t < best || object < first)
        {
            self.found = Some((t, object, weights));
            self.limit = t.next_up();
        }
    }
}
