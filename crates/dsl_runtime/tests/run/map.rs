//! The whole map (issue 28 step 3): actors drive from the plan's first road onto its successor
//! and through a junction, and are placed by `create_odr_point` on roads other than the first,
//! on road files of the corpus (`tests/roads/`). Road ids and s are worked by hand in the
//! scenario files' comments.

use crate::support::{error_on, lower_at};

/// Positions over arcs and spirals: the engine advances the reference line by the step's
/// distance / (1 − κ·t) with κ at the step's start, and carries the rest of a step that crosses
/// a road's end onto the next road at the old road's scale (up to 1.5 % of one 1.5 m step here).
const CURVED_TOL: f64 = 0.03;
/// Positions on straight roads: float round-off only.
const S_TOL: f64 = 1e-6;

fn run(name: &str, road: &str) -> crate::support::Run {
    crate::support::run_on(name, road)
}

/// Runs `name` on junction_trippel_twoway0 to its error: the one error record's time and
/// element, and the run's error.
fn run_to_its_error(name: &str) -> (f64, String, String) {
    let lowered = lower_at(
        &format!("tests/scenarios/{name}.osc"),
        "tests/roads/junction_trippel_twoway0.xodr",
        0,
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = crate::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert_eq!(records.len(), 1, "{records:?}");
    let (time, element, _) = records
        .into_iter()
        .next()
        .expect("one record, asserted above");
    (time, element, error)
}

#[test]
fn a_drive_goes_on_from_a_road_onto_its_successor() {
    let r = run("map_successor", "manual_add_of_geometries0");
    let ego = r.at(0.0, "ego");
    assert_eq!((ego.road.as_str(), ego.lane), ("0", -1));
    assert!((ego.s - 50.0).abs() < S_TOL, "{ego:?}");
    let ego = r.at(5.0, "ego");
    assert_eq!(ego.road, "0");
    assert!((ego.s - 198.522).abs() < CURVED_TOL, "{ego:?}");
    let ego = r.at(7.0, "ego");
    assert_eq!((ego.road.as_str(), ego.lane), ("1", -1));
    assert!((ego.s - 58.5).abs() < CURVED_TOL, "{ego:?}");
    assert!(
        (ego.x - 217.017).abs() < CURVED_TOL && (ego.y - 94.385).abs() < CURVED_TOL,
        "{ego:?}"
    );
    // Placed on road 1, the second road of the plan.
    let npc = r.at(0.0, "npc");
    assert_eq!((npc.road.as_str(), npc.lane), ("1", -1));
    assert!((npc.s - 20.0).abs() < S_TOL, "{npc:?}");
    assert!((r.at(7.0, "npc").s - 90.0).abs() < S_TOL);
}

#[test]
fn a_drive_goes_through_a_junction_by_its_first_connection() {
    let r = run("map_junction", "junction_trippel_twoway0");
    let ego = r.at(0.0, "ego");
    assert_eq!((ego.road.as_str(), ego.lane), ("0", -1));
    assert!((ego.s - 60.0).abs() < S_TOL, "{ego:?}");
    let ego = r.at(5.0, "ego");
    assert_eq!(ego.road, "1", "{ego:?}");
    assert!((ego.s - 9.941).abs() < CURVED_TOL, "{ego:?}");
    let ego = r.at(10.0, "ego");
    assert_eq!((ego.road.as_str(), ego.lane), ("2", -1));
    assert!((ego.s - 29.55).abs() < CURVED_TOL, "{ego:?}");
    assert!(
        (ego.x - 158.391).abs() < CURVED_TOL && (ego.y - 10.429).abs() < CURVED_TOL,
        "{ego:?}"
    );
    // Placed on road 2, beyond the junction.
    let npc = r.at(0.0, "npc");
    assert_eq!((npc.road.as_str(), npc.lane), ("2", -1));
    assert!((npc.s - 40.0).abs() < S_TOL, "{npc:?}");
    assert!((r.at(10.0, "npc").s - 90.0).abs() < S_TOL);
}

/// runtime_checks_several_roads.osc's comment, by hand: after an until, lane(1) and
/// position(146.55m) are the engine's checks on road 2, the plan's third road.
#[test]
fn run_time_checks_on_several_roads_measure_along_the_plans_roads() {
    let r = crate::support::run_on("runtime_checks_several_roads", "junction_trippel_twoway0");
    let (s, e) = r.phase("do.follow");
    assert!(
        (s - 0.85).abs() < 1e-9 && (e - 15.85).abs() < 1e-9,
        "[{s}, {e}]"
    );
    let ego = r.at(15.85, "ego");
    assert_eq!((ego.road.as_str(), ego.lane), ("2", -1), "{ego:?}");
    // The engine steps the spiral's lane length by the curvature at each step's start.
    assert!((ego.s - 16.55).abs() < 0.01, "{ego:?}");
    for check in ["do.check/ego/1:check", "do.check/ego/2:check"] {
        let t = r
            .when(check, "End")
            .unwrap_or_else(|| panic!("{check} ran"));
        assert!((t - 15.85).abs() < 1e-9, "{check} at {t}");
    }
}

#[test]
fn a_route_goes_through_a_junction_by_the_connection_it_names() {
    // map_route.osc: the route from road 0 to road 6 takes the junction's third connection
    // (connecting road 5), not the first (road 1); positions worked in the file.
    let r = run("map_route", "junction_trippel_twoway0");
    let at = |t: f64, who: &str, road: &str, s: f64, x: f64| {
        let p = r.at(t, who);
        assert_eq!(
            (p.road.as_str(), p.lane),
            (road, -1),
            "{who} at {t} s: {p:?}"
        );
        assert!((p.s - s).abs() < S_TOL, "{who} at {t} s: {p:?}");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 1.5).abs() < S_TOL,
            "{who} at {t} s: {p:?}"
        );
    };
    at(0.0, "ego", "0", 60.0, 60.0);
    at(5.0, "ego", "5", 10.0, 110.0);
    at(12.0, "ego", "6", 60.0, 180.0);
    at(0.0, "npc", "0", 20.0, 20.0);
    at(9.0, "npc", "5", 10.0, 110.0);
    at(12.0, "npc", "6", 20.0, 140.0);
}

#[test]
fn routes_no_path_joins_or_in_two_lanes_are_errors_at_their_place() {
    for (name, text, place) in [
        (
            "err_route_unconnected",
            "expected a path in lane -1 from road 2 at s = 10 m to road 0 at s = 50 m in the driving direction, found none",
            "err_route_unconnected.osc:8:9",
        ),
        (
            "err_route_two_lanes",
            "expected every point of a route in a lane driven the way lane -1 is (a legal route, §8.12.2.1 legal_route; right-hand traffic: lanes of negative id driven in +s), found lane 1, driven the other way (a route from it would turn about, which no lane change does)",
            "err_route_two_lanes.osc:8:71",
        ),
    ] {
        let e = error_on(name, "junction_trippel_twoway0");
        assert!(e.contains(text) && e.ends_with(place), "{name}: {e}");
    }
}

/// runtime_several_roads.osc's comment, by hand: after an until, a TravelAction to a place
/// behind lead, along(r) on a named route, a time gap without a duration and a projected gap,
/// each measured in the plan's s across roads 0, 1 and 2.
#[test]
fn run_time_travel_route_and_gaps_on_several_roads_measure_along_the_plans_roads() {
    let r = run("runtime_several_roads", "junction_trippel_twoway0");
    for (phase, a, b) in [
        ("do.ego.approach", 0.0, 0.85),
        ("do.ego.travel", 0.85, 10.85),
        ("do.ego.close", 10.85, 12.30),
        ("do.ego.proj", 12.30, 13.30),
    ] {
        let (s, e) = r.phase(phase);
        assert!(
            (s - a).abs() < 1e-9 && (e - b).abs() < 1e-9,
            "{phase}: [{s}, {e}]"
        );
    }
    let on = |t: f64, who: &str, road: &str, s: f64, v: f64| {
        let p = r.at(t, who);
        assert_eq!(
            (p.road.as_str(), p.lane),
            (road, -1),
            "{who} at {t} s: {p:?}"
        );
        assert!((p.s - s).abs() < CURVED_TOL, "{who} at {t} s: {p:?}");
        assert!((p.speed - v).abs() < 1e-6, "{who} at {t} s: {p:?}");
    };
    // The TravelAction's two halves: 20 -> 7.96 -> 8 m/s over 5 s each, stepped.
    on(5.85, "ego", "0", 96.599, 7.96);
    on(10.85, "ego", "2", 6.05, 8.0);
    on(10.85, "lead", "2", 16.35, 8.0);
    // The time gap reached falling back at 4 m/s; then the projected one.
    on(12.30, "ego", "2", 11.85, 4.0);
    on(12.30, "lead", "2", 27.95, 8.0);
    on(13.30, "ego", "2", 15.85, 4.0);
    // lead braked from 12.5 s: 0.34 m short of its projection (road 2 s 35.95 m).
    let lead = r.at(13.30, "lead");
    assert!((lead.s - 35.61).abs() < CURVED_TOL, "{lead:?}");
    // The named route's check at the close phase's start passed (a failure stops the run).
    let t = r.when("do.ego.close/ego/3:check", "End");
    assert!(t.is_some_and(|t| (t - 10.85).abs() < 1e-9), "{t:?}");
}

/// runtime_distance_several_roads.osc's comment, by hand: distance(100m) over 8 s after an
/// until runs 100 m of lane from road 0 onto road 1's spiral.
#[test]
fn a_distance_after_an_until_on_several_roads_runs_along_the_lane_across_them() {
    let r = run("runtime_distance_several_roads", "junction_trippel_twoway0");
    let (s, e) = r.phase("do.travel");
    assert!(
        (s - 0.85).abs() < 1e-9 && (e - 8.85).abs() < 1e-9,
        "[{s}, {e}]"
    );
    for (t, road, s_road, v) in [(4.85, "0", 76.625, 5.0), (8.85, "1", 26.6407, 20.0)] {
        let p = r.at(t, "ego");
        assert_eq!((p.road.as_str(), p.lane), (road, -1), "{t}: {p:?}");
        assert!((p.s - s_road).abs() < CURVED_TOL, "{t}: {p:?}");
        assert!((p.speed - v).abs() < 1e-6, "{t}: {p:?}");
    }
}

/// runtime_lane_of_several_roads.osc's comment, by hand: lane(same_as: lead) after an until
/// holds with ego on road 0 and lead on road 1, both in lane -1 of the plan's roads.
#[test]
fn a_lane_relative_to_another_actor_after_an_until_holds_across_the_plans_roads() {
    let r = run("runtime_lane_of_several_roads", "junction_trippel_twoway0");
    let (ego, lead) = (r.at(5.85, "ego"), r.at(5.85, "lead"));
    assert_eq!((ego.road.as_str(), ego.lane), ("0", -1), "{ego:?}");
    assert!((ego.s - 67.0).abs() < S_TOL, "{ego:?}");
    assert_eq!((lead.road.as_str(), lead.lane), ("1", -1), "{lead:?}");
    assert!((lead.s - 6.7692).abs() < CURVED_TOL, "{lead:?}");
    // The check (at: all) held over do.same, both at 8 m/s in lanes -1 (a failure stops the
    // run).
    r.held("do.same/ego/1:check", (5.85, 6.85));
}

/// runtime_lateral_of_several_roads.osc's comment, by hand: lateral(0m, side_of: lead) after an
/// until holds with ego at t = −1.5 m of road 0 and lead at t = −1.5 m of road 1 (one measure:
/// their reference lines join continuously at (100, 0)); lateral(3m, left_of: lead) a phase
/// later fails on the measured 0 m, not on the two roads.
#[test]
fn a_lateral_position_beside_another_actor_after_an_until_compares_t_across_the_plans_roads() {
    // ego on road 0 and lead on road 1 at 5.85 s: the places of
    // a_lane_relative_to_another_actor_after_an_until_holds_across_the_plans_roads (the same
    // phases up to there). do.beside's check passed at 5.85 s (no record); do.apart's failed
    // at 6.85 s.
    let (time, element, error) = run_to_its_error("runtime_lateral_of_several_roads");
    assert_eq!(element, "do.apart/ego/1:check");
    assert!((time - 6.85).abs() < 1e-9, "{time}");
    let want = "expected 'ego' 3.000 m to the left of 'lead' across the road (within 0.01 m)";
    assert!(
        error.starts_with(want) && error.contains("found 0.000 m at t = 6.850 s"),
        "{error}"
    );
}

/// runtime_several_roads_off_route.osc's comment, by hand: the route on road 2 checked in the
/// plan's s while ego is on road 0 at s 27 m.
#[test]
fn a_named_route_after_an_until_on_several_roads_is_checked_in_the_plans_s() {
    let (time, element, error) = run_to_its_error("runtime_several_roads_off_route");
    assert_eq!(element, "do.off_route/ego/1:check");
    assert!((time - 0.85).abs() < 1e-9, "{time}");
    let want = "expected 'ego' at s = 180.000 m (within 50.5 m) (along(…) at ";
    assert!(
        error.starts_with(want) && error.contains("runtime_several_roads_off_route.osc:21:13"),
        "{error}"
    );
    assert!(
        error.ends_with("found it at s = 27.000 m at t = 0.850 s"),
        "{error}"
    );
}

/// runtime_place_on_road_several_roads.osc's comment, by hand: from s = 27 m of road 0 ego
/// moves to offset 0.8 m of lane -1 along a sinusoid of the way, D = 73 + 30.45 + 20 =
/// 123.45 m of lane across roads 0, 1 and 2, arriving at s = 20 m of road 2 (0.17 m past it:
/// the engine counts the way along ego's own path, shorter on road 1's left turn).
#[test]
fn change_position_on_the_road_network_after_an_until_arrives_across_the_plans_roads() {
    let r = run(
        "runtime_place_on_road_several_roads",
        "junction_trippel_twoway0",
    );
    const D: f64 = 123.45;
    let offset = |u: f64| 0.8 * (1.0 - (std::f64::consts::PI * u / D).cos()) / 2.0;
    // Road 0 (straight along +x, lane -1's centre at y = -1.5 m): u = x - 27 m, as the
    // one-road test (runtime::change_position_on_the_road_network_after_an_until_…): 1 mm.
    let (mut on_road_0, mut on_road_2) = (0, 0);
    let (x0, y0, h) = (129.71723128680293, 3.1297684891414503, 0.3_f64);
    // Every step from 0.85 s to the run's end at 8.10 s.
    for k in 0..=145 {
        let t = 0.85 + 0.05 * f64::from(k);
        let ego = r.at(t, "ego");
        match ego.road.as_str() {
            "0" => {
                on_road_0 += 1;
                let want = offset(ego.x - 27.0);
                assert!(
                    (ego.y + 1.5 - want).abs() < 1e-3,
                    "{t}: {ego:?}, want {want}"
                );
            }
            "2" => {
                on_road_2 += 1;
                // t from road 2's reference line; u = 103.45 m + s there, which the engine's
                // way along ego's shorter path on road 1 reaches up to 0.24 m later (0.3 rad ·
                // 0.8 m): the sinusoid's slope 0.8·π/(2D) = 0.0102 at most, 3 mm.
                let t_road = -(ego.x - x0) * h.sin() + (ego.y - y0) * h.cos();
                let want = offset((103.45 + ego.s).min(D));
                assert!(
                    (t_road + 1.5 - want).abs() < 3e-3,
                    "{t}: {ego:?}, want {want}"
                );
                assert_eq!(ego.lane, -1, "{t}: {ego:?}");
            }
            _ => {}
        }
    }
    assert!(on_road_0 > 50 && on_road_2 > 20, "{on_road_0} {on_road_2}");
    // The mid-point, x = 88.725 m of road 0, offset 0.4 m: the frames either side of it.
    let (a, b) = (r.at(3.9, "ego"), r.at(3.95, "ego"));
    assert!(
        a.x < 88.725 && b.x > 88.725 && a.y + 1.5 < 0.4 && b.y + 1.5 > 0.4,
        "{a:?} {b:?}"
    );
    // Arrived: offset 0.8 m exactly from the step that ends at 7.05 s; the phase ends at 7.10 s.
    for t in [7.05, 7.1, 8.1] {
        let ego = r.at(t, "ego");
        let t_road = -(ego.x - x0) * h.sin() + (ego.y - y0) * h.cos();
        assert!(
            ego.road == "2" && (t_road + 0.7).abs() < 1e-6,
            "{t}: {ego:?}, t {t_road}"
        );
    }
    let (s, e) = r.phase("do.cut");
    assert!(
        (s - 0.85).abs() < 1e-9 && (e - 7.1).abs() < 1e-9,
        "[{s}, {e}]"
    );
    // ego's path from 0.85 s is 20 m/s·τ: 123 m at 7.00 s, road 2's s 123 - 103.45 = 19.55 m
    // along the lane's centre plus what road 1's left turn saves ego's path left of it
    // (0.1 to 0.3 m: the comment's 0.17 m); not arrived then, arrived at 7.05 s, 1 m on.
    let (a, b) = (r.at(7.0, "ego"), r.at(7.05, "ego"));
    let saved = a.s - 19.55;
    assert!(a.road == "2" && (0.1..0.3).contains(&saved), "{a:?}");
    assert!((b.s - a.s - 1.0).abs() < 1e-6, "{b:?}");
}

/// runtime_place_on_road_several_roads_behind.osc's comment, by hand: p at plan s 20 m is
/// behind ego's 27 m when the phase starts at 0.85 s: an error record then.
#[test]
fn change_position_on_the_road_network_behind_the_actor_on_several_roads_fails_the_run() {
    let (time, element, error) = run_to_its_error("runtime_place_on_road_several_roads_behind");
    assert!((time - 0.85).abs() < 1e-9, "{time}");
    assert_eq!(element, "do.cut/ego/1:change_position");
    assert!(
        error.starts_with("expected s = 20.000 m of one of roads 0, 1, 2 (the plan's s) ahead of 'ego' along its lane (change_position(…) at ")
            && error.ends_with("runtime_place_on_road_several_roads_behind.osc:21:9), found it at s = 27.000 m (s = 27.000 m of road 0) at t = 0.850 s"),
        "{error}"
    );
}

/// The map's routes (issue 27; `m.routes[i]` was an error at the argument): one per road of the
/// OpenDRIVE file, in its order, each the whole road. map_routes.osc on two_roads.xodr, by hand:
/// m.routes[0] is road 1; ego along it from the road's start in its rightmost driving lane
/// (lane -2, y = -5.25 m), its rear at s = 0 (x = 0.5 m), x = 30.5 m at 3 s; npc with lane(2) and position(50m) in lane -1 from
/// x = 50 m to 80 m.
#[test]
fn the_maps_routes_are_its_roads_in_the_files_order() {
    let r = run("map_routes", "two_roads");
    let (e0, e3) = (r.at(0.0, "ego"), r.at(3.0, "ego"));
    assert!(e0.road == "1" && e0.lane == -2, "{e0:?}");
    assert!((e0.y + 5.25).abs() < S_TOL, "{e0:?}");
    // From the road's start, the rear bumper at s = 0: the reference point 0.5 m ahead.
    assert!((e0.x - 0.5).abs() < S_TOL, "{e0:?}");
    assert!((e3.x - 30.5).abs() < S_TOL && e3.lane == -2, "{e3:?}");
    for (t, x) in [(0.0, 50.0), (3.0, 80.0)] {
        let p = r.at(t, "npc");
        assert!(
            p.road == "1" && p.lane == -1 && (p.x - x).abs() < S_TOL && (p.y + 1.75).abs() < S_TOL,
            "at {t} s: {p:?}"
        );
    }
}

/// A map route off the plan's roads, or past the file's roads: errors at the along.
#[test]
fn a_map_route_off_the_plan_or_past_the_files_roads_is_an_error_at_the_along() {
    refused_on(
        ("err_map_route_off", "two_roads"),
        "expected `m.routes[1]` on the roads the plan drives on (1), found road 2, the map's route 1 (one per road",
        "10:13",
    );
    refused_on(
        ("err_map_route_index", "two_roads"),
        "expected an index below 2 into the map's routes (one per road of the OpenDRIVE file, in its order), found `m.routes[5]`",
        "7:9",
    );
}

/// Asserts that `NAME.osc` on `ROAD.xodr` is refused with a message holding `text`, at `at`.
fn refused_on((name, road): (&str, &str), text: &str, at: &str) {
    let e = error_on(name, road);
    assert!(
        e.contains(text) && e.ends_with(&format!("{name}.osc:{at}")),
        "{e}"
    );
}

/// A junction's roads (issue 27): its connecting roads in the order its connections name them.
/// map_junction_road.osc on junction_trippel_twoway0.xodr, by hand: m.junctions[0].roads[0] is
/// road 1; ego from its start (s = 0, x = 100 m) in lane -1, s = 9.941 m at 1 s (10 m along
/// the spiral's lane centre). Past the junction's three roads: an error at along.
#[test]
fn a_junctions_roads_are_its_connecting_roads_in_order() {
    let r = run("map_junction_road", "junction_trippel_twoway0");
    let (e0, e1) = (r.at(0.0, "ego"), r.at(1.0, "ego"));
    assert!(
        e0.road == "1" && e0.lane == -1 && e0.s.abs() < S_TOL && (e0.x - 100.0).abs() < S_TOL,
        "{e0:?}"
    );
    assert!(
        e1.road == "1" && (e1.s - 9.941).abs() < CURVED_TOL,
        "{e1:?}"
    );
    refused_on(
        ("err_map_junction_road", "junction_trippel_twoway0"),
        "expected an index below 3 into the roads of junction 1 (its connecting roads in the order its connections name them), found `m.junctions[0].roads[3]`",
        "7:9",
    );
}
