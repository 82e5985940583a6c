//! The storyboard of esmini's `follow_reference.xosc` against esmini 3.6.0's reference log
//! (`reference/esmini/follow_reference.events.txt`, dt = 0.05 s): a chain of Events and Acts
//! started by StoryboardElementStateConditions on endTransitions with delays of 2–4 s, and a
//! storyboard stop trigger on the Story's end with a delay of 10 s.
//!
//! Only the action durations come from the reference (they are the runtime's business: a lane
//! change of 1.95 s, speed changes of 1.1 s and 2.4 s, the Init speed action of 2.75 s). Every
//! start and stop time follows from the storyboard's rules: edges, delay as a shift, the order of
//! stages (an Event's end is seen by triggers from the next step, hence esmini's 9.050 = 5.000 +
//! 0.050 + 4), and children handled in their parent's step.

use crate::storyboard_support;

use engine::storyboard::{ConditionEdge, StoryDesc, StoryboardDesc, TriggerDesc};
use storyboard_support::*;

const DT: f64 = 0.05;

/// A trigger of one condition `id` (edge none) with `delay`.
fn after(id: u32, delay: f64) -> Option<TriggerDesc> {
    Some(TriggerDesc::single(cond(id, ConditionEdge::None, delay)))
}

fn description() -> StoryboardDesc {
    let act1 = named_group(
        "ManeuverGroup1",
        "Maneuver1",
        vec![
            override_event("Event1", after(11, 2.0), "LaneChangeAction1", 11),
            override_event("Event2", after(12, 4.0), "LaneChangeAction2", 12),
            override_event("Event3", after(13, 2.0), "LaneChangeAction3", 13),
            override_event("Event4", after(14, 2.0), "LaneChangeAction4", 14),
        ],
    );
    let act2 = named_group(
        "ManeuverGroup3",
        "ManeuverSpeedChanges",
        vec![
            override_event("EventSpeedChange1", None, "SpeedAction1", 21),
            override_event("EventSpeedChange2", after(21, 2.0), "SpeedAction2", 22),
        ],
    );
    StoryboardDesc {
        name: "storyBoard".to_owned(),
        init_actions: vec![
            named_action("Init Ego TeleportAction", 1),
            named_action("Init Ego LongitudinalAction", 2),
        ],
        stories: vec![StoryDesc {
            name: "Story".to_owned(),
            acts: vec![
                named_act("Act1", after(10, 3.0), vec![act1]),
                named_act("Act2", after(20, 2.0), vec![act2]),
            ],
        }],
        stop_trigger: after(30, 10.0),
    }
}

#[test]
fn follow_reference_transitions_match_esmini() {
    let mut sb = build(&description());
    let mut conditions = ScriptedConditions::default();
    conditions.dt = DT;
    // SimulationTimeCondition value 0 rule greaterOrEqual.
    for id in [10, 11] {
        conditions.set(id, |k| k as f64 * DT >= 0.0);
    }
    conditions.element_state(12, "event", "Event1", "endTransition");
    conditions.element_state(13, "event", "Event2", "endTransition");
    conditions.element_state(14, "event", "Event3", "endTransition");
    conditions.element_state(20, "act", "Act1", "endTransition");
    conditions.element_state(21, "event", "EventSpeedChange1", "endTransition");
    conditions.element_state(30, "story", "Story", "endTransition");
    let mut actions = ScriptedActions::default();
    // Durations in steps of 0.05 s, from the reference.
    actions
        .set(1, 0)
        .set(2, 55) // 2.75 s
        .set(11, 0)
        .set(12, 39) // 1.95 s
        .set(13, 39)
        .set(14, 39)
        .set(21, 22) // 1.1 s
        .set(22, 48); // 2.4 s
    let log = run_dt(&mut sb, 800, DT, &mut conditions, &mut actions);
    assert!(sb.is_complete());
    let ours = lines(&log);
    let reference = esmini_events("follow_reference");
    assert_eq!(
        by_time(ours.iter().map(String::as_str)),
        by_time(reference.lines())
    );
}
