//! Shared by the fuzz targets: deterministic numbers drawn from the input (so a crash input
//! replays exactly).

use std::hash::{DefaultHasher, Hash, Hasher};

/// A splitmix64 stream seeded by the input's hash.
pub struct Draws(u64);

#[allow(dead_code)] // Not every target draws every kind of number.
impl Draws {
    /// Seeded by `data`.
    pub fn new(data: &[u8]) -> Self {
        let mut h = DefaultHasher::new();
        data.hash(&mut h);
        Draws(h.finish())
    }

    /// The next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [−1, 1).
    pub fn signed(&mut self) -> f64 {
        self.unit() * 2.0 - 1.0
    }

    /// A coin toss.
    pub fn bool(&mut self) -> bool {
        self.next() & 1 == 1
    }
}
