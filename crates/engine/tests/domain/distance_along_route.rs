//! OpenSCENARIO 2.0 §8.7.4.1.1 distance_along_route() on common_junction_creator0.xodr:
//! road "1" (100 m, x from 0 to 100) → junction "100"'s connecting road "100"
//! (100.00000012397831 m) → road "3" (100 m from x = 200), each entered at its start; right-hand
//! traffic, lanes 3 m wide. Route elements, compound routes both ways, a lane route, and the
//! error cases.

use engine::domain::{
    DomainErrorKind, Route, RouteDistanceEnum, RouteElement, RouteStretch, TrafficParticipant,
};
use opendrive::{LanePosition, Pose, RoadNetwork};

use crate::domain_support;
use domain_support::participant;

use RouteDistanceEnum::{FromEnd, FromStart};

/// Length of connecting road "100" (`road/@length`).
const L100: f64 = 100.00000012397831;

/// Road positions are Newton solutions to 1e-10 m.
const TOL: f64 = 1e-7;

fn network() -> RoadNetwork {
    domain_support::network("generated/xodr/common_junction_creator0.xodr")
}

fn road(id: &str) -> RouteElement {
    RouteElement::Road { road_id: id.into() }
}

fn check(net: &RoadNetwork, who: &TrafficParticipant, route: &Route, start: f64, end: f64) {
    let s = who
        .distance_along_route(net, route, FromStart)
        .expect("on the route");
    let e = who
        .distance_along_route(net, route, FromEnd)
        .expect("on the route");
    assert!(
        (s - start).abs() < TOL,
        "from start: got {s}, expected {start}"
    );
    assert!((e - end).abs() < TOL, "from end: got {e}, expected {end}");
}

#[test]
fn distance_along_a_route_element() {
    let net = network();
    // Road 1 alone, run towards +s: an object at s = 30 is 30 m past the start, 70 m
    // before the end.
    let route = Route::element(&net, &road("1")).expect("road 1 exists");
    assert!((route.length() - 100.0).abs() < 1e-12);
    check(
        &net,
        &participant(Pose {
            x: 30.0,
            y: -1.5,
            ..Pose::default()
        }),
        &route,
        30.0,
        70.0,
    );
    // Lane 1 of road 1 is driven towards −s (right-hand traffic), so its route starts at
    // s = 100: the object at s = 30 in lane 1 is 70 m past the start, 30 m before the end.
    let lane = RouteElement::Lane {
        road_id: "1".into(),
        lane_section: 0,
        lane_id: 1,
    };
    let route = Route::element(&net, &lane).expect("lane 1 exists");
    let in_lane_1 = participant(Pose {
        x: 30.0,
        y: 1.5,
        ..Pose::default()
    });
    check(&net, &in_lane_1, &route, 70.0, 30.0);
    // The same spot in lane −1 is not on that lane route.
    let in_lane_minus_1 = participant(Pose {
        x: 30.0,
        y: -1.5,
        ..Pose::default()
    });
    let err = in_lane_minus_1
        .distance_along_route(&net, &route, FromStart)
        .expect_err("other lane");
    assert_eq!(err.kind(), &DomainErrorKind::NotOnRoute);
}

#[test]
fn distance_along_a_compound_route() {
    let net = network();
    let b = participant(
        net.lane_pose("3", -1, 20.0, 0.0)
            .expect("road 3 is 100 m long"),
    );
    let a = participant(Pose {
        x: 30.0,
        y: -1.5,
        ..Pose::default()
    });
    // 1 → 100 → 3, all towards +s: B at s = 20 on road 3 is 100 + L100 + 20 from the start;
    // the route is 200 + L100 long, so B is 80 before the end.
    let forward = Route::compound(&net, &[road("1"), road("100"), road("3")]).expect("valid");
    assert!((forward.length() - (200.0 + L100)).abs() < 1e-9);
    check(&net, &b, &forward, 120.0 + L100, 80.0);
    check(&net, &a, &forward, 30.0, 170.0 + L100);
    // 3 → 100 → 1: road 3 leaves at its start into the junction, so every road is run
    // towards −s. A at s = 30 on road 1 is 100 + L100 + 70 from the start, 30 before the end.
    let back = Route::compound(&net, &[road("3"), road("100"), road("1")]).expect("valid");
    let dirs: Vec<bool> = back
        .stretches()
        .iter()
        .map(|st| st.s_end < st.s_start)
        .collect();
    assert_eq!(dirs, [true, true, true], "{:?}", back.stretches());
    check(&net, &a, &back, 170.0 + L100, 30.0);
}

#[test]
fn distance_along_a_lane_route() {
    let net = network();
    // The road model's lane route from road 1 lane −1 at s = 10 to road 3 lane −1 at s = 50:
    // 90 m on road 1, L100 on road 100, 50 on road 3. An object on road 100 at s = 50 is
    // 90 + 50 from the start.
    let from = LanePosition {
        road_id: "1".into(),
        lane_id: -1,
        s: 10.0,
        offset: 0.0,
    };
    let to = LanePosition {
        road_id: "3".into(),
        lane_id: -1,
        s: 50.0,
        offset: 0.0,
    };
    let lane_route = net.route(&from, &to).expect("the junction joins the roads");
    let route = Route::from_lane_route(&lane_route);
    assert!((route.length() - (140.0 + L100)).abs() < 1e-9);
    let c = participant(
        net.lane_pose("100", -1, 50.0, 0.0)
            .expect("road 100 exists"),
    );
    check(&net, &c, &route, 140.0, L100);
}

#[test]
fn distance_along_route_errors() {
    let net = network();
    let route = Route::compound(&net, &[road("1"), road("100"), road("3")]).expect("valid");
    // On road 2 (the other exit of the junction, from (150, 50) northwards): not on the route.
    let elsewhere = participant(net.lane_pose("2", -1, 50.0, 0.0).expect("road 2 exists"));
    let err = elsewhere
        .distance_along_route(&net, &route, FromStart)
        .expect_err("road 2");
    assert_eq!(err.kind(), &DomainErrorKind::NotOnRoute);
    assert!(err
        .to_string()
        .starts_with("expected a position on the route, found one off it"));
    // Off every road.
    let off = participant(Pose {
        x: 50.0,
        y: 40.0,
        ..Pose::default()
    });
    let err = off
        .distance_along_route(&net, &route, FromEnd)
        .expect_err("off road");
    assert_eq!(err.kind(), &DomainErrorKind::NotOnRoute);
    // Invalid routes.
    let err = Route::compound(&net, &[]).expect_err("empty");
    assert_eq!(
        err.to_string(),
        "expected a route of roads of the network, found no element"
    );
    let err = Route::element(&net, &road("7")).expect_err("unknown road");
    assert_eq!(
        err.to_string(),
        "expected a route of roads of the network, found unknown road 7"
    );
    let stretch = RouteStretch {
        road_id: "1".into(),
        lane_id: None,
        s_start: 0.0,
        s_end: 150.0,
    };
    let err = Route::new(&net, vec![stretch]).expect_err("beyond the road");
    assert!(
        matches!(err.kind(), DomainErrorKind::InvalidRoute { .. }),
        "{err}"
    );
}
