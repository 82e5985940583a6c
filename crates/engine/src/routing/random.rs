//! Weights of routeStrategy `random` (OpenSCENARIO 1.3 §7.5, XSD `RouteStrategy`: "random"):
//! each lane of each lane section gets a weight in [0.5, 1.5) that multiplies its length, and
//! the cheapest path under those weights is taken. A weight is a hash of the run's seed, the
//! route, the leg and the lane (SplitMix64, Steele, Lea & Flood, "Fast splittable
//! pseudorandom number generators", OOPSLA 2014), not a draw from a stream: it does not
//! depend on the order in which the search visits lanes, so a run with the same seed plans
//! the same route. Written by hand because a stateless hash is what is needed here, not a
//! generator crate's stream.

use opendrive::{LaneHandle, Real};

/// SplitMix64's output function applied to `x`.
pub(crate) fn mix(mut x: u64) -> u64 {
    x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// The key of one leg: the seed, the route's name (FNV-1a) and the leg's index.
pub(crate) fn leg_key(seed: u64, route: &str, leg: usize) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in route.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    mix(seed ^ mix(h ^ mix(leg as u64)))
}

/// The weight of lane `h` in the leg keyed `key`, in [0.5, 1.5).
pub(crate) fn lane_weight(key: u64, h: LaneHandle) -> Real {
    let lane = u64::from(h.lane as u32);
    let x = mix(key ^ mix(u64::from(h.road) << 32 | u64::from(h.section)) ^ mix(lane << 1));
    // The top 53 bits as a uniform number in [0, 1).
    0.5 + (x >> 11) as Real / (1u64 << 53) as Real
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_are_reproducible_and_in_range() {
        let h = LaneHandle {
            road: 3,
            section: 1,
            lane: -2,
        };
        let k = leg_key(42, "R", 0);
        assert_eq!(lane_weight(k, h).to_bits(), lane_weight(k, h).to_bits());
        assert_ne!(k, leg_key(43, "R", 0));
        let mut sum = 0.0;
        for road in 0..1000 {
            let w = lane_weight(k, LaneHandle { road, ..h });
            assert!((0.5..1.5).contains(&w));
            sum += w;
        }
        // Mean of 1000 uniform draws on [0.5, 1.5): 1 ± 0.03 (3.3 standard errors of 0.0091).
        assert!((sum / 1000.0 - 1.0).abs() < 0.03, "{sum}");
    }
}
