//! `yaw(…)` and `orientation(…)` relative to the road: zero angles hold where the vehicle does
//! not move sideways, another yaw where the actor stands or, with a non-physical movement
//! allowed, moves crabwise along its lane; other forms are errors. Expectations in the
//! scenario files.

use crate::along::refused;
use crate::support::run;

/// Heading on the straight road: float round-off.
const H_TOL: f64 = 1e-9;

#[test]
fn zero_orientation_relative_to_the_road_holds_where_planned() {
    let r = run("orientation_zero", 0, None);
    for t in [0.0, 1.0, 2.0, 6.0] {
        let h = r.at(t, "ego").h;
        assert!(h.abs() < H_TOL, "heading {h} at {t} s");
    }
    // Half way through the lane change the vehicle is turned: yaw(0deg) could not hold
    // throughout that phase (err_yaw_all).
    assert!(r.at(4.0, "ego").h.abs() > 1e-3);
    assert_eq!(r.at(6.0, "ego").lane, -2);
}

#[test]
fn orientations_the_planner_does_not_steer_are_errors() {
    refused(
        "err_yaw_all",
        "expected no lateral movement while yaw(…) at ",
        "8:9",
    );
    refused(
        "err_yaw_angle",
        "expected `ego` standing throughout the run with a yaw of 0.0873 rad relative to the road, or moving along its lane with physical_movement(prefer_non_physical) in every invocation of it, found it moving under the default physical_movement(must_be_physical) at",
        "7:13",
    );
    refused(
        "err_yaw_later",
        "expected yaw 0.5236 rad relative to the road (the yaw the actor stands at from its first phase), found 0.1745 rad",
        "14:30",
    );
    refused(
        "err_orientation_relative",
        "expected orientation(…) relative to the road, found relative_to:",
        "7:45",
    );
}

/// A standing actor keeps a yaw other than 0 relative to the road (yaw_parked.osc's comment).
#[test]
fn a_standing_actor_keeps_its_yaw_relative_to_the_road() {
    let r = run("yaw_parked", 0, None);
    let yaw = std::f64::consts::PI / 6.0;
    for t in [0.0, 3.0, 6.0] {
        let npc = r.at(t, "npc");
        assert!((npc.h - yaw).abs() < H_TOL, "heading {} at {t} s", npc.h);
        assert!(
            (npc.x - 100.0).abs() < H_TOL && (npc.y + 5.25).abs() < H_TOL,
            "{npc:?}"
        );
        assert!(r.at(t, "ego").h.abs() < H_TOL);
    }
}

#[test]
fn a_moving_actor_keeps_its_yaw_crabwise_where_non_physical_movement_is_allowed() {
    let r = run("yaw_crabwise", 0, None);
    let yaw = std::f64::consts::PI / 6.0;
    // x = 20 m + the distance along the lane; y the lane's centre throughout.
    for (t, x) in [(0.0, 20.0), (1.0, 30.0), (2.0, 40.0), (4.0, 70.0 + 0.25)] {
        let ego = r.at(t, "ego");
        assert!((ego.h - yaw).abs() < H_TOL, "heading {} at {t} s", ego.h);
        assert!(
            (ego.x - x).abs() < 1e-6,
            "x {} at {t} s, expected {x}",
            ego.x
        );
        assert!((ego.y + 5.25).abs() < H_TOL, "y {} at {t} s", ego.y);
    }
    assert!((r.at(4.0, "ego").speed - 20.0).abs() < H_TOL);
}

#[test]
fn a_moving_actor_with_a_yaw_under_must_be_physical_or_changing_lane_is_an_error() {
    refused(
        "err_yaw_crabwise_physical",
        "found it moving under the default physical_movement(must_be_physical) at",
        "10:17",
    );
    refused(
        "err_yaw_crabwise_physical",
        "err_yaw_crabwise_physical.osc:12:9: a vehicle or person moves along its heading",
        "10:17",
    );
    refused(
        "err_yaw_crabwise_lane",
        "found it moving sideways from 0.00 s (a crabwise movement keeps to the lane: no lane or offset change)",
        "8:13",
    );
}
