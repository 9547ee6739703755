//! The tests' random numbers.

use ch00_toolkit::Vec3;

/// A small deterministic generator (xorshift64*): a test that searches
/// with it finds the same rays on every run.
pub struct Rng(pub u64);

impl Rng {
    /// A float in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 40; // 24 bits
        lo + (hi - lo) * (bits as f32 / (1u64 << 24) as f32)
    }

    /// A vector whose coordinates are each in [lo, hi).
    pub fn vec(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }

    /// A random unit vector.
    pub fn unit(&mut self) -> Vec3 {
        loop {
            let v = self.vec(-1.0, 1.0);
            if (0.01..=1.0).contains(&v.length_squared()) {
                return v.normalize();
            }
        }
    }
}
