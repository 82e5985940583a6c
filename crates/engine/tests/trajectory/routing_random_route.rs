//! RandomRouteAction (OpenSCENARIO 1.3, XSD `RandomRouteAction`): a random route drawn from the
//! run's seed and followed by the default controller (routing/random_route.rs).
//!
//! Fixture `files/position/random_route.xosc` on `two_junction_choice.xodr`: Driver starts on
//! road 1 at s = 10 (lane −1, driven towards +s) at 25 m/s with a RandomRouteAction in Init.
//! Road 1 is 100 m long and enters junction 100, whose connecting roads 11 and 12 (10 m each)
//! lead to road 2 and road 3: the one draw of the walk there decides the road. At t = 7 s the
//! car has driven 175 m: 90 m on road 1, 10 m on the connecting road, 75 m on road 2 or 3.

use crate::runtime_support;

use engine::EngineConfig;
use runtime_support::run_with;

/// Tolerance of s (m): 7 s at 25 m/s in steps of 0.05 s, summed in floating point.
const TOL: f64 = 1e-6;

fn road_at_7s(seed: u64) -> String {
    let path = crate::corpus::fixture("position").join("random_route.xosc");
    let config = EngineConfig {
        seed,
        ..EngineConfig::default()
    };
    let (_, frames, events) = run_with(&path, &[], config);
    assert!(
        !events.iter().any(|e| matches!(
            e,
            engine::EventRecord::Error { .. } | engine::EventRecord::Unsupported { .. }
        )),
        "seed {seed}: {events:?}"
    );
    let (road, lane, s, _, _) = frames.at("Driver", 7.0).road.clone().expect("on a road");
    assert_eq!(lane, -1);
    assert!((s - 75.0).abs() < TOL, "seed {seed}: s = {s}");
    road
}

#[test]
fn the_seed_draws_the_road_and_the_same_seed_draws_it_again() {
    let roads: Vec<String> = (0..24).map(road_at_7s).collect();
    // A fair draw between two successors: over 24 seeds both roads occur (the chance that one
    // never does is 2 · 2⁻²⁴).
    assert!(
        roads.iter().any(|r| r == "2") && roads.iter().any(|r| r == "3"),
        "{roads:?}"
    );
    for seed in [0, 5, 17] {
        assert_eq!(
            road_at_7s(seed),
            roads[seed as usize],
            "seed {seed} repeated"
        );
    }
}
