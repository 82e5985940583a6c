//! The event log: one record per state transition (OpenSCENARIO 1.3 §8.2) with the standard's
//! literal state and transition names. JSON objects for `--events FILE.jsonl`; text lines in
//! the format of esmini's reference logs (corpus `reference/esmini/*.events.txt`).

use crate::storyboard_support;

use engine::storyboard::{ElementKind, ElementState, Priority, Transition, TransitionRecord};
use storyboard_support::*;

/// The records of a run where Event `CutInEvent` starts on C1 at t = 0.3.
fn cut_in_log() -> Vec<TransitionRecord> {
    let desc = storyboard(act(
        None,
        None,
        group(
            1,
            vec![event("CutInEvent", Priority::Override, 1, when(1), 1)],
        ),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 3);
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    run(&mut sb, 4, &mut conditions, &mut actions)
}

#[test]
fn a_record_serializes_to_the_event_log_object() {
    let log = cut_in_log();
    let Some(record) = log.iter().find(|r| r.name == "CutInEvent") else {
        panic!("CutInEvent did not start");
    };
    assert_eq!(record.kind, ElementKind::Event);
    assert_eq!(
        (record.from, record.transition, record.to),
        (
            ElementState::Standby,
            Transition::Start,
            ElementState::Running
        )
    );
    let json = match serde_json::to_value(record) {
        Ok(json) => json,
        Err(error) => panic!("{error}"),
    };
    // t = 3 · 0.1 in binary floating point.
    assert_eq!(
        json,
        serde_json::json!({
            "time": 3.0 * 0.1,
            "element": "CutInEvent",
            "kind": "event",
            "from": "standbyState",
            "transition": "startTransition",
            "to": "runningState",
        })
    );
}

#[test]
fn a_record_prints_as_an_esmini_reference_line() {
    // The line of esmini 3.6.0's reference log for cut-in.xosc, and ours for the same
    // transition at the same time.
    let reference = esmini_events("cut-in");
    let expected = "6.500 CutInEvent standbyState -> startTransition -> runningState";
    assert!(reference.lines().any(|line| line == expected));
    let log = cut_in_log();
    let Some(record) = log.iter().find(|r| r.name == "CutInEvent") else {
        panic!("CutInEvent did not start");
    };
    let at_esmini_time = TransitionRecord {
        time: 6.5,
        ..record.clone()
    };
    assert_eq!(at_esmini_time.to_string(), expected);
}

#[test]
fn kinds_use_the_xsd_storyboard_element_type_names() {
    let names: Vec<&str> = [
        ElementKind::Story,
        ElementKind::Act,
        ElementKind::ManeuverGroup,
        ElementKind::Maneuver,
        ElementKind::Event,
        ElementKind::Action,
    ]
    .iter()
    .map(|kind| kind.as_str())
    .collect();
    // XSD 1.3 enumeration StoryboardElementType.
    assert_eq!(
        names,
        [
            "story",
            "act",
            "maneuverGroup",
            "maneuver",
            "event",
            "action"
        ]
    );
    for kind in [ElementKind::ManeuverGroup, ElementKind::Storyboard] {
        let json = match serde_json::to_value(kind) {
            Ok(json) => json,
            Err(error) => panic!("{error}"),
        };
        assert_eq!(json, serde_json::json!(kind.as_str()));
    }
}
