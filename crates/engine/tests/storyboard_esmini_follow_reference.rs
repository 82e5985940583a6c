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

mod storyboard_support;

use std::collections::BTreeMap;

use engine::storyboard::{
    ActDesc, ActionDesc, ActionId, ConditionEdge, ElementKind, EventDesc, ManeuverDesc,
    ManeuverGroupDesc, Priority, StoryDesc, StoryboardDesc, Transition, TriggerDesc,
};
use storyboard_support::*;

const DT: f64 = 0.05;

fn action(name: &str, id: u32) -> ActionDesc {
    ActionDesc {
        name: name.to_owned(),
        id: ActionId(id),
    }
}

fn event(name: &str, trigger: Option<TriggerDesc>, action_name: &str, id: u32) -> EventDesc {
    EventDesc {
        name: name.to_owned(),
        priority: Priority::Override,
        maximum_execution_count: 1,
        start_trigger: trigger,
        actions: vec![action(action_name, id)],
    }
}

/// A trigger of one condition `id` (edge none) with `delay`.
fn after(id: u32, delay: f64) -> Option<TriggerDesc> {
    Some(TriggerDesc::single(cond(id, ConditionEdge::None, delay)))
}

fn act(
    name: &str,
    trigger: Option<TriggerDesc>,
    group: &str,
    maneuver: &str,
    events: Vec<EventDesc>,
) -> ActDesc {
    ActDesc {
        name: name.to_owned(),
        start_trigger: trigger,
        stop_trigger: None,
        maneuver_groups: vec![ManeuverGroupDesc {
            name: group.to_owned(),
            maximum_execution_count: 1,
            maneuvers: vec![ManeuverDesc {
                name: maneuver.to_owned(),
                events,
            }],
        }],
    }
}

fn description() -> StoryboardDesc {
    StoryboardDesc {
        name: "storyBoard".to_owned(),
        init_actions: vec![
            action("Init Ego TeleportAction", 1),
            action("Init Ego LongitudinalAction", 2),
        ],
        stories: vec![StoryDesc {
            name: "Story".to_owned(),
            acts: vec![
                act(
                    "Act1",
                    after(10, 3.0),
                    "ManeuverGroup1",
                    "Maneuver1",
                    vec![
                        event("Event1", after(11, 2.0), "LaneChangeAction1", 11),
                        event("Event2", after(12, 4.0), "LaneChangeAction2", 12),
                        event("Event3", after(13, 2.0), "LaneChangeAction3", 13),
                        event("Event4", after(14, 2.0), "LaneChangeAction4", 14),
                    ],
                ),
                act(
                    "Act2",
                    after(20, 2.0),
                    "ManeuverGroup3",
                    "ManeuverSpeedChanges",
                    vec![
                        event("EventSpeedChange1", None, "SpeedAction1", 21),
                        event("EventSpeedChange2", after(21, 2.0), "SpeedAction2", 22),
                    ],
                ),
            ],
        }],
        stop_trigger: after(30, 10.0),
    }
}

/// StoryboardElementStateCondition: `kind` `name` had an endTransition.
fn ended(conditions: &mut ScriptedConditions, id: u32, kind: ElementKind, name: &'static str) {
    conditions.set_with_view(id, move |_, view| match view.find_kind(kind, name) {
        Some(element) => view.transition_happened(element, Transition::End),
        None => panic!("no {kind} {name}"),
    });
}

/// Lines grouped by their time stamp, each group sorted: esmini orders transitions within a
/// step differently (e.g. it ends Init actions after the storyboard starts).
fn by_time<'a>(lines: impl Iterator<Item = &'a str>) -> BTreeMap<String, Vec<String>> {
    let mut groups: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for line in lines {
        let time = line.split(' ').next().unwrap_or("").to_owned();
        groups.entry(time).or_default().push(line.to_owned());
    }
    for group in groups.values_mut() {
        group.sort();
    }
    groups
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
    ended(&mut conditions, 12, ElementKind::Event, "Event1");
    ended(&mut conditions, 13, ElementKind::Event, "Event2");
    ended(&mut conditions, 14, ElementKind::Event, "Event3");
    ended(&mut conditions, 20, ElementKind::Act, "Act1");
    ended(&mut conditions, 21, ElementKind::Event, "EventSpeedChange1");
    ended(&mut conditions, 30, ElementKind::Story, "Story");
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
