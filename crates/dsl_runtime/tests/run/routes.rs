//! Routes through points in other lanes and at other offsets from their lanes' centres
//! (issue 27; ASAM OpenSCENARIO DSL 2.1 §8.12.2.1 `create_route`, `create_odr_point`): the
//! actor changes lanes (its offset) over the stretch between two points, so it passes each
//! point where it is. Motions worked by hand in the scenario files' comments.

use std::f64::consts::PI;

use crate::support::{error_on, lower_at, run, run_on};

/// Positions on the straight road away from a change: float round-off only.
const S_TOL: f64 = 1e-6;
/// y against the closed form of the change at the x the engine reports: the engine's step
/// foresees the sideways share of a step at its start and end (lane_change's `Foreseen`), so
/// y and x agree to the step's second order.
const CHANGE_TOL: f64 = 2e-3;
/// A walk along a crossing's line: the engine's trajectory following (mode `position`) is
/// exact at the step's times but for float round-off.
const WALK_TOL: f64 = 1e-6;
/// x where a change's longer path leaves the actor short of the plan's s (m): the closed form
/// A²π²/(16L) of the extra length, summed over the changes.
const PATH_TOL: f64 = 5e-3;

#[test]
fn a_route_through_points_in_other_lanes_changes_lanes_between_them() {
    let r = run("route_lanes", 0, None);
    // Start: lane -1, x 20.
    let p = r.at(0.0, "ego");
    assert!(
        (p.x - 20.0).abs() < S_TOL && (p.y + 1.75).abs() < S_TOL && p.lane == -1,
        "{p:?}"
    );
    // Before the first change (50 m at 3 s) it keeps lane -1's centre.
    let p = r.at(2.9, "ego");
    assert!((p.y + 1.75).abs() < S_TOL && p.lane == -1, "{p:?}");
    // The offset change after the lane change starts when the engine's triggers see the
    // lane change's end (a step after the step it ends in): x0 the last x at lane -2's
    // centre, at most two steps' travel (2 * 10 m/s * 0.05 s) past the point at 90 m.
    let x0 = r
        .frames
        .iter()
        .filter_map(|(_, objs)| objs.iter().find(|o| o.name == "ego"))
        .filter(|p| p.x >= 90.0 && (p.y + 5.25).abs() < S_TOL)
        .map(|p| p.x)
        .fold(f64::NAN, f64::max);
    assert!((90.0..=91.0).contains(&x0), "x0 {x0}");
    // Every step: y the closed form of the stretch the engine's x is on.
    let mut seen_mid = false;
    for (t, objs) in &r.frames {
        let Some(p) = objs.iter().find(|o| o.name == "ego") else {
            continue;
        };
        let want = if p.x <= 50.0 {
            -1.75
        } else if p.x <= 90.0 {
            -1.75 - 3.5 * (1.0 - (PI * (p.x - 50.0) / 40.0).cos()) / 2.0
        } else if p.x <= x0 {
            -5.25
        } else {
            -5.25 + 0.5 * (1.0 - (PI * (p.x - x0) / (120.0 - x0)).cos()) / 2.0
        };
        assert!(
            (p.y - want).abs() < CHANGE_TOL,
            "at {t} s: {p:?}, want y {want}"
        );
        // Mid-point of the lane change: y = -3.5 m at x = 70 m.
        if (p.x - 70.0).abs() < 0.25 {
            assert!(
                (p.y + 3.5).abs() < 0.25 * 3.5 * PI / 80.0 + CHANGE_TOL,
                "{p:?}"
            );
            seen_mid = true;
        }
    }
    assert!(seen_mid);
    // End of the lane change: lane -2 by 7 s and x = 90 less its longer path.
    let extra = 3.5f64.powi(2) * PI * PI / (16.0 * 40.0);
    let p = r.at(7.05, "ego");
    assert_eq!(p.lane, -2, "{p:?}");
    // End: 0.5 m left of lane -2's centre, x = 120 less both changes' extra path.
    let extra2 = extra + 0.5f64.powi(2) * PI * PI / (16.0 * (120.0 - x0));
    let p = r.at(10.0, "ego");
    assert!((p.y + 4.75).abs() < CHANGE_TOL && p.lane == -2, "{p:?}");
    assert!(
        (p.x - (120.0 - extra2)).abs() < PATH_TOL,
        "{p:?} (extra {extra2})"
    );
    // npc: one point at t = -0.5 m, kept.
    for (t, x) in [(0.0, 10.0), (5.0, 35.0), (10.0, 60.0)] {
        let p = r.at(t, "npc");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 9.25).abs() < S_TOL && p.lane == -3,
            "npc at {t} s: {p:?}"
        );
    }
}

/// Asserts that ego starts at (`x0`, `y0`) in `lane` and that at every step its y is `want`
/// of its x (CHANGE_TOL): the closed form of the stretch its x is on.
fn ego_follows(
    r: &crate::support::Run,
    (x0, y0, lane): (f64, f64, i32),
    want: impl Fn(f64) -> f64,
) {
    let p = r.at(0.0, "ego");
    assert!(
        (p.x - x0).abs() < S_TOL && (p.y - y0).abs() < S_TOL && p.lane == lane,
        "{p:?}"
    );
    ego_y_follows(r, want);
}

/// Asserts that at every step ego's y is `want` of its x (CHANGE_TOL).
fn ego_y_follows(r: &crate::support::Run, want: impl Fn(f64) -> f64) {
    for (t, objs) in &r.frames {
        let Some(p) = objs.iter().find(|o| o.name == "ego") else {
            continue;
        };
        let want = want(p.x);
        assert!(
            (p.y - want).abs() < CHANGE_TOL,
            "at {t} s: {p:?}, want y {want}"
        );
    }
}

/// The x at which ego leaves the flat y `y` going past `from` m: the last x at y (S_TOL) at or
/// after `from` in `r`'s frames (the start of a change the engine triggered there).
fn last_x_at(r: &crate::support::Run, y: f64, from: f64) -> f64 {
    r.frames
        .iter()
        .filter_map(|(_, objs)| objs.iter().find(|o| o.name == "ego"))
        .filter(|p| p.x >= from && (p.y - y).abs() < S_TOL)
        .map(|p| p.x)
        .fold(f64::NAN, f64::max)
}

/// route_lanes_runtime.osc, by hand: the route's changes after a run-time start (ego at
/// x = 40.5 m at 2.05 s) start where the engine has ego at each point: lane -1 -> -2 from x1
/// (50 <= x1 <= 51) to 90 m, then the offset from x0 (90 <= x0 <= 91) to 120 m; y the
/// closed form of the stretch the engine's x is on at every step; the end y = -4.75 m.
#[test]
fn a_route_through_lanes_after_a_run_time_start_changes_lanes_where_the_engine_reaches_its_points()
{
    let r = run("route_lanes_runtime", 0, None);
    let (s, e) = r.phase("do.0.0");
    assert!(
        (s - 0.0).abs() < S_TOL && (e - 2.05).abs() < S_TOL,
        "[{s}, {e}]"
    );
    let p = r.at(2.05, "ego");
    assert!((p.x - 40.5).abs() < S_TOL && p.lane == -1, "{p:?}");
    let x1 = last_x_at(&r, -1.75, 40.0);
    assert!((50.0..=51.0).contains(&x1), "x1 {x1}");
    let x0 = last_x_at(&r, -5.25, 90.0);
    assert!((90.0..=91.0).contains(&x0), "x0 {x0}");
    ego_follows(&r, (20.0, -1.75, -1), |x| {
        if x <= x1 {
            -1.75
        } else if x <= 90.0 {
            -1.75 - 3.5 * (1.0 - (PI * (x - x1) / (90.0 - x1)).cos()) / 2.0
        } else if x <= x0 {
            -5.25
        } else {
            -5.25 + 0.5 * (1.0 - (PI * (x - x0) / (120.0 - x0)).cos()) / 2.0
        }
    });
    let extra = 3.5f64.powi(2) * PI * PI / (16.0 * (90.0 - x1))
        + 0.5f64.powi(2) * PI * PI / (16.0 * (120.0 - x0));
    let p = r.at(10.0, "ego");
    assert!(
        p.lane == -2 && (p.y + 4.75).abs() < CHANGE_TOL && (p.x - (120.0 - extra)).abs() < PATH_TOL,
        "{p:?}, want x {}",
        120.0 - extra
    );
}

/// route_lanes_runtime_past.osc, by hand: the run-time phase starts at 8.05 s with ego at
/// x = 100.5 m in lane -1, past the route's point in lane -2 at 90 m: the change there fails
/// (an error record at 8.05 s naming the along at 21:17, and a failed run).
#[test]
fn a_route_through_lanes_after_a_run_time_start_past_a_point_fails_the_run() {
    let (error, records) = crate::support::run_to_error_on("route_lanes_runtime_past", "straight");
    let error = error.expect("the run fails");
    let (t, _, message) = records.first().expect("an error record");
    assert!((t - 8.05).abs() < 1e-9, "{t} {message}");
    assert!(
        message.contains("21:17")
            && message.contains("s = 90.000 m of road 1 ahead of 'ego'")
            && message.contains("100.5"),
        "{message} / {error}"
    );
}

/// route_point_along.osc, by hand: a route point 40 m along a route through points is the
/// route from s = 60 m on, in lane -1 (its last point's before it): ego placed at (60, -1.75),
/// y = -1.75 - 3.5 (1 - cos(pi (x - 60) / 30)) / 2 at every step to 90 m, then lane -2; x =
/// 100 m less the change's longer path at 4 s. npc 15 m along a route from one point, 0.5 m
/// from its line: (25, -8.25) at 0 s, (45, -8.25) at 4 s.
#[test]
fn a_route_point_as_the_route_is_the_route_from_that_point_on() {
    let r = run("route_point_along", 0, None);
    ego_follows(&r, (60.0, -1.75, -1), |x| {
        if x <= 90.0 {
            -1.75 - 3.5 * (1.0 - (PI * (x - 60.0) / 30.0).cos()) / 2.0
        } else {
            -5.25
        }
    });
    let extra = 3.5f64.powi(2) * PI * PI / (16.0 * 30.0);
    let p = r.at(4.0, "ego");
    assert!(
        p.lane == -2 && (p.x - (100.0 - extra)).abs() < PATH_TOL,
        "{p:?}, want x {}",
        100.0 - extra
    );
    for (t, x) in [(0.0, 25.0), (4.0, 45.0)] {
        let p = r.at(t, "npc");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 8.25).abs() < S_TOL && p.lane == -3,
            "at {t} s: {p:?}"
        );
    }
}

/// route_ends.osc, by hand: r.end_point() is the route from r's last point (90, -5.25): ego
/// from there to x = 115 m at 2.5 s; r.start_point() is r: npc (20, -1.75) -> (45, -1.75);
/// route_point_to_xyz(p) is p's place: bus (30, -8.75) -> (42.5, -8.75); a route field among
/// create_route's points gives its points: truck (100, -8.75) -> (125, -8.75).
#[test]
fn a_routes_start_and_end_points_and_a_points_world_position_are_routes_from_them() {
    let r = run("route_ends", 0, None);
    for (name, lane, y, x0, x3) in [
        ("ego", -2, -5.25, 90.0, 115.0),
        ("npc", -1, -1.75, 20.0, 45.0),
        ("bus", -3, -8.75, 30.0, 42.5),
        ("truck", -3, -8.75, 100.0, 125.0),
    ] {
        for (t, x) in [(0.0, x0), (2.5, x3)] {
            let p = r.at(t, name);
            assert!(
                (p.x - x).abs() < S_TOL && (p.y - y).abs() < S_TOL && p.lane == lane,
                "{name} at {t} s: {p:?}"
            );
        }
    }
}

/// route_lanes_runtime_against.osc, by hand: driving against s after a run-time start (ego at
/// x = 894.5 m at 1.55 s), the change into lane 2 starts where the engine has ego at the point
/// 880 m (x1 within a step's travel past it) and follows y = 1.75 + 3.5 (1 - cos(pi (x1 - x) /
/// (x1 - 840))) / 2 at every step to 840 m.
#[test]
fn a_route_through_lanes_against_s_after_a_run_time_start_changes_where_the_engine_reaches_its_points(
) {
    let r = run("route_lanes_runtime_against", 0, None);
    let p = r.at(1.55, "ego");
    assert!((p.x - 894.5).abs() < S_TOL && p.lane == 1, "{p:?}");
    // The last x at lane 1's centre before 880 m is passed (x falls along the run).
    let x1 = r
        .frames
        .iter()
        .filter_map(|(_, objs)| objs.iter().find(|o| o.name == "ego"))
        .filter(|p| p.x <= 880.0 && (p.y - 1.75).abs() < S_TOL)
        .map(|p| p.x)
        .fold(f64::NAN, f64::min);
    assert!((879.0..=880.0).contains(&x1), "x1 {x1}");
    ego_y_follows(&r, |x| {
        if x >= x1 {
            1.75
        } else if x >= 840.0 {
            1.75 + 3.5 * (1.0 - (PI * (x1 - x) / (x1 - 840.0)).cos()) / 2.0
        } else {
            5.25
        }
    });
    // Past 840 m (about 7.0 s) in lane 2 at its centre: the phase's end, 7.55 s.
    let p = r.at(7.55, "ego");
    assert!(p.lane == 2 && (p.y - 5.25).abs() < CHANGE_TOL, "{p:?}");
}

/// route_lanes_against.osc, by hand: the change into lane 2 over x 880 -> 840 m driving
/// against s, y = 1.75 + 3.5 (1 - cos(pi (880 - x) / 40)) / 2 at every step.
#[test]
fn a_route_through_lanes_driven_against_s_changes_lanes_between_its_points() {
    let r = run("route_lanes_against", 0, None);
    let p = r.at(0.0, "ego");
    assert!(
        (p.x - 900.0).abs() < S_TOL && (p.y - 1.75).abs() < S_TOL && p.lane == 1,
        "{p:?}"
    );
    for (t, objs) in &r.frames {
        let Some(p) = objs.iter().find(|o| o.name == "ego") else {
            continue;
        };
        let want = if p.x >= 880.0 {
            1.75
        } else if p.x >= 840.0 {
            1.75 + 3.5 * (1.0 - (PI * (880.0 - p.x) / 40.0).cos()) / 2.0
        } else {
            5.25
        };
        assert!(
            (p.y - want).abs() < CHANGE_TOL,
            "at {t} s: {p:?}, want y {want}"
        );
    }
    let extra = 3.5f64.powi(2) * PI * PI / (16.0 * 40.0);
    let p = r.at(6.0, "ego");
    assert!(
        p.lane == 2 && (p.x - (840.0 + extra)).abs() < PATH_TOL,
        "{p:?}"
    );
}

/// route_xyz.osc, by hand: points in world coordinates placed on the road; ego changes over
/// x 20 -> 60 m into lane -2 0.25 m left of its centre, npc keeps its point's offset.
#[test]
fn route_points_in_world_coordinates_are_the_road_points_there() {
    let r = run("route_xyz", 0, None);
    let p = r.at(0.0, "ego");
    assert!(
        (p.x - 20.0).abs() < S_TOL && (p.y + 1.75).abs() < S_TOL && p.lane == -1,
        "{p:?}"
    );
    for (t, objs) in &r.frames {
        let Some(p) = objs.iter().find(|o| o.name == "ego") else {
            continue;
        };
        let want = -1.75 - 3.25 * (1.0 - (PI * (p.x - 20.0) / 40.0).cos()) / 2.0;
        assert!(
            (p.y - want).abs() < CHANGE_TOL,
            "at {t} s: {p:?}, want y {want}"
        );
    }
    let extra = 3.25f64.powi(2) * PI * PI / (16.0 * 40.0);
    let p = r.at(4.0, "ego");
    assert!(
        p.lane == -2 && (p.x - (60.0 - extra)).abs() < PATH_TOL && (p.y + 5.0).abs() < CHANGE_TOL,
        "{p:?}"
    );
    for (t, x) in [(0.0, 10.0), (4.0, 30.0)] {
        let p = r.at(t, "npc");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 9.0).abs() < S_TOL && p.lane == -3,
            "npc at {t} s: {p:?}"
        );
    }
}

#[test]
fn what_a_route_through_lanes_cannot_do_is_an_error_at_its_place() {
    for (name, road, text, place) in [
        // No method of the map gives a lane: a lane field given an odr point is the
        // checker's error at the value (the runtime never sees it as a `target:`).
        (
            "err_lane_field_route",
            "straight",
            "expected lane for field `l`, found odr_point",
            "err_lane_field_route.osc:5:15",
        ),
        (
            "err_route_point_free",
            "straight",
            "found `r`, a route the runtime chooses (its start, which s is measured from, is where the actors drive",
            "err_route_point_free.osc:9:36",
        ),
        (
            "err_route_point_beyond",
            "straight",
            "expected the route point 100 m along the route before its last point (road 1, s = 90 m), found s = 120 m, past it",
            "err_route_point_beyond.osc:7:9",
        ),
        (
            "err_route_end_one_point",
            "straight",
            "before .end_point() in along(…), found a route from one point (it runs on over the roads the engine drives onto",
            "err_route_end_one_point.osc:8:15",
        ),
        (
            "err_route_self",
            "straight",
            "defined through itself",
            "err_route_self.osc:6:32",
        ),
        (
            "err_route_xyz",
            "straight",
            "expected a point on a road of the network for the route's point at x = 50 m, y = 30 m",
            "err_route_xyz.osc:7:9",
        ),
        (
            "err_route_crossing",
            "crosswalk",
            "expected a crosswalk of the map holding the straight line from lane -1 at s = 50 m to lane 1 at s = 50 m of road 1 in one lane section (connect_points_by: crossing), found none",
            "err_route_crossing.osc:8:9",
        ),
        (
            "err_route_lanes_short",
            "straight",
            "expected `ego` to reach the route's point in lane -2 (road 1 at s = 90.00 m) within the phase, to end the change it begins at s = 50.00 m, found it at s = 80.00 m when the phase ends (the plan's s)",
            "err_route_lanes_short.osc:8:9",
        ),
        (
            "err_route_lanes_lateral",
            "straight",
            "err_route_lanes_lateral.osc:7:9 (a route through points in other lanes or at other offsets moves the actor across between them), found one",
            "err_route_lanes_lateral.osc:8:9",
        ),
    ] {
        let e = error_on(name, road);
        assert!(e.contains(text) && e.ends_with(place), "{name}: {e}");
    }
}
/// route_point.osc, by hand: along(m.odr_to_route_point("1", "-2", 50m, 0m)), the route from
/// that point: ego placed at (50, -5.25) in lane -2, at 10 m/s (70, -5.25) at 2 s and (90,
/// -5.25) at 4 s; npc's point without lane_id, t -9.0 m from the reference line: lane -3,
/// (30, -9.0) to (70, -9.0).
#[test]
fn a_route_from_a_route_point_of_an_odr_point_is_driven_from_it() {
    let r = run("route_point", 0, None);
    for (who, lane, y, x0) in [("ego", -2, -5.25, 50.0), ("npc", -3, -9.0, 30.0)] {
        for t in [0.0, 2.0, 4.0] {
            let p = r.at(t, who);
            assert!(
                (p.x - (x0 + 10.0 * t)).abs() < S_TOL && (p.y - y).abs() < S_TOL && p.lane == lane,
                "{who} at {t} s: {p:?}"
            );
        }
    }
}

/// opposite_road_sequence.osc, by hand: back = road 2 driven against s, npc from its start
/// (road 2's end, rear bumper there) in lane 2 at 10 m/s, 50 m on at 5 s; ego along b = road 2
/// in +s from x 100 to 150 m.
#[test]
fn a_road_the_map_binds_driven_the_other_way_is_that_road_against_s() {
    let r = run_on(
        "opposite_road_sequence",
        "road_link_unequal_number_of_lanes0",
    );
    let npc0 = r.at(0.0, "npc");
    // Its rear overhang: the reference point's distance from the rear bumper.
    let rear = 100.0 - npc0.s;
    assert!((0.0..2.5).contains(&rear), "{npc0:?}");
    assert!(
        npc0.road == "2" && npc0.lane == 2 && (npc0.y - 4.5).abs() < S_TOL,
        "{npc0:?}"
    );
    assert!((npc0.h - PI).abs() < S_TOL, "{npc0:?}");
    let npc = r.at(5.0, "npc");
    assert!(
        npc.road == "2" && npc.lane == 2 && (npc.s - (50.0 - rear)).abs() < S_TOL,
        "{npc:?}"
    );
    assert!((npc.x - (150.0 - rear)).abs() < S_TOL, "{npc:?}");
    let ego = r.at(5.0, "ego");
    assert!(ego.road == "2" && (ego.x - 150.0).abs() < S_TOL, "{ego:?}");
}

#[test]
fn a_road_bound_in_plus_s_as_the_route_against_s_is_an_error_at_the_modifier() {
    let e = match lower_at(
        "tests/scenarios/err_opposite_road_sequence.osc",
        "tests/roads/road_link_unequal_number_of_lanes0.xodr",
        0,
        None,
    ) {
        Ok(_) => panic!("planned"),
        Err(e) => e.to_string(),
    };
    assert!(
        e.contains("expected route2 driven against s, opposite to route1, found `b`, one road driven in +s")
            && e.ends_with("err_opposite_road_sequence.osc:8:5"),
        "{e}"
    );
}

/// route_crossing.osc, by hand: the line (99, -1.75) -> (101, 1.75), 4.0311 m, walked at 0.5
/// m/s: placed at its start, (99.9923, -0.0135) at 4 s, at its end in lane 1 at 8.062 s.
#[test]
fn a_route_the_map_makes_across_a_crossing_is_walked_along_its_line() {
    let r = run_on("route_crossing", "crosswalk");
    let len = (2.0f64 * 2.0 + 3.5 * 3.5).sqrt();
    // The walk, and with it the scenario, ends with the step that reaches the line's end
    // (8.062 s), from 8.05 to 8.1 s; the engine moves bob on at his speed to the step's end:
    // 0.038 s * 0.5 m/s past the end, along the line.
    let (end, _) = r.frames.last().expect("frames");
    assert!((end - 8.1).abs() < 1e-9, "ends at {end} s");
    let past = (end - len / 0.5) * 0.5;
    let along = |d: f64| (99.0 + d * 2.0 / len, -1.75 + d * 3.5 / len);
    for (t, (x, y)) in [
        (0.0, along(0.0)),
        (4.0, along(2.0)),
        (8.05, along(8.05 * 0.5)),
        (*end, along(len + past)),
    ] {
        let p = r.at(t, "bob");
        assert!(
            (p.x - x).abs() < WALK_TOL && (p.y - y).abs() < WALK_TOL,
            "bob at {t} s: {p:?}, want ({x}, {y})"
        );
    }
    assert_eq!(r.at(*end, "bob").lane, 1);
}
