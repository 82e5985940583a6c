//! Actors that drive against s (oncoming traffic): placed, planned and lowered in the distance
//! along their direction of travel, driven by the engine in their lane's driving direction.
//! Every expectation is worked by hand in the scenario's comment.

use std::f64::consts::PI;

use crate::support::{error_on, phases_are, run_on, run_to_error_on, DT};

/// Positions on straight roads: the engine integrates speed exactly; float round-off only.
const S_TOL: f64 = 1e-6;
/// Headings (rad).
const H_TOL: f64 = 1e-9;
/// Event times are step times.
const T_TOL: f64 = 1e-9;
/// Across a spiral the engine steps the curvature per step (1 cm, as in run::map).
const SPIRAL_TOL: f64 = 0.01;
/// Along the road during a sinusoidal lane change: the change's cost Δ²π²/(16·T·v) is the
/// small-slope approximation of the path's extra length (within 1 mm for 3.5 m over 40 m).
const COST_TOL: f64 = 1e-3;

/// `tests/scenarios/NAME.osc` on `tests/roads/ROAD.xodr` runs to its end with no error record
/// (the engine's checks at run time passed).
pub(crate) fn ends_without_error(name: &str, road: &str) {
    let (failed, errors) = run_to_error_on(name, road);
    assert!(
        failed.is_none() && errors.is_empty(),
        "{name}: {failed:?} {errors:?}"
    );
}

/// The angle `a` (rad) in (−π, π].
pub(crate) fn wrap(a: f64) -> f64 {
    let r = a.rem_euclid(2.0 * PI);
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

/// The engine moves each step at the step's end speed: during a linear change at `a` m/s² it
/// is ahead of the exact integral by a·dt/2 per second of the change.
fn ramp_lead(a: f64, seconds: f64) -> f64 {
    0.5 * a * DT * seconds
}

#[test]
fn an_oncoming_actor_drives_its_lane_against_s_measured_along_its_direction_of_travel() {
    let r = run_on("opposite_one_road", "straight");
    let ego = r.at(0.0, "ego");
    assert_eq!(ego.lane, -1);
    assert!(
        (ego.x - 20.0).abs() < S_TOL && (ego.y + 1.75).abs() < S_TOL,
        "{ego:?}"
    );
    assert!((r.at(6.0, "ego").x - 80.0).abs() < S_TOL);
    // npc: u = 100 m is s = 900 m, in lane 1, heading pi.
    let npc = r.at(0.0, "npc");
    assert_eq!((npc.road.as_str(), npc.lane), ("1", 1), "{npc:?}");
    assert!((npc.s - 900.0).abs() < S_TOL, "{npc:?}");
    assert!(
        (npc.x - 900.0).abs() < S_TOL && (npc.y - 1.75).abs() < S_TOL,
        "{npc:?}"
    );
    assert!(wrap(npc.h - PI).abs() < H_TOL, "{npc:?}");
    assert!((npc.speed - 20.0).abs() < S_TOL);
    let at2 = r.at(2.0, "npc");
    assert!((at2.x - 860.0).abs() < S_TOL, "{at2:?}");
    // Half way through 20 -> 10 m/s: 15 m/s, 35 m on (less the engine's step lead).
    let at4 = r.at(4.0, "npc");
    assert!((at4.speed - 15.0).abs() < S_TOL, "{at4:?}");
    assert!(
        (at4.x - (860.0 - 35.0 - ramp_lead(-2.5, 2.0))).abs() < S_TOL,
        "{at4:?}"
    );
    let at6 = r.at(6.0, "npc");
    assert!((at6.speed - 10.0).abs() < S_TOL);
    assert!(
        (at6.x - (800.0 - ramp_lead(-2.5, 4.0))).abs() < S_TOL,
        "{at6:?}"
    );
    // truck: 30 m behind npc along their direction of travel, at npc's speed at every step
    // (speed(same_as: npc) at: all) as the engine reads it at the step's start (npc's of the
    // step before: truck moves first). Each moves a step at its step's end speed, so the sums
    // telescope: x_truck − x_npc = 30 − (20 − v_npc(t))·dt, 29.5 m at 6 s, x = 829.75 m.
    let truck = r.at(0.0, "truck");
    assert_eq!(truck.lane, 1);
    assert!(
        (truck.x - 930.0).abs() < S_TOL && (truck.speed - 20.0).abs() < S_TOL,
        "{truck:?}"
    );
    for k in 1..=120 {
        let t = k as f64 * DT;
        let (tr, n) = (r.at(t, "truck"), r.at(t, "npc"));
        let gap = 30.0 - (20.0 - n.speed) * DT;
        assert!(
            (tr.x - (n.x + gap)).abs() < S_TOL
                && (tr.speed - r.at(t - DT, "npc").speed).abs() < S_TOL,
            "at {t} s: {tr:?} {n:?}"
        );
    }
    assert!((r.at(6.0, "truck").x - 829.75).abs() < S_TOL);
    // distance(50m) at 10 m/s: 5 s.
    let (s, e) = r.phase("do.2.2");
    assert!(
        (s - 6.0).abs() < T_TOL && (e - 11.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let end = r.at(11.0, "npc");
    assert_eq!(end.lane, 1);
    assert!(
        (end.s - 750.25).abs() < S_TOL && (end.y - 1.75).abs() < S_TOL,
        "{end:?}"
    );
    assert!(wrap(end.h - PI).abs() < H_TOL, "{end:?}");
}

#[test]
fn a_gap_between_two_oncoming_actors_is_reached_along_their_direction_of_travel() {
    let r = run_on("opposite_gap", "straight");
    assert!((r.at(0.0, "npc").x - 900.0).abs() < S_TOL);
    let mid = r.at(5.0, "npc");
    assert!((mid.speed - 16.0).abs() < S_TOL, "{mid:?}");
    assert!(
        (mid.x - (810.0 - ramp_lead(-0.8, 5.0))).abs() < S_TOL,
        "{mid:?}"
    );
    let (npc, truck) = (r.at(10.0, "npc"), r.at(10.0, "truck"));
    assert!((truck.x - 700.0).abs() < S_TOL, "{truck:?}");
    assert!((npc.x - 720.0).abs() < S_TOL, "{npc:?}");
    assert!((npc.speed - 20.0).abs() < S_TOL, "{npc:?}");
}

#[test]
fn speed_actions_against_s_run_along_the_direction_of_travel() {
    let r = run_on("opposite_actions", "straight");
    assert!((r.at(0.0, "npc").x - 980.0).abs() < S_TOL);
    assert!((r.at(1.0, "npc").x - 970.0).abs() < S_TOL);
    let at3 = r.at(3.0, "npc");
    assert!((at3.speed - 20.0).abs() < S_TOL, "{at3:?}");
    assert!(
        (at3.x - (940.0 - ramp_lead(5.0, 2.0))).abs() < S_TOL,
        "{at3:?}"
    );
    assert_eq!(r.phase("do.1"), (1.0, 5.0));
    let at5 = r.at(5.0, "npc");
    assert!(
        (at5.x - (890.0 - ramp_lead(5.0, 4.0))).abs() < S_TOL,
        "{at5:?}"
    );
    let at6 = r.at(6.0, "npc");
    assert!((at6.speed - 30.0).abs() < S_TOL && at6.lane == 1, "{at6:?}");
    assert!(
        (at6.x - (860.0 - ramp_lead(5.0, 4.0))).abs() < S_TOL,
        "{at6:?}"
    );
}

#[test]
fn an_oncoming_actor_brakes_after_a_run_time_condition() {
    let r = run_on("opposite_until", "straight");
    let (_, e) = r.phase("do.1.0");
    assert!((e - 1.10).abs() < T_TOL, "until @quick ended at {e}");
    assert!((r.at(1.10, "npc").x - 878.0).abs() < S_TOL);
    let (s, e) = r.phase("do.1.1");
    assert!(
        (s - 1.10).abs() < T_TOL && (e - 5.10).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let mid = r.at(3.10, "npc");
    assert!((mid.speed - 10.0).abs() < S_TOL, "{mid:?}");
    assert!(
        (mid.x - (848.0 - ramp_lead(-5.0, 2.0))).abs() < S_TOL,
        "{mid:?}"
    );
    let end = r.at(5.10, "npc");
    assert!(end.speed.abs() < S_TOL && end.lane == 1, "{end:?}");
    assert!(
        (end.x - (838.0 - ramp_lead(-5.0, 4.0))).abs() < S_TOL,
        "{end:?}"
    );
    assert!(wrap(end.h - PI).abs() < H_TOL, "{end:?}");
    // distance(8m) over 2 s from standing: the engine's TravelAction along the lane.
    assert!((r.at(6.10, "npc").x - (838.5 - 4.0 - ramp_lead(8.0, 1.0))).abs() < S_TOL);
    let last = r.at(7.10, "npc");
    assert!(
        (last.x - 830.5).abs() < S_TOL && last.speed.abs() < S_TOL,
        "{last:?}"
    );
    // The engine's lane check at the run-time start passed: no error record, the run ends.
    ends_without_error("opposite_until", "straight");
}

#[test]
fn an_oncoming_actors_checks_after_a_run_time_start_measure_along_its_direction_of_travel() {
    let r = run_on("opposite_runtime_checks", "straight");
    let (_, e) = r.phase("do.2.0");
    assert!((e - 1.10).abs() < T_TOL, "until @quick ended at {e}");
    phases_are(
        &r,
        &[
            ("do.2.1", 1.10, 2.10),
            ("do.2.2", 2.10, 3.10),
            ("do.2.3", 3.10, 4.10),
        ],
    );
    let npc = r.at(0.0, "npc");
    assert!(
        (npc.x - 900.0).abs() < S_TOL && (npc.y - 2.25).abs() < S_TOL,
        "{npc:?}"
    );
    assert!(wrap(npc.h - PI).abs() < H_TOL, "{npc:?}");
    let at1 = r.at(1.10, "npc");
    assert!(
        (at1.x - 878.0).abs() < S_TOL && (at1.y - 2.25).abs() < S_TOL,
        "{at1:?}"
    );
    let (npc2, truck2) = (r.at(2.10, "npc"), r.at(2.10, "truck"));
    assert!(
        (npc2.s - 858.0).abs() < S_TOL && (truck2.s - 828.0).abs() < S_TOL,
        "{npc2:?} {truck2:?}"
    );
    assert_eq!((npc2.lane, truck2.lane), (1, 1));
    assert!((r.at(3.10, "npc").s - 838.0).abs() < S_TOL);
    let end = r.at(5.0, "npc");
    assert!(
        (end.x - 800.0).abs() < S_TOL && (end.y - 2.25).abs() < S_TOL,
        "{end:?}"
    );
    // Every check passed: no error record, the run ends.
    ends_without_error("opposite_runtime_checks", "straight");
}

#[test]
fn an_oncoming_actors_checks_after_a_run_time_start_fail_where_it_is_not() {
    const U: &str = "along the direction of travel (against s)";
    for (name, want, place, found) in [
        (
            "opposite_check_position_fails",
            format!("expected 'npc' at u = 140.000 m {U} (within 0.5 m) (position(…) at "),
            "39:17",
            format!("found it at u = 122.000 m {U} at t = 1.100 s"),
        ),
        (
            "opposite_check_behind_fails",
            format!("expected 'truck' 20.000 m from 'npc' {U} (within 0.5 m) (position(…) at "),
            "40:17",
            "found 30.000 m at t = 1.100 s".to_string(),
        ),
        (
            "opposite_check_lateral_fails",
            "expected 'npc' 0.500 m from the centre of its lane 3.500 m wide (within 0.01 m) (lateral(…) at ".to_string(),
            "40:17",
            "found it -0.500 m from it at t = 1.100 s".to_string(),
        ),
        (
            "opposite_check_beside_fails",
            "expected 'npc' 1.000 m to the left of 'truck' across the road (within 0.01 m) (lateral(…) at ".to_string(),
            "41:17",
            "found -0.500 m at t = 1.100 s".to_string(),
        ),
        (
            "opposite_check_lane_fails",
            "expected 'npc' in lane 2 of road 1, 1 lane to the right of 'truck''s lane 1 (lane(…) at ".to_string(),
            "40:17",
            "found it in lane 1 of road 1 at t = 1.100 s".to_string(),
        ),
        (
            "opposite_check_route_fails",
            format!("expected 'npc' at u = 600.000 m {U} (within 400.5 m) (along(…) at "),
            "40:17",
            format!("found it at u = 122.000 m {U} at t = 1.100 s"),
        ),
    ] {
        let (error, records) = run_to_error_on(name, "straight");
        let error = error.unwrap_or_else(|| panic!("{name}: the run ends"));
        assert!(
            error.starts_with(&want)
                && error.contains(&format!("{name}.osc:{place}), "))
                && error.ends_with(&found),
            "{name}: {error}"
        );
        assert_eq!(records.len(), 1, "{name}: {records:?}");
        assert!((records[0].0 - 1.10).abs() < T_TOL, "{name}: {records:?}");
        assert_eq!(records[0].2, error, "{name}");
    }
}

#[test]
fn an_oncoming_actors_gaps_and_travels_are_measured_along_its_direction_of_travel() {
    let r = run_on("opposite_runtime_gaps", "straight");
    phases_are(
        &r,
        &[
            ("do.1.0", 0.0, 9.90),
            ("do.1.1", 9.90, 12.90),
            ("do.1.2", 12.90, 16.90),
            ("do.1.3", 16.90, 17.20),
            ("do.1.4", 17.20, 21.20),
        ],
    );
    let x = |t: f64| r.at(t, "npc").x;
    let v = |t: f64| r.at(t, "npc").speed;
    // The gap reached from behind at 9.90 s, 20.8 m.
    assert!((x(9.90) - 702.0).abs() < S_TOL, "{}", x(9.90));
    assert!((r.at(9.90, "truck").x - 681.2).abs() < S_TOL);
    // distance(30m) at 10 m/s.
    assert!((x(11.40) - 687.0).abs() < S_TOL && (v(11.40) - 10.0).abs() < S_TOL);
    assert!((x(12.90) - 672.0).abs() < S_TOL, "{}", x(12.90));
    // The TravelAction 10 m behind truck: 10 -> 22.4 -> 10 m/s.
    assert!((v(14.90) - 22.4).abs() < S_TOL, "{}", v(14.90));
    assert!((x(14.90) - 639.29).abs() < S_TOL, "{}", x(14.90));
    assert!((x(16.90) - 607.2).abs() < S_TOL && (v(16.90) - 10.0).abs() < S_TOL);
    assert!((r.at(16.90, "truck").x - 597.2).abs() < S_TOL);
    // The time gap reached falling back, at 17.20 s.
    assert!((x(17.20) - 605.7).abs() < S_TOL, "{}", x(17.20));
    // The TravelAction to u = 450 m: 5 -> 22.85 -> 5 m/s.
    assert!((v(19.20) - 22.85).abs() < S_TOL, "{}", v(19.20));
    assert!((x(19.20) - 577.40375).abs() < S_TOL, "{}", x(19.20));
    let end = r.at(21.20, "npc");
    assert!(
        (end.x - 550.0).abs() < S_TOL && (end.speed - 5.0).abs() < S_TOL && end.lane == 1,
        "{end:?}"
    );
    assert!(wrap(end.h - PI).abs() < H_TOL, "{end:?}");
}

#[test]
fn a_projected_gap_between_oncoming_actors_is_measured_along_their_direction_of_travel() {
    let r = run_on("opposite_runtime_projected", "straight");
    phases_are(&r, &[("do.1.0", 0.0, 1.10), ("do.1.1", 1.10, 6.00)]);
    assert!((r.at(1.10, "truck").x - 789.0).abs() < S_TOL);
    let (npc, truck) = (r.at(6.00, "npc"), r.at(6.00, "truck"));
    assert!((npc.x - 780.0).abs() < S_TOL, "{npc:?}");
    assert!(
        (truck.x - (749.0 + ramp_lead(2.0, 3.0))).abs() < S_TOL,
        "{truck:?}"
    );
    ends_without_error("opposite_runtime_projected", "straight");
}

#[test]
fn a_lateral_position_beside_an_oncoming_actor_on_another_road_is_checked_to_the_drivers_left() {
    let road = "junction_trippel_twoway0";
    let r = run_on("opposite_runtime_beside_roads", road);
    phases_are(&r, &[("do.2.0", 0.0, 1.10), ("do.2.1", 1.10, 2.10)]);
    let (npc, truck) = (r.at(1.10, "npc"), r.at(1.10, "truck"));
    assert!(npc.road == "2" && (npc.s - 79.0).abs() < S_TOL, "{npc:?}");
    assert!(
        truck.road == "0" && (truck.s - 39.0).abs() < S_TOL && (truck.y - 1.75).abs() < S_TOL,
        "{truck:?}"
    );
    ends_without_error("opposite_runtime_beside_roads", road);
}

#[test]
fn an_oncoming_actors_checks_travels_and_gaps_on_several_roads_measure_along_the_reversed_chain() {
    let road = "junction_trippel_twoway0";
    let r = run_on("opposite_runtime_roads", road);
    phases_are(
        &r,
        &[
            ("do.2.0", 0.0, 1.10),
            ("do.2.1", 1.10, 2.10),
            ("do.2.2", 2.10, 10.10),
            ("do.2.3", 10.10, 12.40),
            ("do.2.4", 12.40, 13.40),
        ],
    );
    let on = |t: f64, who: &str, road: &str, s: f64, tol: f64| {
        let o = r.at(t, who);
        assert!(
            o.road == road && o.lane == 1 && (o.s - s).abs() < tol,
            "{who} at {t}: {o:?}, want road {road} s {s}"
        );
        o
    };
    on(1.10, "npc", "2", 79.0, S_TOL);
    on(1.10, "truck", "2", 49.0, S_TOL);
    // Half way through the TravelAction, still on road 2 (straight, heading 0.3 + pi).
    let mid = on(6.10, "npc", "2", 18.875, S_TOL);
    assert!((mid.speed - 15.0).abs() < S_TOL, "{mid:?}");
    let (x, y) = (
        129.71723128680293 + 18.875 * 0.3f64.cos() - 1.5 * 0.3f64.sin(),
        3.1297684891414503 + 18.875 * 0.3f64.sin() + 1.5 * 0.3f64.cos(),
    );
    assert!(
        (mid.x - x).abs() < S_TOL && (mid.y - y).abs() < S_TOL,
        "{mid:?} want ({x}, {y})"
    );
    assert!(wrap(mid.h - (0.3 + PI)).abs() < H_TOL, "{mid:?}");
    // The end: road 0, 10 m behind truck along their direction of travel.
    let end = on(10.10, "npc", "0", 98.55, SPIRAL_TOL);
    assert!((end.speed - 10.0).abs() < S_TOL, "{end:?}");
    on(10.10, "truck", "0", 88.55, SPIRAL_TOL);
    // The gap without a duration, reached falling back at 12.40 s.
    on(12.40, "npc", "0", 87.05, SPIRAL_TOL);
    on(12.40, "truck", "0", 65.55, SPIRAL_TOL);
    ends_without_error("opposite_runtime_roads", road);
    // Not where the check asks: the error record names the modifier and the measured u.
    let (error, records) = run_to_error_on("opposite_check_roads_fails", road);
    let error = error.expect("the run fails");
    let u = "along the direction of travel (against s)";
    assert!(
        error.starts_with(&format!(
            "expected 'npc' at u = 25.000 m {u} (within 0.5 m) (position(…) at "
        )) && error.contains("opposite_check_roads_fails.osc:25:17), ")
            && error.ends_with(&format!("found it at u = 21.000 m {u} at t = 1.100 s")),
        "{error}"
    );
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 1.10).abs() < T_TOL && records[0].2 == error);
}

#[test]
fn offsets_in_the_lane_against_s_are_to_the_left_of_the_direction_of_travel() {
    let r = run_on("opposite_lateral", "straight");
    let start = r.at(0.0, "npc");
    assert_eq!(start.lane, 1);
    assert!(
        (start.x - 900.0).abs() < S_TOL && (start.y - 2.25).abs() < S_TOL,
        "{start:?}"
    );
    assert!(
        (r.at(4.0, "npc").y - 2.25).abs() < S_TOL,
        "{:?}",
        r.at(4.0, "npc")
    );
    let mid = r.at(6.0, "npc");
    assert!((mid.y - 1.75).abs() < 1e-6, "{mid:?}");
    let end = r.at(8.0, "npc");
    assert!((end.y - 1.25).abs() < 1e-6 && end.lane == 1, "{end:?}");
    let cost = PI * PI / (16.0 * 4.0 * 10.0);
    assert!((end.x - (820.0 + cost)).abs() < COST_TOL, "{end:?}");
    // change_lane(…, side: right, offset: 0.5m): lane 2, 0.5 m left of its centre for npc.
    assert!(
        (r.at(10.0, "npc").y - 3.0).abs() < 1e-6,
        "{:?}",
        r.at(10.0, "npc")
    );
    let last = r.at(12.0, "npc");
    assert!((last.y - 4.75).abs() < 1e-6 && last.lane == 2, "{last:?}");
    let cost2 = 3.5f64.powi(2) * PI * PI / (16.0 * 4.0 * 10.0);
    assert!(
        (last.x - (780.0 + cost + cost2)).abs() < COST_TOL,
        "{last:?}"
    );
}

#[test]
fn an_oncoming_car_stops_behind_a_stationary_object_it_measures() {
    let r = run_on("opposite_stop_behind_object", "straight");
    let (s, e) = r.phase("do.approach");
    assert!(
        s.abs() < T_TOL && (e - 3.85).abs() < T_TOL,
        "approach [{s}, {e}]"
    );
    assert!((r.at(3.85, "car").x - 903.0).abs() < S_TOL);
    let (s, e) = r.phase("do.brake");
    assert!(
        (s - 3.85).abs() < T_TOL && (e - 7.85).abs() < T_TOL,
        "brake [{s}, {e}]"
    );
    assert!((r.at(5.85, "car").speed - 10.0).abs() < S_TOL);
    for t in [7.85, 9.85] {
        let c = r.at(t, "car");
        assert!(
            (c.x - 863.5).abs() < S_TOL && c.speed.abs() < S_TOL && c.lane == 1,
            "car at {t}: {c:?}"
        );
    }
    assert!((r.last_time() - 9.85).abs() < T_TOL);
}

#[test]
fn lanes_against_s_are_counted_in_the_direction_of_travel() {
    let r = run_on("opposite_lanes", "straight");
    let y1 = |tau: f64| 1.75 + 3.5 * (1.0 - (PI * tau / 4.0).cos()) / 2.0;
    let start = r.at(0.0, "npc");
    assert_eq!(start.lane, 1);
    assert!(
        (start.x - 950.0).abs() < S_TOL && (start.y - 1.75).abs() < S_TOL,
        "{start:?}"
    );
    // lane(1, at: end): the rightmost lane in npc's direction, lane 2 (the outer one).
    assert!(
        (r.at(2.0, "npc").y - y1(2.0)).abs() < S_TOL,
        "{:?}",
        r.at(2.0, "npc")
    );
    let at4 = r.at(4.0, "npc");
    assert_eq!(at4.lane, 2, "{at4:?}");
    assert!((at4.y - 5.25).abs() < S_TOL, "{at4:?}");
    let cost = 3.5f64.powi(2) * PI * PI / (16.0 * 4.0 * 10.0);
    assert!((at4.x - (910.0 + cost)).abs() < COST_TOL, "{at4:?}");
    // change_lane(side: left): towards the centre line, back into lane 1.
    assert!(
        (r.at(6.0, "npc").y - 3.5).abs() < S_TOL,
        "{:?}",
        r.at(6.0, "npc")
    );
    let at8 = r.at(8.0, "npc");
    assert_eq!(at8.lane, 1, "{at8:?}");
    assert!((at8.y - 1.75).abs() < S_TOL, "{at8:?}");
    assert!(
        (at8.x - (870.0 + 2.0 * cost)).abs() < 2.0 * COST_TOL,
        "{at8:?}"
    );
    assert!(wrap(at8.h - PI).abs() < H_TOL, "{at8:?}");
    assert!((r.phase("do").1 - 8.0).abs() < T_TOL);
}

#[test]
fn an_oncoming_actor_drives_the_plans_roads_backwards_through_a_junction() {
    let r = run_on("opposite_roads", "junction_trippel_twoway0");
    let npc = r.at(0.0, "npc");
    assert_eq!((npc.road.as_str(), npc.lane), ("2", 1), "{npc:?}");
    assert!((npc.s - 50.0).abs() < S_TOL, "{npc:?}");
    assert!(
        (npc.x - 177.0408).abs() < 1e-4 && (npc.y - 19.3388).abs() < 1e-4,
        "{npc:?}"
    );
    assert!(wrap(npc.h - (0.3 + PI)).abs() < H_TOL, "{npc:?}");
    let at3 = r.at(3.0, "npc");
    assert!(
        (at3.x - 148.3807).abs() < 1e-4 && (at3.y - 10.4732).abs() < 1e-4,
        "{at3:?}"
    );
    let (_, end) = r.phase("do.1");
    assert!(
        (end - 10.0).abs() < T_TOL,
        "distance(100m) at 10 m/s: {end}"
    );
    let at10 = r.at(10.0, "npc");
    assert_eq!((at10.road.as_str(), at10.lane), ("0", 1), "{at10:?}");
    assert!((at10.s - 79.55).abs() < SPIRAL_TOL, "{at10:?}");
    assert!((at10.y - 1.5).abs() < SPIRAL_TOL, "{at10:?}");
    assert!(wrap(at10.h - PI).abs() < SPIRAL_TOL, "{at10:?}");
    let ego = r.at(10.0, "ego");
    assert!(
        (ego.x - 60.0).abs() < S_TOL && (ego.y + 1.5).abs() < S_TOL,
        "{ego:?}"
    );
}

#[test]
fn routes_are_opposite_on_route_fields_binds_the_second_to_the_roads_against_s() {
    let r = run_on("opposite_routes", "straight");
    let ego = r.at(4.0, "ego");
    assert_eq!(ego.lane, -3);
    assert!(
        (ego.x - 90.0).abs() < S_TOL && (ego.y + 8.75).abs() < S_TOL,
        "{ego:?}"
    );
    let npc0 = r.at(0.0, "npc");
    assert_eq!(npc0.lane, 1, "{npc0:?}");
    assert!(
        (npc0.s - 800.0).abs() < S_TOL && (npc0.y - 1.75).abs() < S_TOL,
        "{npc0:?}"
    );
    let npc = r.at(4.0, "npc");
    assert!(
        (npc.x - 740.0).abs() < S_TOL && (npc.y - 1.75).abs() < S_TOL,
        "{npc:?}"
    );
    assert!(wrap(npc.h - PI).abs() < H_TOL, "{npc:?}");
    let bus0 = r.at(0.0, "bus");
    assert_eq!(bus0.lane, 2, "{bus0:?}");
    assert!(
        (bus0.x - 900.0).abs() < S_TOL && (bus0.y - 5.25).abs() < S_TOL,
        "{bus0:?}"
    );
    assert!((r.at(4.0, "bus").x - 820.0).abs() < S_TOL);
    assert!((r.phase("do").1 - 4.0).abs() < T_TOL);
}

#[test]
fn what_does_not_run_against_s_is_an_error_at_its_place() {
    for (name, road, texts, place) in [
        (
            "err_opposite_ahead",
            "straight",
            &[
                "expected `ahead_of:` of position(…) to name an actor driving in the direction of `ego` (in +s), found `npc`, which drives against s",
                "two actors driving opposite ways share none",
            ][..],
            "18:37",
        ),
        (
            "err_opposite_lane",
            "straight",
            &["expected a driving lane numbered 3 from the right on road 1"][..],
            "13:13",
        ),
        (
            "err_opposite_point",
            "straight",
            &["expected a driving lane of road 1 (right-hand traffic: lanes [-3, -2, -1] driven in +s, [1, 2] in -s) at s = 50 m, found lane 3"][..],
            "7:13",
        ),
        (
            "err_opposite_route_dir",
            "straight",
            &["expected `ego`, which drives in +s, along a route in its direction, found `theirs` (the plan's roads against s, bound by map.routes_are_opposite(…) at "][..],
            "16:13",
        ),
        (
            "err_opposite_lateral_gap_place",
            "straight",
            &["expected a 0.5 m gap left of `lead` to leave `ego` in a driving lane, found it at t = 0.75 m across the road"][..],
            "26:13",
        ),
        (
            "err_opposite_obstacle",
            "straight",
            &["expected `same_as:` of lane(…) to name an object in a lane `npc` drives in its direction (against s, a lane of the left side), found `barrier` in lane -1, driven in +s"][..],
            "19:27",
        ),
        (
            "err_opposite_route_self",
            "straight",
            &["expected two routes in opposite directions, found `r` twice"][..],
            "6:5",
        ),
    ] {
        let e = error_on(name, road);
        assert!(
            texts.iter().all(|t| e.contains(t)) && e.ends_with(&format!("{name}.osc:{place}")),
            "{name}: {e}"
        );
    }
}
