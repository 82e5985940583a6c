//! `along(route)` and the modifiers that constrain a phase's motion without adding to it
//! (`keep_lane`, `keep_speed`, `physical_movement`, `movement_mode`, `avoid_collisions`,
//! `track`): each either shapes the plan or is an error before the run. Expectations are worked
//! by hand in the scenario files' comments.

use crate::ramp_lead;
use crate::support::{error, lower_at, run, run_scenario};

/// Asserts that `tests/scenarios/NAME.osc` does not plan, with `message` in the error at
/// `NAME.osc:LINE:COL` (its own place, the end of the message).
pub(crate) fn refused(name: &str, message: &str, at: &str) {
    let e = error(name);
    assert!(
        e.contains(message) && e.ends_with(&format!("{name}.osc:{at}")),
        "{e}"
    );
}

/// Positions on straight roads: float round-off only.
const S_TOL: f64 = 1e-6;

#[test]
fn along_a_named_lane_drives_on_that_road_from_its_offset() {
    let lowered = lower_at(
        "tests/scenarios/along_odr_point.osc",
        "tests/roads/two_roads.xodr",
        0,
        None,
    )
    .expect("plans");
    let r = run_scenario("along_odr_point", &lowered.scenario, 0, None);
    let ego = r.at(0.0, "ego");
    assert_eq!(ego.lane, -2);
    assert!((ego.s - 50.0).abs() < S_TOL, "{ego:?}");
    assert!(
        (ego.x - 5.25).abs() < S_TOL && (ego.y - 150.0).abs() < S_TOL,
        "{ego:?}"
    );
    let ego = r.at(3.0, "ego");
    assert!(
        (ego.s - 80.0).abs() < S_TOL && (ego.y - 180.0).abs() < S_TOL,
        "{ego:?}"
    );
    let npc = r.at(0.0, "npc");
    assert_eq!(npc.lane, -2);
    assert!((npc.y - 170.0).abs() < S_TOL, "{npc:?}");
    assert!((r.at(3.0, "npc").y - 200.0).abs() < S_TOL);
}

#[test]
fn actors_along_one_free_lane_route_share_its_lane() {
    let r = run("along_shared_lane", 0, None);
    for (name, s0, s4) in [("ego", 50.0, 90.0), ("npc", 70.0, 110.0)] {
        let a = r.at(0.0, name);
        assert_eq!(a.lane, -2, "{name}");
        assert!(
            (a.y + 5.25).abs() < S_TOL && (a.s - s0).abs() < S_TOL,
            "{a:?}"
        );
        assert!((r.at(4.0, name).s - s4).abs() < S_TOL, "{name}");
    }
    refused("err_along_free_lane", "expected `npc` in the lane of route `r` (lane -2, where `ego` drives along it), found lane -3", "15:13");
}

#[test]
fn routes_that_cannot_be_followed_are_errors_before_the_run() {
    // The message names the along(…) it contradicts, at 7:9.
    refused(
        "err_along_lane_change",
        "expected no lane change along the route along lane -2 of road 1 from s = 0 m (one lane, along(…) at ",
        "9:9",
    );
    refused(
        "err_along_lane_change",
        "err_along_lane_change.osc:7:9), found `change_lane(…)` at ",
        "9:9",
    );
    refused(
        "err_along_end_offset",
        "between s = 0.00 m and 100.00 m at the phase end, found it at s = 130.00 m",
        "8:9",
    );
    refused("err_along_off_road", "expected `ego` on route `r` between s = 0.00 m and 1000.00 m at the phase end, found it at s = 1050.00 m", "8:9");
    refused(
        "err_along_free_offset",
        "expected no start_offset on `r`, a route the runtime chooses",
        "7:32",
    );
    refused(
        "err_along_path",
        "found `p`, a path nothing defines (no points to follow)",
        "7:15",
    );
    let e = match lower_at(
        "tests/scenarios/err_along_two_roads.osc",
        "tests/roads/two_roads.xodr",
        0,
        None,
    ) {
        Ok(_) => panic!("planned"),
        Err(e) => e.to_string(),
    };
    assert!(
        e.contains(
            "expected every named route on the roads the plan drives on (2: road 2 and the roads the engine drives onto after it), found road 1"
        ) && e.contains("err_along_two_roads.osc:12:13"),
        "{e}"
    );
}

#[test]
fn keep_and_physical_modifiers_forbid_what_contradicts_them() {
    refused(
        "err_keep_speed",
        "expected no speed change beside keep_speed() at ",
        "7:9",
    );
    refused(
        "err_keep_speed",
        "err_keep_speed.osc:6:9, found `change_speed(…)` at ",
        "7:9",
    );
    refused(
        "err_keep_lane",
        "expected no lane change beside keep_lane()",
        "7:9",
    );
    refused(
        "err_physical_step",
        "found a step of speed from 10.00 m/s to 20.00 m/s",
        "10:13",
    );
    let r = run("physical_change", 0, None);
    assert!((r.at(2.0, "ego").s - 40.0).abs() < S_TOL);
    assert!((r.at(4.0, "ego").s - (70.0 + ramp_lead(5.0, 2.0))).abs() < S_TOL);
    assert!((r.at(4.0, "ego").speed - 20.0).abs() < S_TOL);
    refused(
        "err_avoid_collisions",
        "expected no distance planned beside avoid_collisions(true) at ",
        "8:9",
    );
}

#[test]
fn monotonous_movement_is_planned_or_refused() {
    refused(
        "err_monotonous",
        "found it needs 30.00 m/s half way",
        "17:13",
    );
    let r = run("monotonous_position", 0, None);
    // Two ramps of 5/3 m/s² over 3 s each.
    let a = 5.0 / 3.0;
    assert!((r.at(3.0, "npc").s - (157.5 + ramp_lead(a, 3.0))).abs() < S_TOL);
    assert!((r.at(3.0, "npc").speed - 25.0).abs() < S_TOL);
    assert!((r.at(6.0, "npc").s - (240.0 + ramp_lead(a, 6.0))).abs() < S_TOL);
    assert!((r.at(6.0, "ego").s - 220.0).abs() < S_TOL);
}

#[test]
fn arguments_the_planner_would_not_read_are_errors() {
    refused(
        "err_two_references",
        "expected one of the reference objects in position(…), found a second one",
        "7:46",
    );
    refused(
        "err_lane_from_reference",
        "expected from: in lane(…) without a reference object",
        "7:49",
    );
}

#[test]
fn keep_position_stands_still() {
    let r = crate::support::run("keep_position", 0, None);
    for t in [0.0, 3.0, 6.0] {
        let npc = r.at(t, "npc");
        assert!(
            npc.lane == -2 && (npc.s - 100.0).abs() < S_TOL && npc.speed == 0.0,
            "{npc:?}"
        );
    }
    assert!((r.at(3.0, "ego").s - 50.0).abs() < S_TOL);
    // Braking at −5 m/s²: the engine's step lags the exact integral by 5·dt/2 per second.
    let braked = 60.0 - crate::ramp_lead(5.0, 2.0);
    assert!((r.at(5.0, "ego").s - braked).abs() < S_TOL);
    assert!((r.at(6.0, "ego").s - braked).abs() < S_TOL);
    refused(
        "err_keep_position_moving",
        "expected `ego` standing at the start of keep_position(), found it at 10.00 m/s",
        "9:13",
    );
    refused(
        "err_keep_position_change",
        "expected no movement beside keep_position() at ",
        "8:9",
    );
}
