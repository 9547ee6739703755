//! How far two tracers' answers to the same rays agree: hit or miss, and
//! the distance.

/// Two distances agree if they differ by at most this fraction.
const T_TOLERANCE: f32 = 1e-4;

/// How far two tracers' answers to the same rays agree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Agreement {
    pub rays: usize,
    /// Rays one tracer calls a hit and the other a miss.
    pub hit_or_miss_differs: usize,
    /// Rays both hit.
    pub both_hit: usize,
    /// Rays both hit whose distances differ by more than `T_TOLERANCE` (10⁻⁴)
    /// of the larger.
    pub t_differs: usize,
}

impl Agreement {
    /// The fraction of rays both call a hit or both a miss.
    pub fn hit_or_miss(&self) -> f64 {
        fraction_but(self.hit_or_miss_differs, self.rays)
    }

    /// Of the rays both hit, the fraction whose distances agree (1 if none).
    pub fn t(&self) -> f64 {
        fraction_but(self.t_differs, self.both_hit)
    }
}

/// The fraction of `of` things that are not among `but`; 1 of none.
fn fraction_but(but: usize, of: usize) -> f64 {
    if of == 0 {
        1.0
    } else {
        (of - but) as f64 / of as f64
    }
}

/// Compares two tracers' hit distances for the same rays (+∞ for a miss).
pub fn agreement(ours: &[f32], theirs: &[f32]) -> Agreement {
    assert_eq!(ours.len(), theirs.len(), "the same rays");
    let pairs = || ours.iter().zip(theirs);
    let both = || pairs().filter(|(a, b)| a.is_finite() && b.is_finite());
    Agreement {
        rays: ours.len(),
        hit_or_miss_differs: pairs()
            .filter(|(a, b)| a.is_finite() != b.is_finite())
            .count(),
        both_hit: both().count(),
        t_differs: both()
            .filter(|&(a, b)| (a - b).abs() > T_TOLERANCE * a.max(*b))
            .count(),
    }
}

#[cfg(test)]
mod tests {
    use super::agreement;

    #[test]
    fn agreement_counts_hits_misses_and_distances() {
        let inf = f32::INFINITY;
        let ours = [1.0, 2.0, inf, inf, 4.0];
        let theirs = [1.0, 2.1, inf, 3.0, 4.0001];
        let a = agreement(&ours, &theirs);
        assert_eq!(a.hit_or_miss_differs, 1, "a miss against a hit");
        assert_eq!(a.hit_or_miss(), 0.8);
        assert_eq!((a.both_hit, a.t_differs), (3, 1), "2.0 against 2.1 differs");
        assert_eq!(a.t(), 2.0 / 3.0, "4.0 against 4.0001 is within 1e-4");
        let none = agreement(&[inf], &[inf]);
        assert_eq!(
            (none.hit_or_miss(), none.t()),
            (1.0, 1.0),
            "no hits: all agree"
        );
    }
}
