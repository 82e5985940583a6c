//! `yaw(…)` and `orientation(…)` relative to the road: zero angles hold where the vehicle does
//! not move sideways, another yaw where the actor stands or, with a non-physical movement
//! allowed, moves crabwise along its lane; other forms are errors. Expectations in the
//! scenario files.

use crate::along::refused;
use crate::support::{lower_at, run, run_on};

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
        "expected measured_by: relative_to_reference beside relative_to: (the angle between the two objects' axes), found measured_by: relative_to_road, which measures from no object",
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

/// Headings on bend.xodr's arc: the engine steps along the lane at 0.05 s, its heading the
/// road's at the s it reaches (by hand in the scenario file to 1e-5 rad).
pub(crate) const ARC_TOL: f64 = 1e-4;

/// The difference of two headings on the circle (rad).
pub(crate) fn turn(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// Yaws measured in the world (absolute, relative to north) and from another object
/// (length_to_width, length_to_length) on bend.xodr (yaw_world.osc's comment).
#[test]
fn yaws_measured_in_the_world_or_from_another_object_are_the_actors_headings() {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};
    let r = run_on("yaw_world", "bend");
    for t in [0.0, 7.5, 15.0] {
        for (who, h) in [
            ("npc", FRAC_PI_2),
            ("bus", FRAC_PI_4),
            ("truck", -FRAC_PI_2),
            ("post", std::f64::consts::FRAC_PI_6),
        ] {
            let got = r.at(t, who).h;
            assert!(
                turn(got, h) < H_TOL,
                "{who} heading {got} at {t} s, expected {h}"
            );
        }
    }
    for t in [0.0, 2.5, 5.0] {
        for who in ["ego", "car"] {
            let got = r.at(t, who).h;
            assert!(turn(got, 0.0) < H_TOL, "{who} heading {got} at {t} s");
        }
    }
    // ego in lane -3 (radius 108.75 m on the arc): s = 100 + 70 / 1.0875 m at 15 s, heading
    // 0.01 (s - 100) = 0.643678 rad.
    let h = 70.0 / 1.0875 * 0.01;
    let got = r.at(15.0, "ego").h;
    assert!(
        turn(got, h) < ARC_TOL,
        "ego heading {got} at 15 s, expected {h}"
    );
}

/// Yaws in the world or from another object that the plan's headings do not meet, or that the
/// plan cannot measure: errors at the angle (by hand in the scenario files).
#[test]
fn yaws_measured_in_the_world_or_from_another_object_that_do_not_hold_are_errors() {
    refused_on(
        "err_yaw_world_end",
        "expected `ego` at heading 0.6880 rad (the angle 0.6880 rad, absolute) at 15.00 s, found it at 0.6437 rad, its lane's heading 0.6437 rad",
        "13:30",
    );
    refused_on(
        "err_yaw_relative_end",
        "expected `car` at heading 0.6437 rad (the angle 0.0000 rad, length_to_length from `ego`, `ego` heading 0.6437 rad) at 15.00 s, found it at 0.6651 rad, its lane's heading 0.6651 rad",
        "23:21",
    );
    refused_on(
        "err_yaw_road_after_north",
        "expected `npc` at heading 0.5000 rad (the angle 0.0000 rad, relative to the road) at 2.00 s, found it at 1.5708 rad, its lane's heading 0.5000 rad",
        "14:17",
    );
    refused(
        "err_yaw_relative_measure",
        "expected measure_by: length_to_length, length_to_width, width_to_length or width_to_width beside relative_to: (the angle between the two objects' axes), found measure_by: relative_to_road, which measures from no object",
        "7:32",
    );
    refused(
        "err_yaw_measure_without_object",
        "expected relative_to: (the object whose axes the angle is measured from) beside measure_by: width_to_width, found none",
        "6:31",
    );
}

/// `refused` on bend.xodr.
fn refused_on(name: &str, message: &str, at: &str) {
    let e = lower_at(
        &format!("tests/scenarios/{name}.osc"),
        "tests/roads/bend.xodr",
        0,
        None,
    )
    .err()
    .unwrap_or_else(|| panic!("{name} lowers"))
    .to_string();
    assert!(
        e.contains(message) && e.ends_with(&format!("{name}.osc:{at}")),
        "{e}"
    );
}

/// A moving actor with a heading in the world other than its lane's: crabwise where a
/// non-physical movement is allowed, an error under must_be_physical (the scenario files).
#[test]
fn a_moving_actor_facing_north_moves_crabwise_only_where_non_physical_movement_is_allowed() {
    let r = run("yaw_north_crabwise", 0, None);
    let north = std::f64::consts::FRAC_PI_2;
    for t in [0.0, 1.0, 2.0] {
        let ego = r.at(t, "ego");
        assert!(turn(ego.h, north) < H_TOL, "heading {} at {t} s", ego.h);
        let x = 20.0 + 10.0 * t;
        assert!(
            (ego.x - x).abs() < 1e-6,
            "x {} at {t} s, expected {x}",
            ego.x
        );
        assert!((ego.y + 5.25).abs() < H_TOL, "y {} at {t} s", ego.y);
    }
    refused(
        "err_yaw_north_moving",
        "expected `ego` standing throughout the run with a yaw of 1.5708 rad relative to the road, or moving along its lane with physical_movement(prefer_non_physical) in every invocation of it, found it moving under the default physical_movement(must_be_physical)",
        "10:13",
    );
}

/// Yaws measured in the world or from another object for actors driving against s (facing -s,
/// the road's heading turned by pi) and for a reference that does, on bend.xodr
/// (yaw_against.osc's comment, by hand there).
#[test]
fn yaws_measured_in_the_world_or_from_another_object_hold_for_actors_driving_against_s() {
    use std::f64::consts::{FRAC_PI_4, PI};
    let r = run_on("yaw_against", "bend");
    for t in [0.0, 2.5, 5.0] {
        for (who, h) in [("car", PI), ("post", FRAC_PI_4), ("ego", 0.0), ("bus", PI)] {
            let got = r.at(t, who).h;
            assert!(
                turn(got, h) < H_TOL,
                "{who} heading {got} at {t} s, expected {h}"
            );
        }
    }
    // bus on the straight at 10 m/s towards -x: x = 90 - 10 t.
    let bus = r.at(5.0, "bus");
    assert!((bus.x - 40.0).abs() < 1e-6 && bus.lane == 1, "{bus:?}");
    // npc 50 m along lane 2 (radius 94.75 m) from s = 180 m: s = 180 - 50 / 0.9475 m, heading
    // 0.01 (s - 100) + pi.
    let s = 180.0 - 50.0 / 0.9475;
    let h = 0.01 * (s - 100.0) + PI;
    let npc = r.at(5.0, "npc");
    assert!(turn(npc.h, h) < ARC_TOL, "npc {npc:?}, expected h {h}");
    assert!(
        (npc.s - s).abs() < 1e-2 && npc.lane == 2,
        "npc {npc:?}, expected s {s}"
    );
}

/// A heading asked of an actor driving against s as if it faced +s: an error at the angle
/// naming its heading, the road's turned by pi (err_yaw_against_end.osc).
#[test]
fn a_yaw_in_the_world_that_an_actor_driving_against_s_does_not_face_is_an_error() {
    refused_on(
        "err_yaw_against_end",
        "expected `npc` at heading 0.2723 rad (the angle 0.2723 rad, absolute) at 5.00 s, found it at -2.8693 rad, its lane's heading -2.8693 rad",
        "20:30",
    );
}
