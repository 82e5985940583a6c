//! OpenSCENARIO 2.0 §8.7.5.1.2 time_headway(): Δs along the road in the caller's direction
//! of travel divided by the caller's speed (see the module doc of `time_headway`), on corpus
//! roads. Road facts are in `domain_route_coords.rs`.

use std::f64::consts::PI;

use engine::domain::{DomainErrorKind, Vehicle, VehicleCategory};
use opendrive::{Pose, RoadNetwork};

use crate::domain_support;
use domain_support::{assert_close_opt, car_box, network, participant_with};

/// Road positions are Newton solutions to 1e-10 m; divided by speeds ≥ 10 m/s.
const TOL: f64 = 1e-8;

fn car(pose: Pose, speed: f64) -> Vehicle {
    Vehicle::new(
        participant_with(car_box(), pose, speed),
        VehicleCategory::Car,
        Vec::new(),
    )
    .expect("the box reaches behind the reference point")
}

fn headway(net: &RoadNetwork, a: &Vehicle, b: &Vehicle) -> Option<f64> {
    a.time_headway(net, b).expect("both on joined roads")
}

#[test]
fn time_headway_table() {
    let curve = network("esmini/xodr/curve_r100.xodr");
    let arc = |s: f64, speed: f64| {
        // Lane −1 on the arc at s, heading along the road (pose from the road model).
        car(
            curve.lane_pose("0", -1, s, 0.0).expect("s within the road"),
            speed,
        )
    };
    let straight = |x: f64, speed: f64| {
        car(
            Pose {
                x,
                y: -1.535,
                ..Pose::default()
            },
            speed,
        )
    };
    let cases = [
        // Straight: Δs = 140 − 100 = 40 m at 20 m/s → 2 s.
        (
            "reference ahead",
            straight(100.0, 20.0),
            straight(140.0, 5.0),
            Some(2.0),
        ),
        // Swapped: the reference is 40 m behind → −2 s (the time since the caller was there).
        (
            "reference behind",
            straight(140.0, 20.0),
            straight(100.0, 5.0),
            Some(-2.0),
        ),
        // Standing caller: it never reaches the reference.
        (
            "caller at rest",
            straight(100.0, 0.0),
            straight(140.0, 5.0),
            None,
        ),
        // On the arc: Δs = 550 − 530 = 20 along the reference line (not the 20.307 m of the
        // lane centre at radius 101.535, nor the chord) at 10 m/s → 2 s.
        ("curve r100", arc(530.0, 10.0), arc(550.0, 10.0), Some(2.0)),
    ];
    for (name, a, b, expected) in cases {
        assert_close_opt(name, headway(&curve, &a, &b), expected, TOL);
    }
}

#[test]
fn time_headway_against_s_in_lane_1() {
    // Lane 1 is driven towards −s (heading π on the straight). Caller at s = 200, reference at
    // s = 150: ahead by 50 m in the direction of travel; at 25 m/s → 2 s.
    let curve = network("esmini/xodr/curve_r100.xodr");
    let a = car(
        Pose {
            x: 200.0,
            y: 1.535,
            h: PI,
            ..Pose::default()
        },
        25.0,
    );
    let b = car(
        Pose {
            x: 150.0,
            y: 1.535,
            h: PI,
            ..Pose::default()
        },
        25.0,
    );
    let got = headway(&curve, &a, &b).expect("moving");
    assert!((got - 2.0).abs() < TOL, "{got}");
}

#[test]
fn time_headway_across_a_junction() {
    // common_junction_creator0: A on road 1 at s = 90, B on road 3 at s = 20 (lane −1).
    // Along the roads: (100 − 90) + 100.00000012397831 (road 100) + 20 = 130.00000012397831 m;
    // at 10 m/s → 13.000000012397831 s.
    let net = network("generated/xodr/common_junction_creator0.xodr");
    let a = car(
        Pose {
            x: 90.0,
            y: -1.5,
            ..Pose::default()
        },
        10.0,
    );
    let b = car(
        net.lane_pose("3", -1, 20.0, 0.0)
            .expect("road 3 is 100 m long"),
        10.0,
    );
    let got = headway(&net, &a, &b).expect("moving");
    let expected = (10.0 + 100.000_000_123_978_31 + 20.0) / 10.0;
    assert!((got - expected).abs() < TOL, "{got}");
}

#[test]
fn time_headway_into_a_connecting_road_and_back_across_the_junction() {
    let net = network("generated/xodr/common_junction_creator0.xodr");
    // B in lane 1 of connecting road 101 (junction 100, entered at its start from road 1's
    // end) at s = 60, past the part where the junction's roads overlap, heading along the
    // road. Along the roads B is (100 − 90) + 60 = 70 m ahead of A; at 10 m/s → 7 s.
    let a = car(
        Pose {
            x: 90.0,
            y: -1.5,
            ..Pose::default()
        },
        10.0,
    );
    let b = car(
        net.lane_pose("101", 1, 60.0, 0.0)
            .expect("road 101 is 80 m long"),
        10.0,
    );
    let got = headway(&net, &a, &b).expect("moving");
    assert!((got - 7.0).abs() < TOL, "{got}");
    // Seen from C on road 3 (s = 20, lane −1, heading +x), A is behind: the path leaves
    // road 3 at its start into the junction, runs road 100 backwards and enters road 1 at its
    // end: 20 + L100 + 10 = 130.00000012397831 m behind → −13.000000012397831 s at 10 m/s.
    let c = car(
        net.lane_pose("3", -1, 20.0, 0.0)
            .expect("road 3 is 100 m long"),
        10.0,
    );
    let got = headway(&net, &c, &a).expect("moving");
    let expected = -(20.0 + 100.000_000_123_978_31 + 10.0) / 10.0;
    assert!((got - expected).abs() < TOL, "{got}");
}

#[test]
fn time_headway_errors() {
    let curve = network("esmini/xodr/curve_r100.xodr");
    let a = car(
        Pose {
            x: 100.0,
            y: -1.535,
            ..Pose::default()
        },
        10.0,
    );
    let off = car(
        Pose {
            x: 250.0,
            y: 50.0,
            ..Pose::default()
        },
        10.0,
    );
    let err = a
        .time_headway(&curve, &off)
        .expect_err("reference off the road");
    assert_eq!(err.kind(), &DomainErrorKind::NotOnRoad);
    let two = network("generated/xodr/two_roads0.xodr");
    let p = car(
        Pose {
            x: 50.0,
            y: -1.5,
            ..Pose::default()
        },
        10.0,
    );
    let q = car(
        Pose {
            x: -1.5,
            y: 60.0,
            h: PI / 2.0,
            ..Pose::default()
        },
        10.0,
    );
    let err = p.time_headway(&two, &q).expect_err("unconnected roads");
    assert!(matches!(err.kind(), DomainErrorKind::NoRouteBetween { .. }));
}
