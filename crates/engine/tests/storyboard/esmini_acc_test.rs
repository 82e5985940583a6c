//! The storyboard of esmini's `acc-test.xosc` against esmini 3.6.0's reference log
//! (`reference/esmini/acc-test.events.txt`, dt = 0.05 s): an Act on `SimulationTime > 0`
//! (edge none), Events on `SimulationTime > T` with rising edges, two Events of the same name in
//! one Maneuver, priority overwrite, and a stop trigger on an Event's endTransition (rising,
//! delay 12 s).
//!
//! Only the action durations come from the reference. One difference is expected and asserted:
//! at 20.050 s TargetBrake2Event (priority overwrite) starts while TargetAccelerateEvent of the
//! same Maneuver still runs (its action reports the end of its 3 s only in that step's completion
//! stage, after the triggers). The standard: "A terminated Event moves to completeState with
//! stopTransition" (OpenSCENARIO 1.3 §8.4.2.2); esmini logs the terminated Event and its action
//! with endTransition.

use crate::storyboard_support;

use engine::storyboard::{ConditionEdge, StoryDesc, StoryboardDesc, TriggerDesc};
use storyboard_support::*;

const DT: f64 = 0.05;

/// A trigger of condition `id` with `edge`, `delay`.
fn on(id: u32, edge: ConditionEdge, delay: f64) -> Option<TriggerDesc> {
    Some(TriggerDesc::single(cond(id, edge, delay)))
}

fn description() -> StoryboardDesc {
    let rising = |id| on(id, ConditionEdge::Rising, 0.0);
    let lane_changes = named_group(
        "CutInAndBrakeSequence",
        "LaneChangeManeuvers",
        vec![
            override_event("LaneChange1Event", rising(2), "LaneChange1Action", 2),
            override_event("LaneChange2Event", rising(3), "LaneChange2Action", 3),
            override_event("TargetBrakeEvent", rising(4), "TargetBrakeAction", 4),
            override_event(
                "TargetAccelerateEvent",
                rising(5),
                "TargetAccelerateAction",
                5,
            ),
            override_event("TargetBrake2Event", rising(6), "TargetBrake2Action", 6),
        ],
    );
    let ego_speed = named_group(
        "EgoSpeedChange",
        "EgoSpeedManeuver",
        vec![
            override_event("EgoSpeedEvent", rising(7), "EgoSpeedAction", 7),
            override_event("EgoSpeedEvent", rising(8), "EgoSpeedAction", 8),
        ],
    );
    StoryboardDesc {
        name: "storyBoard".to_owned(),
        init_actions: vec![
            named_action("Init Ego TeleportAction", 91),
            named_action("Init Ego LongitudinalAction", 92),
            named_action("Init Target TeleportAction", 93),
            named_action("Init Target LongitudinalAction", 94),
        ],
        stories: vec![StoryDesc {
            name: "CutInAndBrakeStory".to_owned(),
            acts: vec![named_act(
                "CutInAndBrakeAct",
                on(1, ConditionEdge::None, 0.0),
                vec![lane_changes, ego_speed],
            )],
        }],
        stop_trigger: on(9, ConditionEdge::Rising, 12.0),
    }
}

#[test]
fn acc_test_transitions_match_esmini_but_for_the_override_at_20_050() {
    let mut sb = build(&description());
    let mut conditions = ScriptedConditions::default();
    conditions.dt = DT;
    // SimulationTimeCondition rule greaterThan, value T s: true at steps k > T / 0.05.
    for (id, seconds) in [
        (1, 0),
        (2, 5),
        (3, 7),
        (4, 11),
        (5, 17),
        (6, 20),
        (7, 2),
        (8, 10),
    ] {
        conditions.set(id, move |k| k > seconds * 20);
    }
    conditions.element_state(9, "event", "TargetBrake2Event", "endTransition");
    let mut actions = ScriptedActions::default();
    // Durations in steps of 0.05 s, from the reference; all Init actions are instantaneous.
    actions
        .set(2, 29) // 5.05 → 6.50
        .set(3, 27) // 7.05 → 8.40
        .set(4, 41) // 11.05 → 13.10
        .set(5, 60) // 17.05 → 20.05
        .set(6, 24); // 20.05 → 21.25
    let log = run_dt(&mut sb, 700, DT, &mut conditions, &mut actions);
    assert!(sb.is_complete());

    let reference = esmini_events("acc-test");
    let expected = reference.lines().map(|line| {
        if line.starts_with("20.050 TargetAccelerate") {
            line.replace("endTransition", "stopTransition")
        } else {
            line.to_owned()
        }
    });
    let expected: Vec<String> = expected.collect();
    let ours = lines(&log);
    assert_eq!(
        by_time(ours.iter().map(String::as_str)),
        by_time(expected.iter().map(String::as_str))
    );
}
