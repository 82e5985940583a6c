//! Random streams of the traffic actions: one ChaCha8 generator per action, seeded with the
//! run's seed and set to the stream numbered by a 64-bit FNV-1a hash of the action's name, so
//! that adding or removing one traffic action leaves every other action's draws unchanged and
//! the same seed gives the same traffic on every platform (ChaCha's output is specified
//! bit for bit, rand_chacha 0.3).
//!
//! FNV-1a is written out here: it is eight lines, and the standard library's hasher is not
//! guaranteed stable across Rust releases.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The stream of the traffic action called `name` under the run's `seed`.
pub(crate) fn stream(seed: u64, name: &str) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(fnv1a(name));
    rng
}

/// 64-bit FNV-1a of `text` (offset basis 0xcbf29ce484222325, prime 0x100000001b3).
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// An index drawn with probability proportional to `weights` (non-finite or negative weights
/// count as 0); `None` when no weight is positive.
pub(crate) fn weighted(rng: &mut ChaCha8Rng, weights: impl Iterator<Item = f64>) -> Option<usize> {
    let w: Vec<f64> = weights
        .map(|w| if w.is_finite() && w > 0.0 { w } else { 0.0 })
        .collect();
    let total: f64 = w.iter().sum();
    if total <= 0.0 {
        return None;
    }
    let mut x = rng.gen::<f64>() * total;
    for (i, wi) in w.iter().enumerate() {
        if x < *wi {
            return Some(i);
        }
        x -= wi;
    }
    w.iter().rposition(|wi| *wi > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a test vectors of the reference (Fowler, Noll, Vo): "" → 0xcbf29ce484222325,
    /// "a" → 0xaf63dc4c8601ec8c, "foobar" → 0x85944171f73967e8.
    #[test]
    fn fnv1a_matches_the_reference_vectors() {
        assert_eq!(fnv1a(""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a("a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a("foobar"), 0x8594_4171_f739_67e8);
    }
}
