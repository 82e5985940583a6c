//! The random seed of each variant: a pure function of the batch's seed and the variant's
//! number, so a variant run alone (`oscsim batch DIST --only 17`, or `oscsim run SCENARIO
//! --param … --seed S` with the seed the batch reports) draws the same traffic and random
//! routes as in the batch, whatever the number of jobs or shards.
//!
//! `seed(run, i) = mix(run ⊕ mix(i))` with SplitMix64's finaliser as `mix` (Steele, Lea, Flood,
//! "Fast splittable pseudorandom number generators", OOPSLA 2014): neighbouring variants get
//! unrelated seeds. Written by hand: five lines of a published function.

/// SplitMix64's output function.
fn mix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// The seed of variant `variant` in a batch run with seed `run`.
pub fn variant_seed(run: u64, variant: u64) -> u64 {
    mix(run ^ mix(variant))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_depend_on_run_and_variant_only() {
        // SplitMix64 of 0 (the first output of a SplitMix64 stream started at 0) is
        // 0xE220A8397B1DCDAF, the value of the reference implementation.
        assert_eq!(mix(0), 0xE220_A839_7B1D_CDAF);
        assert_eq!(variant_seed(1, 17), variant_seed(1, 17));
        assert_ne!(variant_seed(1, 17), variant_seed(1, 18));
        assert_ne!(variant_seed(1, 17), variant_seed(2, 17));
    }
}
