//! One route, one path: a RoutePosition (OpenSCENARIO 1.3 §7.5, XSD `InRoutePosition`) and an
//! AssignRouteAction on the same route with routeStrategy `random` agree for every run seed.
//!
//! Fixture `files/position/route_seed.xosc` on `two_junction_choice.xodr` (see
//! routing_strategies.rs): route "R" from road 1, s = 10 to road 4, s = 50, which runs either
//! over road 2 or over road 3; pathS 175 lies 75 m into whichever (90 m on road 1, 10 m on a
//! connecting road). Driver is assigned the route and drives it at 25 m/s from its first
//! waypoint, so at t = 175 / 25 = 7 s it is at pathS 175; Marker is teleported to pathS 175
//! of the same route at t = 0. Both must be on the same road, at s = 75.

use crate::runtime_support;

use engine::EngineConfig;
use runtime_support::run_with;

/// Tolerance of s (m): 7 s at 25 m/s in steps of 0.05 s, summed in floating point.
const TOL: f64 = 1e-6;

#[test]
fn a_random_route_is_one_path_to_a_route_position_and_to_the_controller() {
    let path = crate::corpus::fixture("position").join("route_seed.xosc");
    let mut roads_seen = Vec::new();
    for seed in 0..200 {
        let config = EngineConfig {
            seed,
            ..EngineConfig::default()
        };
        let (_, frames, _) = run_with(&path, &[], config);
        let road = |name: &str, t: f64| {
            let (road, _, s, _, _) = frames.at(name, t).road.clone().expect("on a road");
            assert!((s - 75.0).abs() < TOL, "seed {seed}: {name} at s = {s}");
            road
        };
        let marker = road("Marker", 0.0);
        assert_eq!(marker, road("Driver", 7.0), "seed {seed}");
        if !roads_seen.contains(&marker) {
            roads_seen.push(marker);
        }
    }
    roads_seen.sort();
    // routing_strategies.rs: road 2 for about one seed in 16, road 3 otherwise.
    assert_eq!(roads_seen, ["2", "3"]);
}
