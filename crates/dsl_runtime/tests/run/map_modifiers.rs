//! The map's modifiers in the scenario's body (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2) against the
//! loaded road: lane fields bound to its lanes and used by `change_lane(target: l)` /
//! `follow_lane(target: l)`, the plan's roads checked, and one failing binding or check per
//! class. Lanes and positions worked by hand in the scenario files' comments.

use std::f64::consts::PI;

use crate::support::{error_on, lower_at};

/// Lateral positions are closed forms of the step times on straight roads.
const Y_TOL: f64 = 1e-6;
/// The lane change's cost in s against its first-order closed form (the next order,
/// ∫ ẏ⁴/(8v³) dt, and the steps make up the 1 mm left).
const COST_TOL: f64 = 3e-3;

fn run(name: &str, road: &str) -> crate::support::Run {
    crate::support::run_on(name, road)
}

fn refused(name: &str, road: &str, text: &str, place: &str) {
    refused_all(name, road, &[text], place);
}

fn refused_all(name: &str, road: &str, texts: &[&str], place: &str) {
    let e = error_on(name, road);
    assert!(
        texts.iter().all(|t| e.contains(t)) && e.ends_with(&format!("{name}.osc:{place}")),
        "{name}: {e}"
    );
}

#[test]
fn end_lane_and_lane_side_bind_the_lane_a_change_moves_into() {
    let r = run("map_lanes", "lane_drop");
    let y = |t: f64| -8.75 + 7.0 * (1.0 - (PI * t / 4.0).cos()) / 2.0;
    let start = r.at(0.0, "ego");
    assert_eq!(start.lane, -3, "ego starts in the ending lane");
    assert!((start.s - 100.0).abs() < Y_TOL, "{start:?}");
    for (t, want) in [(1.0, y(1.0)), (2.0, -5.25), (4.0, -1.75), (6.0, -1.75)] {
        let got = r.at(t, "ego").y;
        assert!((got - want).abs() < Y_TOL, "y({t}) = {got}, want {want}");
    }
    let end = r.at(6.0, "ego");
    assert_eq!(end.lane, -1, "target is lane -1");
    // The engine moves ego at 20 m/s along its path, so along the road at √(v² − ẏ²): the
    // change costs ∫ ẏ²/(2v) dt = Δ²π²/(16·T·v) = 49π²/1280 = 0.378 m of s (to first order).
    let cost = 49.0 * PI * PI / 1280.0;
    let npc = r.at(6.0, "npc");
    assert_eq!(npc.lane, -1, "npc along target");
    assert!(
        (npc.s - 80.0).abs() < Y_TOL && (npc.y + 1.75).abs() < Y_TOL,
        "{npc:?}"
    );
    for (t, s) in [(4.0, 180.0), (6.0, 220.0)] {
        let got = r.at(t, "ego").s;
        assert!((got - (s - cost)).abs() < COST_TOL, "s({t}) = {got}");
    }
}

#[test]
fn lanes_in_sequence_and_opposite_are_bound_through_the_lane_links() {
    let r = run("map_sequence", "lane_drop");
    let y = |t: f64| -1.75 - 3.5 * (1.0 - (PI * t / 4.0).cos()) / 2.0;
    for (t, want) in [(0.0, -1.75), (1.0, y(1.0)), (2.0, -3.5), (4.0, -5.25)] {
        let got = r.at(t, "ego").y;
        assert!((got - want).abs() < Y_TOL, "y({t}) = {got}, want {want}");
    }
    assert_eq!(r.at(4.0, "ego").lane, -2, "after is lane -2 of section 1");
    assert!((r.at(0.0, "ego").s - 310.0).abs() < Y_TOL);
}

#[test]
fn a_turn_through_a_junction_binds_its_lanes_and_the_roads_the_plan_drives() {
    let r = run("map_junction_turn", "junction_trippel_twoway0");
    let at = |t: f64| r.at(t, "ego");
    assert_eq!((at(0.0).road.as_str(), at(0.0).lane), ("0", -1));
    assert!((at(3.0).s - 90.0).abs() < Y_TOL, "{:?}", at(3.0));
    for t in [8.0, 10.0] {
        assert_eq!((at(t).road.as_str(), at(t).lane), ("4", -1), "at {t} s");
    }
}

#[test]
fn a_way_through_a_junction_by_its_roads_is_the_roads_the_plan_drives() {
    // map_junction_roads.osc: clockwise_count 1 from road 0 is road 6, through road 5 (20 m).
    let r = run("map_junction_roads", "junction_trippel_twoway0");
    let at = |t: f64| r.at(t, "ego");
    for (t, road, s) in [
        (0.0, "0", 60.0),
        (3.0, "0", 90.0),
        (5.0, "5", 10.0),
        (10.0, "6", 40.0),
    ] {
        let p = at(t);
        assert_eq!((p.road.as_str(), p.lane), (road, -1), "at {t} s");
        assert!((p.s - s).abs() < Y_TOL, "at {t} s: {p:?}");
    }
}

#[test]
fn a_junction_route_is_the_connecting_road_the_plan_drives_through() {
    // map_junction_route.osc: jr = road 5 (junction 1), 20 m at heading 0 from (100, 0).
    let r = run("map_junction_route", "junction_trippel_twoway0");
    for (t, road, s, x) in [
        (0.0, "5", 0.0, 100.0),
        (1.0, "5", 10.0, 110.0),
        (1.5, "5", 15.0, 115.0),
        (3.5, "6", 15.0, 135.0),
    ] {
        let p = r.at(t, "ego");
        assert_eq!((p.road.as_str(), p.lane), (road, -1), "at {t} s: {p:?}");
        assert!((p.s - s).abs() < Y_TOL, "at {t} s: {p:?}");
        assert!(
            (p.x - x).abs() < Y_TOL && (p.y + 1.5).abs() < Y_TOL,
            "at {t} s: {p:?}"
        );
    }
}

#[test]
fn a_person_walks_a_crossing_the_map_binds_and_a_car_stops_before_her() {
    // map_crossing.osc: c = crosswalk cw1 of road 1 from lane -1 (100, -1.75) to lane 1
    // (100, 1.75), walked at 0.5 m/s from 0 s.
    let r = run("map_crossing", "crosswalk");
    for (t, y) in [(0.0, -1.75), (2.0, -0.75), (3.5, 0.0), (7.0, 1.75)] {
        let p = r.at(t, "alice");
        assert!(
            (p.x - 100.0).abs() < Y_TOL && (p.y - y).abs() < Y_TOL,
            "alice at {t} s: {p:?}"
        );
    }
    assert_eq!(r.at(0.0, "alice").lane, -1);
    assert_eq!(r.at(7.0, "alice").lane, 1);
    let (_, walked) = r.phase("do.cross");
    assert!((walked - 7.0).abs() < Y_TOL, "walk ends at {walked}");
    // The car measures her: its approach ends at 4.65 s, it stands 19.75 m before her.
    let (_, e) = r.phase("do.stop.approach");
    assert!((e - 4.65).abs() < Y_TOL, "approach ends at {e}");
    assert!((r.at(4.65, "car").s - 66.5).abs() < Y_TOL);
    assert!((r.at(5.65, "car").speed - 5.0).abs() < Y_TOL);
    for t in [6.65, 7.65] {
        let car = r.at(t, "car");
        let gap = 99.5 - (car.s + 3.5);
        assert!(
            (car.s - 76.25).abs() < Y_TOL && (gap - 19.75).abs() < Y_TOL,
            "car at {t} s: {car:?}"
        );
    }
}

#[test]
fn a_person_walks_the_part_of_a_crossing_its_offsets_leave() {
    // map_crossing_offsets.osc: c from (100, -1.75) to (100, 1.75) walked from 1 m after its
    // start to 0.5 m before its end, then c2 back from 0.5 m after its start to 1 m before its
    // end, each 2 m at 0.5 m/s and 0.5 m to +x of the crossing's line (the walker's right
    // going, its left coming back); positions worked in the file.
    let r = run("map_crossing_offsets", "crosswalk");
    for (t, y, lane) in [
        (0.0, -0.75, -1),
        (1.0, -0.25, -1),
        (3.0, 0.75, 1),
        (4.0, 1.25, 1),
        (6.0, 0.25, 1),
        (8.0, -0.75, -1),
    ] {
        let p = r.at(t, "alice");
        assert!(
            (p.x - 100.5).abs() < Y_TOL && (p.y - y).abs() < Y_TOL && p.lane == lane,
            "alice at {t} s: {p:?}"
        );
    }
    for (phase, a, b) in [("do.there", 0.0, 4.0), ("do.back", 4.0, 8.0)] {
        let (s, e) = r.phase(phase);
        assert!(
            (s - a).abs() < Y_TOL && (e - b).abs() < Y_TOL,
            "{phase}: [{s}, {e}]"
        );
    }
}

#[test]
fn roads_in_sequence_are_bound_and_driven_from_their_starts() {
    // map_roads_sequence.osc: a = road 1, b = road 2 (linked end to start).
    let r = run("map_roads_sequence", "road_link_unequal_number_of_lanes0");
    // npc's rear bumper at road 1's start: its reference point its rear overhang (under half
    // its length) on.
    let s0 = r.at(0.0, "npc").s;
    assert!((0.0..2.5).contains(&s0), "{s0}");
    for (t, who, road, s) in [
        (0.0, "npc", "1", s0),
        (5.0, "npc", "1", s0 + 50.0),
        (0.0, "ego", "2", 0.0),
        (5.0, "ego", "2", 50.0),
    ] {
        let p = r.at(t, who);
        assert_eq!(p.road.as_str(), road, "{who} at {t} s: {p:?}");
        assert!([-1, -2].contains(&p.lane), "{who} at {t} s: {p:?}");
        assert!((p.s - s).abs() < Y_TOL, "{who} at {t} s: {p:?}");
    }
}

#[test]
fn a_road_and_a_lane_and_two_routes_in_sequence_are_bound_and_driven() {
    // map_sequence_mixed.osc: a = road 1 (lane -2), l = lane -2 of road 2, r1/r2 = roads 1/2.
    let r = run("map_sequence_mixed", "road_link_unequal_number_of_lanes0");
    let s0 = r.at(0.0, "npc").s;
    assert!((0.0..2.5).contains(&s0), "{s0}");
    let truck_lane = r.at(0.0, "truck").lane;
    assert!([-1, -2].contains(&truck_lane), "{truck_lane}");
    for (t, who, road, lane, s) in [
        (0.0, "ego", "2", -2, 0.0),
        (2.5, "ego", "2", -2, 25.0),
        (5.0, "ego", "2", -2, 50.0),
        (0.0, "npc", "1", -2, s0),
        (5.0, "npc", "1", -2, s0 + 50.0),
        (0.0, "truck", "2", truck_lane, 50.0),
        (5.0, "truck", "2", truck_lane, 75.0),
    ] {
        let p = r.at(t, who);
        assert_eq!(
            (p.road.as_str(), p.lane),
            (road, lane),
            "{who} at {t} s: {p:?}"
        );
        assert!((p.s - s).abs() < Y_TOL, "{who} at {t} s: {p:?}");
    }
}

#[test]
fn routes_the_map_makes_in_sequence_are_checked_and_driven() {
    // map_sequence_named.osc: a = road 0 s 10 to 90 m, b = road 6 s 0 to 60 m, lane -1.
    let r = run("map_sequence_named", "junction_trippel_twoway0");
    in_lane_minus_one_at(
        &r,
        &[
            (0.0, "ego", "0", 10.0),
            (5.0, "ego", "0", 60.0),
            (0.0, "npc", "6", 0.0),
            (5.0, "npc", "6", 40.0),
        ],
    );
}

/// Each (t, actor, road, s): the actor on that road at that s in lane -1 at t.
fn in_lane_minus_one_at(r: &crate::support::Run, places: &[(f64, &str, &str, f64)]) {
    for &(t, who, road, s) in places {
        let p = r.at(t, who);
        assert_eq!(
            (p.road.as_str(), p.lane),
            (road, -1),
            "{who} at {t} s: {p:?}"
        );
        assert!((p.s - s).abs() < Y_TOL, "{who} at {t} s: {p:?}");
    }
}

/// A route the map makes beside a road field: the field is the road after (before) it.
/// map_sequence_made_field.osc: b after road 0 s 10 to 90 m is road 2 (the plan's way on,
/// through connecting road 1), c before road 6 s 0 to 60 m is road 0, the lane l after it lane
/// -1 of road 2.
#[test]
fn a_road_field_beside_a_route_the_map_makes_is_the_road_after_or_before_it() {
    let r = run("map_sequence_made_field", "junction_trippel_twoway0");
    in_lane_minus_one_at(
        &r,
        &[
            (0.0, "ego", "2", 0.0),
            (5.0, "ego", "2", 50.0),
            (0.0, "npc", "0", 20.0),
            (5.0, "npc", "0", 60.0),
            (0.0, "truck", "2", 0.0),
            (5.0, "truck", "2", 25.0),
        ],
    );
}

/// Route fields given a value at their declaration are that route: route_field_value.osc, the
/// routes of map_sequence_named.osc as fields (`a: route = …`, `var b: route = …`, `c: route = b`),
/// ego along(a, start_offset: 5m), npc along(c).
#[test]
fn route_fields_given_a_value_are_that_route() {
    let r = run("route_field_value", "junction_trippel_twoway0");
    in_lane_minus_one_at(
        &r,
        &[
            (0.0, "ego", "0", 15.0),
            (5.0, "ego", "0", 65.0),
            (0.0, "npc", "6", 0.0),
            (5.0, "npc", "6", 40.0),
        ],
    );
    let r = run("route_field_value_global", "junction_trippel_twoway0");
    in_lane_minus_one_at(&r, &[(0.0, "ego", "6", 10.0), (5.0, "ego", "6", 50.0)]);
    refused(
        "err_route_field_value_map",
        "junction_trippel_twoway0",
        "expected a route field nothing defines, found `r`, given a route the map makes at its declaration",
        "8:23",
    );
}

#[test]
fn lane_sections_in_sequence_are_bound_and_driven_from_the_second_ones_start() {
    // map_sequence_sections.osc: y = section 1 of road 1 (300 to 500 m).
    let r = run("map_sequence_sections", "lane_drop");
    let lane = r.at(0.0, "ego").lane;
    assert!([-1, -2].contains(&lane), "{lane}");
    for (t, s) in [(0.0, 300.0), (2.5, 325.0), (5.0, 350.0)] {
        let p = r.at(t, "ego");
        assert_eq!((p.road.as_str(), p.lane), ("1", lane), "at {t} s: {p:?}");
        assert!((p.s - s).abs() < Y_TOL, "at {t} s: {p:?}");
    }
}

#[test]
fn a_traffic_lights_control_file_cycles_the_maps_signals() {
    // map_traffic_lights.osc: L go [0, 4) s, attention [4, 5) s, stop [5, 10) s, then again.
    let lowered = lower_at(
        "tests/scenarios/map_traffic_lights.osc",
        "tests/roads/red_light.xodr",
        0,
        None,
    )
    .expect("plans");
    let controllers = &lowered.scenario.road_network.traffic_signal_controllers;
    assert_eq!(controllers.len(), 1);
    assert_eq!(controllers[0].name, "C");
    let durations: Vec<f64> = controllers[0].phases.iter().map(|p| p.duration).collect();
    assert_eq!(durations, [4.0, 1.0, 5.0]);
    let s = &lowered.scenario;
    let network = engine::load::road_network(s).expect("road network");
    let mut engine = engine::Engine::new(s, network, crate::support::config()).expect("engine");
    let mut seen = Vec::new();
    for (t, want) in [
        (2.0, "off;off;on"),
        (4.5, "off;on;off"),
        (7.0, "on;off;off"),
        (12.0, "off;off;on"),
    ] {
        while engine.time() < t - 1e-9 {
            engine.step(&mut (), &mut ()).expect("steps");
        }
        let states = engine.signal_states();
        let l = states
            .iter()
            .find(|(id, _)| id == "L")
            .map(|(_, v)| v.as_str());
        seen.push((t, l.map(str::to_string)));
        assert_eq!(l, Some(want), "at {t} s: {seen:?}");
    }
}

#[test]
fn map_checks_that_fail_name_what_the_map_has() {
    refused(
        "err_map_number_of_lanes",
        "straight",
        "expected 3 driving lanes on `r` (the roads the plan drives on), found 5 on road 1 (the lane section from s = 0.00 m: lanes [-3, -2, -1, 1, 2])",
        "7:5",
    );
    refused(
        "err_map_overlap",
        "straight",
        "expected `a` and `b` to overlap as inside, found both the roads the plan drives on (1), which overlap as equal",
        "7:5",
    );
}

#[test]
fn map_bindings_with_no_lane_or_a_lane_the_use_cannot_take_are_errors() {
    refused(
        "err_map_start_lane",
        "straight",
        "expected lanes of the map for `l` that satisfy start_lane(…), found none on roads 1",
        "6:5",
    );
    refused(
        "err_map_sequence",
        "straight",
        "expected lanes of the map for `a`, `b` that satisfy routes_are_in_sequence(…), found none on roads 1",
        "7:5",
    );
    refused(
        "err_map_side_section",
        "road_link_unequal_number_of_lanes0",
        "expected lanes of the map for `k`, `l` that satisfy lane_side(…) and the map modifiers before it, found none on roads 1, 2",
        "10:5",
    );
    refused(
        "err_map_junction_other",
        "junction_trippel_twoway0",
        "expected direction straight, right, u_turn or left, found other: every way through a junction is one of those four",
        "9:68",
    );
    refused(
        "err_map_junction",
        "junction_trippel_twoway0",
        "expected lanes of the map for `a`, `b` that satisfy roads_follow_in_junction(…), found none on roads 0, 2, 4, 6",
        "8:5",
    );
    refused(
        "err_map_junction_roads",
        "junction_trippel_twoway0",
        "that satisfy roads_follow_in_junction(…), found none on roads 0, 2, 4, 6",
        "8:5",
    );
    refused(
        "err_map_junction_clockwise",
        "junction_trippel_twoway0",
        "that satisfy roads_follow_in_junction(…), found none on roads 0, 2, 4, 6",
        "7:5",
    );
    refused(
        "err_map_junction_route",
        "straight",
        "expected lanes of the map for `r_in's lane into the junction (roads_follow_in_junction at 8:5)`, `the road's lane out of the junction (roads_follow_in_junction at 8:5)` that satisfy roads_follow_in_junction(…), found none on roads 1",
        "8:5",
    );
    refused(
        "err_map_sequence_roads",
        "straight",
        "expected lanes of the map for `a's lane (routes_are_in_sequence at 10:5)`, `b's lane (routes_are_in_sequence at 10:5)` that satisfy routes_are_in_sequence(…), found none on roads 1",
        "10:5",
    );
    refused(
        "err_map_sequence_road_arg",
        "road_link_unequal_number_of_lanes0",
        "expected a road holding both routes in road: (\"one route follows another in successive order\": the succeeding one after the preceding one's end), found `a`, the preceding route itself",
        "11:65",
    );
    refused(
        "err_map_crossing",
        "sidewalk",
        "expected a crosswalk on the map for `cross` (an OpenDRIVE object of type crosswalk with an outline, or a length and width), found none on roads ",
        "8:5",
    );
    refused(
        "err_map_crossing_s",
        "crosswalk",
        "expected lanes of the map for `a`, `b` that satisfy crossing_connects(…), found none on roads 1",
        "8:5",
    );
    refused(
        "err_map_crossing_offsets",
        "crosswalk",
        "expected start_offset + end_offset below the length of crossing `c2`, 3.50 m (crosswalk cw1 of road 1 bound by map.crossing_connects(…) at ",
        "18:13",
    );
    refused(
        "err_map_sequence_named",
        "road_link_unequal_number_of_lanes0",
        "expected the succeeding route to start where the preceding one ends (road 2 at s = 60 m) or after it: expected a path in lane -1 from road 2 at s = 60 m to road 1 at s = 10 m in the driving direction, found none",
        "7:5",
    );
    refused(
        "err_map_sequence_made_point",
        "road_link_unequal_number_of_lanes0",
        "expected a preceding route with an end (map.create_route([…]) through two or more points), found one from a single point",
        "8:41",
    );
    refused_all(
        "err_map_crossing_away",
        "crosswalk",
        &[
            "expected `alice` at the start of crossing `c` (crosswalk cw1 of road 1 bound by map.crossing_connects(…) at ",
            "err_map_crossing_away.osc:11:5: lane -1 at s = 100.00 m, t = -1.75 m) when its walk starts, found it in lane -1 at s = 92.00 m, t = -1.75 m",
        ],
        "17:13",
    );
    refused(
        "err_map_roads_sequence_off",
        "road_link_unequal_number_of_lanes0",
        "expected `npc` on route `a` (road 1 bound by map.routes_are_in_sequence(…) at ",
        "10:9",
    );
    refused(
        "err_map_other_road",
        "road_link_unequal_number_of_lanes0",
        "expected a lane of the roads the plan drives on (1) for `l`, found lane -3 of road 2 (bound by map.start_lane(…) at ",
        "10:32",
    );
    refused_all(
        "err_map_against",
        "lane_drop",
        &[
            "expected a driving lane of road 1 in the direction `ego` drives (right-hand traffic: lanes [-3, -2, -1]) at s = ",
            "for `l`, found lane 1 (bound by map.lane_side(…) at ",
            "err_map_against.osc:10:5), which runs against it",
        ],
        "11:32",
    );
    refused_all(
        "err_map_opposite",
        "lane_drop",
        &[
            "for `oncoming`, found lane 1 (bound by map.routes_are_opposite(…) at ",
            "err_map_opposite.osc:15:5), which runs against it",
        ],
        "16:32",
    );
    refused(
        "err_map_along",
        "lane_drop",
        "expected `npc` in the lane of route `target` (lane -1, bound by map.lane_side(…) at ",
        "23:13",
    );
}

#[test]
fn modifiers_of_the_scenario_the_runtime_does_not_run_say_why() {
    refused(
        "err_map_traffic_lights",
        "red_light",
        "red_light_control_unknown.xosc in the map (signals L), found `M` in phase `stop` of controller `C` at ",
        "6:5",
    );
    refused(
        "err_map_traffic_lights_missing",
        "red_light",
        "expected an OpenSCENARIO 1.x file of traffic signal controllers for set_traffic_lights_control_file, found one that does not load: ",
        "6:5",
    );
    refused(
        "err_scenario_modifier",
        "straight",
        "modifier `speed` needs an actor to apply to",
        "6:5",
    );
    refused(
        "err_scenario_user_modifier",
        "straight",
        "found `gentle(…)`, a modifier applied to the scenario itself",
        "9:5",
    );
    refused(
        "err_map_invoked",
        "lane_drop",
        "found `lane_side(…)`, a map modifier in an invoked scenario (the map is the run's: write it in the scenario that runs)",
        "7:5",
    );
}
