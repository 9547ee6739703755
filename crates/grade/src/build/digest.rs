//! The hash that tells whether a student's files changed since the last run.

use std::hash::Hasher;

/// A 128-bit hash from two differently seeded std hashers: stable for a
/// given toolchain, which is all a cache needs (a new toolchain only
/// grades again).
pub struct Digest(std::hash::DefaultHasher, std::hash::DefaultHasher);

impl Default for Digest {
    fn default() -> Digest {
        let mut second = std::hash::DefaultHasher::new();
        second.write_u8(0x5a);
        Digest(std::hash::DefaultHasher::new(), second)
    }
}

impl Hasher for Digest {
    fn write(&mut self, bytes: &[u8]) {
        self.0.write(bytes);
        self.1.write(bytes);
    }

    fn finish(&self) -> u64 {
        self.0.finish()
    }
}

impl Digest {
    /// The hash, in 32 hex digits.
    pub fn hex(&self) -> String {
        format!("{:016x}{:016x}", self.0.finish(), self.1.finish())
    }
}
