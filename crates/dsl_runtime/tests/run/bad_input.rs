//! Bad input is an error before the run, with FILE:LINE:COL (issue 27, item 4): one test per
//! class — an action the actor does not have, a missing mandatory argument, a target that
//! cannot be reached within the vehicle's limits or the phase's duration, and a modifier that
//! contradicts the action it modifies.

use crate::support::error;

fn expect(name: &str, place: &str, words: &[&str]) {
    let e = error(&format!("actions/{name}"));
    assert!(e.contains(&format!("{name}.osc:{place}")), "{e}");
    for w in words {
        assert!(e.contains(w), "{w:?} not in {e}");
    }
}

#[test]
fn an_action_the_actor_does_not_have() {
    expect(
        "err_walk_vehicle",
        "4:12",
        &["unknown action or scenario `walk` on actor `vehicle`"],
    );
}

#[test]
fn a_missing_mandatory_argument() {
    expect(
        "err_missing_target",
        "4:8",
        &["expected a target in change_speed(…) (a mandatory argument), found none"],
    );
}

#[test]
fn missing_mandatory_arguments_of_the_position_trajectory_and_gap_actions() {
    expect(
        "err_change_position_none",
        "5:9",
        &["expected a target in change_position(…) (a mandatory argument, a position_3d), found none"],
    );
    expect(
        "err_follow_trajectory_none",
        "5:9",
        &["expected a trajectory in follow_trajectory(…) (absolute: or relative:, one is mandatory), found none"],
    );
    expect(
        "err_gap_no_target",
        "8:9",
        &["expected a target in change_space_gap(…) (a mandatory argument), found none"],
    );
}

#[test]
fn change_position_on_the_road_network_behind_or_too_sharp() {
    expect(
        "err_change_position_on_road",
        "10:9",
        &["expected change_position(…, on_road_network: true) within the vehicle's ±10 m/s² lateral acceleration, found it needs 138.17 m/s² to move 7.00 m sideways in 0.50 s"],
    );
    expect(
        "err_change_position_behind",
        "9:9",
        &["expected the target of change_position(…, on_road_network: true) ahead of `ego` (s = 50.00 m), found it at s = 10.00 m"],
    );
}

#[test]
fn a_relative_trajectory_of_route_points_or_without_its_reference() {
    expect(
        "err_relative_route_points",
        "11:41",
        &["expected point 0 of `rt` (a route element, left to the runtime) given by a keep of its declaration"],
    );
    expect(
        "err_relative_no_reference",
        "10:9",
        &["expected a reference in follow_trajectory(…) (a mandatory argument), found none"],
    );
}

#[test]
fn offsets_that_leave_nothing_of_the_trajectory() {
    expect(
        "err_trajectory_offsets",
        "13:76",
        &["expected start_offset + end_offset below the trajectory's length 40.00 m, found 40.00 m"],
    );
}

#[test]
fn a_trajectory_faster_than_the_vehicle() {
    expect(
        "err_follow_trajectory_fast",
        "15:41",
        &["expected a trajectory within the vehicle's 70 m/s, found segment 2 (100.00 m in 1.00 s) needs 100.00 m/s"],
    );
}

#[test]
fn a_target_beyond_the_vehicle_limits_or_the_duration() {
    expect(
        "err_speed_limits",
        "4:8",
        &["within the vehicle's ±10 m/s²", "needs 20.00 m/s²"],
    );
    expect(
        "err_speed_duration",
        "4:8",
        &["within the action's 3 s", "needs 10.00 s"],
    );
    // After a run-time start the engine checks the rate from the speed the actor has then
    // (runtime::a_speed_change_from_the_speed_after_change_acceleration_beyond_the_limit_fails_the_run).
}

#[test]
fn a_modifier_that_contradicts_the_action() {
    expect(
        "err_speed_modifier",
        "6:9",
        &["expected no speed modifier beside change_speed(…), which controls the speed, found `speed(…)`"],
    );
}

#[test]
fn lateral_actions_with_bad_arguments() {
    expect(
        "err_change_lane_target",
        "6:49",
        &["expected either target: or num_of_lanes: in change_lane(…) (target: names the lane itself, num_of_lanes: one relative to an actor), found both"],
    );
    expect(
        "err_follow_lane_target",
        "13:33",
        &[
            "at the start of follow_lane(target: l), which follows the lane the actor is in",
            "found lane -2",
            "drawn for `l` at ",
            "err_follow_lane_target.osc:9:33)",
        ],
    );
    expect(
        "err_change_lane_same",
        "4:30",
        &["expected a reference with side: same"],
    );
    expect(
        "err_follow_lane_offset",
        "4:32",
        &["expected an offset within the lane's half width ±1.75 m, found 3.00 m"],
    );
}

#[test]
fn lateral_actions_beyond_the_limits_or_contradicted() {
    expect(
        "err_change_lane_fast",
        "4:8",
        &[
            "within the vehicle's ±10 m/s² lateral acceleration",
            "needs 17.27 m/s²",
        ],
    );
    expect(
        "err_change_lane_modifier",
        "7:9",
        &["expected no lane or lateral modifier beside change_lane(…), which controls the lateral position, found `lateral(…)`"],
    );
}

#[test]
fn gap_actions_without_a_reference_sideways_or_followed_at_a_planned_time() {
    expect(
        "err_gap_no_reference",
        "7:9",
        &["expected a reference in change_space_gap(…) (a mandatory argument), found none"],
    );
    expect(
        "err_gap_lateral",
        "12:9",
        &["expected a 5 m gap right of `lead` to leave `ego` in a driving lane, found it at t = -12.25 m across the road"],
    );
    expect(
        "err_gap_lateral_lane",
        "10:13",
        &["expected no lane or lateral modifier beside change_space_gap(…), which controls the lateral position, found `lane(…)`"],
    );
    expect(
        "err_gap_then_timed",
        "12:9",
        &[
            "expected this phase of `ego` to start on a run-time condition",
            "found it at 5.00 s",
        ],
    );
}

#[test]
fn assign_position_without_or_with_two_places_or_off_the_road() {
    expect(
        "err_assign_position_none",
        "4:8",
        &["expected a position, route_point or odr_point in assign_position(…) (one is mandatory), found none"],
    );
    expect(
        "err_assign_position_two",
        "6:52",
        &["expected one of position, route_point and odr_point in assign_position(…), found `position` and `odr_point`"],
    );
    expect(
        "err_assign_orientation_none",
        "4:8",
        &["expected a target in assign_orientation(…) (a mandatory argument, an orientation_3d), found none"],
    );
    expect(
        "err_assign_orientation_moving",
        "11:9",
        &["expected `ego` standing at the start of assign_orientation(…) (a moving vehicle follows its lane), found it at 10.00 m/s"],
    );
    expect(
        "err_assign_position_off",
        "5:39",
        &["expected a place in a driving lane of road 1, found s = 120.00 m, lane -4 outside them"],
    );
}

#[test]
fn a_smooth_trajectory_with_two_points_at_one_place() {
    expect(
        "err_trajectory_smooth_same_point",
        "19:41",
        &["expected the points of a smooth path apart, found points 2 and 3 at the same place"],
    );
}

#[test]
fn follow_path_and_a_trajectory_without_its_times() {
    expect(
        "err_follow_path_field",
        "6:24",
        &["found `p`, which is no struct the solver resolved (a path is made by map.create_path(points: [...], interpolation: ...))"],
    );
    expect(
        "err_follow_path_standing",
        "10:8",
        &["expected `ego` moving at the start of follow_path(…) (it moves at the speed it has), found it standing"],
    );
    expect(
        "err_follow_trajectory_times",
        "7:30",
        &["expected two or more points with as many rising time stamps, found 3 points and 2 time stamps"],
    );
}

/// Bad input the runtime used to report as `ErrorKind::Unsupported`, which docs/dsl.md keeps
/// for what oscsim does not run: each now has the kind that says what is wrong, at its
/// file:line:column (the scenarios' comments).
#[test]
fn bad_input_once_reported_as_not_run_has_the_kind_of_its_fault() {
    use dsl_runtime::ErrorKind as K;
    for (name, kind, place, text) in [
        (
            "err_map_lane_use_other",
            K::Argument,
            "9:5",
            "expected a split the OpenDRIVE lane types say (see docs/dsl.md, map modifiers), found split, which none of them does",
        ),
        (
            "err_map_opposite_overlap",
            K::Unsatisfiable,
            "10:58",
            "expected lateral_overlap: never for two routes driven in opposite directions",
        ),
        (
            "err_opposite_ahead",
            K::Unsatisfiable,
            "18:37",
            "expected `ahead_of:` of position(…) to name an actor driving in the direction of `ego` (in +s), found `npc`, which drives against s",
        ),
        // §7.3.9: a scenario's behavior is its `do`; invoked without one (and without an
        // actor), there is nothing to run.
        (
            "err_scenario_no_do",
            K::Invocation,
            "7:8",
            "expected an actor before `inner`, or a scenario with a `do`, found neither",
        ),
        // An action the program declares without a `do` and without a §8.8 action among its
        // ancestors specifies no behavior (§7.3.9).
        (
            "declared/err_action_no_body",
            K::Invocation,
            "13:9",
            "expected a `do` in `nothing`, an action the program declares without one",
        ),
        // A `call` of a method `is undefined`: nothing to call.
        (
            "err_on_call",
            K::Call,
            "8:14",
            "expected a method with an implementation in `call`",
        ),
        // A list field nothing constrains has no routes the planner can compute.
        (
            "err_create_route_free_list",
            K::Value,
            "8:34",
            "expected a list of odr points and routes ([m.create_odr_point(…), …]) in create_route(…), found another expression",
        ),
    ] {
        let e = match crate::support::lower_at(
            &format!("tests/scenarios/{name}.osc"),
            "tests/roads/straight.xodr",
            0,
            None,
        ) {
            Ok(_) => panic!("{name} planned"),
            Err(e) => e,
        };
        let message = e.to_string();
        assert_eq!(e.kind(), &kind, "{name}: {message}");
        assert!(
            message.contains(text) && message.ends_with(&format!("{name}.osc:{place}")),
            "{name}: {message}"
        );
    }
}
