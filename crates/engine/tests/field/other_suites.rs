//! Class 8 — files that other engines' own test suites run, reduced to what stopped oscsim.
//! Each case follows the OpenSCENARIO 1.3 text; where it is silent the choice is named.
//!
//! * An empty `<Action name="…"/>`: the XSD's `Action` requires one of GlobalAction,
//!   UserDefinedAction, PrivateAction; nothing else in the standard depends on it, so it is
//!   read with a warning (at its file:line:col) as an action that does nothing and ends at
//!   once, like any instantaneous action.
//! * `FollowTrajectoryAction/@initialDistanceOffset`: the XSD bounds it by the trajectory's arc
//!   length; one past the end by no more than rounding (1 cm, or 10⁻⁴ of the length) means the
//!   end.
//! * LateralDistanceAction in the entity frame (§7.7.2.2, "the actor's local coordinate
//!   system") needs no lane: an actor off the road moves along its own y axis.
//! * Lateral distance in road coordinates between entities on linked roads (§6.4): t is
//!   carried across the link (`domain::space_gap`).
//! * AddEntityAction relative to the entity being added after a DeleteEntityAction: resolved
//!   with the entity where it left (the standard gives a deleted entity no position).
//! * RelativeLanePosition whose target lane ends at its s: a lane is defined on its lane
//!   section's closed interval (OpenDRIVE 1.8 §11.3), so it has a position at its end.

use std::f64::consts::PI;

use engine::output::EventRecord;
use engine::storyboard::Transition;

use crate::support::{file, load, run, transitions};

/// Positions are computed in closed form on straight roads; round-off only.
const POS_TOL: f64 = 1e-6;

fn errors(events: &[EventRecord]) -> Vec<String> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Error {
                element, message, ..
            } => Some(format!("{element}: {message}")),
            _ => None,
        })
        .collect()
}

#[test]
fn an_empty_action_is_a_no_op_with_a_warning() {
    let scenario = scenario::Scenario::load(&file("empty_action.xosc")).expect("loads");
    let warnings: Vec<String> = scenario.warnings.iter().map(|w| w.to_string()).collect();
    // `<Action name="Nothing"/>` is written at line 40, column 15.
    assert!(
        warnings.iter().any(|w| w.starts_with(
            "Action 'Nothing' has none of GlobalAction, UserDefinedAction, PrivateAction; \
             it is read as an action that does nothing at "
        ) && w.ends_with("empty_action.xosc:40:15")),
        "{warnings:?}"
    );
    let (_, _, events) = run("empty_action.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    // Both Events start at t = 1 s; the empty action starts and ends as the instantaneous
    // VariableAction beside it does: in the same steps.
    for transition in [Transition::Start, Transition::End] {
        let nothing = transitions(&events, "Nothing", transition);
        let set = transitions(&events, "SetDone", transition);
        assert_eq!(nothing.len(), 1, "{transition:?} {nothing:?}");
        assert_eq!(nothing, set, "{transition:?}");
        assert!(
            (nothing[0] - 1.0).abs() < 0.051,
            "{transition:?} {nothing:?}"
        );
    }
}

#[test]
fn an_initial_distance_offset_equal_to_the_length_up_to_rounding_starts_at_the_end() {
    // The Polyline runs from x = 10 to x = 99.99868: 89.99868 m. Offset 90 exceeds it by
    // 1.32 mm < 1 cm: the actor starts at the end, the action ends there, and Ego drives on
    // at 10 m/s from x = 99.99868 (module doc of actions/follow_trajectory.rs).
    let (_, rows, events) = run("trajectory_offset.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    let follow_start = transitions(&events, "FollowIt", Transition::Start);
    let follow_end = transitions(&events, "FollowIt", Transition::End);
    assert_eq!(follow_start.len(), 1);
    assert_eq!(follow_end.len(), 1);
    // Started and ended in the step from t = 1 s (logged at its start, 1 s): the actor is put
    // at the end at the step's start and the default controller drives it on over the step,
    // so the frame of 1.05 s shows x = 99.99868 + 10 · 0.05 = 100.49868; at the stop time
    // 3 s, x = 99.99868 + 10 · 2 = 119.99868 (before: x = 10 + 10 · 3 = 40, the action
    // refused).
    assert!((follow_start[0] - 1.0).abs() < 1e-9, "{follow_start:?}");
    let after = rows.at("Ego", 1.05);
    assert!((after.x - 100.49868).abs() < POS_TOL, "{after:?}");
    assert!((after.y + 1.535).abs() < POS_TOL, "{after:?}");
    let end = rows.at("Ego", 3.0);
    assert!((end.x - 119.99868).abs() < POS_TOL, "{end:?}");

    // 90.5 exceeds it by 0.50132 m: out of range, the action stops with the error at its
    // place (line 40, column 15) and Ego stays on its lane: x = 10 + 10 · 3 = 40 at 3 s.
    let (_, rows, events) = run("trajectory_offset.xosc", &[("Offset", "90.5")]);
    let errors = errors(&events);
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].starts_with("FollowIt: expected initialDistanceOffset in [0, 89.99868")
            && errors[0].contains("found 90.5 m at ")
            && errors[0].ends_with("trajectory_offset.xosc:40:15"),
        "{errors:?}"
    );
    let end = rows.at("Ego", 3.0);
    assert!((end.x - 40.0).abs() < 1e-6, "{end:?}");
}

#[test]
fn a_lateral_distance_in_the_entity_frame_needs_no_lane() {
    // Drone (60, 30), heading 0, is 31.75 m left of Ego (60, -1.75) in its own frame; kept
    // 20 m left of it: y = -1.75 + 20 = 18.25, x and heading unchanged (both stand still).
    let (_, rows, events) = run("lateral_off_road.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    let end = rows.at("Drone", 3.0);
    assert!((end.y - 18.25).abs() < POS_TOL, "{end:?}");
    assert!((end.x - 60.0).abs() < POS_TOL, "{end:?}");
    assert!(end.h.abs() < POS_TOL, "{end:?}");
    // Reached (|error| ≤ 0.01 m): the non-continuous action ended.
    assert_eq!(
        transitions(&events, "KeepDistance", Transition::End).len(),
        1
    );
}

#[test]
fn a_lateral_distance_in_road_coordinates_reaches_across_linked_roads() {
    // Road 2 continues road 1's reference line (same direction, t unchanged across the
    // link). Both at t = -1.75: 0 m apart across the road; Target moves to 1.5 m left of Ego,
    // t = -0.25, still in lane -1 ([-3.5, 0]): y = -0.25 at x = 95.
    let (_, rows, events) = run("lateral_linked_roads.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    let end = rows.at("Target", 3.0);
    assert!((end.y + 0.25).abs() < 1e-3, "{end:?}");
    assert!((end.x - 95.0).abs() < POS_TOL, "{end:?}");
    assert_eq!(
        transitions(&events, "KeepDistance", Transition::End).len(),
        1
    );
}

#[test]
fn an_entity_added_back_relative_to_itself_starts_from_where_it_left() {
    // Car left at road 2, lane -1, s = 20. dLane 1 (lane 1, centre t = 1.75, driven towards
    // −s on a right-hand road: heading π), ds 5: s = 25, (125, 1.75).
    let (_, rows, events) = run("add_returning.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    assert!(
        rows.0.iter().all(|r| !(r.time > 1.01 && r.time < 1.99)),
        "absent in between"
    );
    let back = rows.at("Car", 3.0);
    assert!((back.x - 125.0).abs() < POS_TOL, "{back:?}");
    assert!((back.y - 1.75).abs() < POS_TOL, "{back:?}");
    assert!((back.h.cos() - PI.cos()).abs() < POS_TOL, "{back:?}");
    // dLane 0: lane -1, s = 25, heading 0: (125, -1.75).
    let (_, rows, _) = run("add_returning.xosc", &[("DLane", "0")]);
    let back = rows.at("Car", 3.0);
    assert!(
        (back.x - 125.0).abs() < POS_TOL && (back.y + 1.75).abs() < POS_TOL,
        "{back:?}"
    );
}

#[test]
fn a_relative_lane_position_is_found_where_its_lane_ends() {
    // Ego at road 1, lane -1, s = 30. dLane -1: lane -2, 3.5 m wide right of lane -1, centre
    // t = -(3.5 + 1.75) = -5.25; ds 20: s = 50, the end of lane -2's section. (50, -5.25).
    let (_, rows, events) = run("relative_lane_end.xosc", &[]);
    assert!(errors(&events).is_empty(), "{:?}", errors(&events));
    let other = rows.at("Other", 0.0);
    assert!((other.x - 50.0).abs() < POS_TOL, "{other:?}");
    assert!((other.y + 5.25).abs() < POS_TOL, "{other:?}");
    assert!(other.h.abs() < POS_TOL, "{other:?}");
    // 1 m further lane -2 no longer exists: still refused.
    let err = load("relative_lane_end.xosc", &[("Ds", "21")])
        .and_then(|mut e| {
            let mut frames = crate::support::Recorder::default();
            let mut events = Vec::new();
            e.run(&mut frames, &mut events).map_err(|e| e.to_string())?;
            Ok(errors(&events))
        })
        .unwrap_or_else(|e| vec![e]);
    assert!(
        err.iter().any(|e| e.contains("-2")),
        "lane -2 at s = 51 must be refused: {err:?}"
    );
}
