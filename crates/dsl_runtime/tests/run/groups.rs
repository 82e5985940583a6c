//! Vehicle groups (ASAM OpenSCENARIO DSL 2.1 §8.7.18): a common-route group over several lanes
//! fills the lanes from its own leftwards, a row at a time; random traffic is an error.
//! Expectations in the scenario files.

use crate::support::run;

const S_TOL: f64 = 1e-6;

#[test]
fn common_route_group_fills_the_lanes_row_by_row() {
    let r = run("common_route_group", 0, None);
    let expected = [(-3, 100.0), (-2, 100.0), (-1, 100.0), (-3, 85.0)];
    for (i, (lane, s0)) in expected.into_iter().enumerate() {
        let name = format!("g.vehicles[{i}]");
        let m = r.at(0.0, &name);
        assert_eq!(m.lane, lane, "{m:?}");
        assert!((m.s - s0).abs() < S_TOL, "{m:?}");
        assert!((r.at(2.0, &name).s - (s0 + 20.0)).abs() < S_TOL);
    }
}

#[test]
fn single_lane_group_places_its_first_member_and_the_rest_behind() {
    let r = run("single_lane_group", 0, None);
    for (i, s0) in [100.0, 85.0, 70.0].into_iter().enumerate() {
        let m = r.at(0.0, &format!("g.vehicles[{i}]"));
        assert_eq!(m.lane, -2, "{m:?}");
        assert!((m.s - s0).abs() < S_TOL, "{m:?}");
    }
}

#[test]
fn random_traffic_is_an_error() {
    crate::along::refused(
        "err_random_traffic",
        "found `g`, a random_traffic_vehicle_group (random traffic is not planned)",
        "5:8",
    );
}
