//! OpenSCENARIO 1.3 §8.4.2.2 "Event priority" (pitfall 3 in semantics-pitfalls.md):
//! override stops the running Events of the same Maneuver with stopTransition "regardless of
//! the number of executions left"; skip does not move to runningState while another Event of
//! the Maneuver runs and takes a skipTransition, which counts as an execution; parallel starts
//! regardless.
//!
//! Every test has E1 (parallel, count 3, trigger k ≥ 1, action A1 of 100 steps) running from
//! t = 0.1, and E2 with the priority under test and trigger k ≥ 3. Steps are k at t = 0.1·k.

use crate::storyboard_support;

use engine::storyboard::{ElementState, EventDesc, ManeuverDesc, Priority};
use storyboard_support::*;

fn e1() -> EventDesc {
    event("E1", Priority::Parallel, 3, when(1), 1)
}

fn e2(priority: Priority, maximum_execution_count: u32) -> EventDesc {
    event("E2", priority, maximum_execution_count, when(2), 2)
}

/// Runs M = [E1, E2] (plus Maneuver M2 = [E3: parallel, no trigger, action A3 of 100 steps])
/// for 8 steps; returns the log, the action calls and the final states of E1, E2, E3.
fn run_priority(e2: EventDesc, a1_steps: i64) -> (Vec<String>, Vec<String>, [ElementState; 3]) {
    let mut mg = group(1, vec![e1(), e2]);
    mg.maneuvers.push(ManeuverDesc {
        name: "M2".to_owned(),
        events: vec![event("E3", Priority::Parallel, 1, None, 3)],
    });
    let mut sb = build(&storyboard(act(None, None, mg)));
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 1).set(2, |k| k >= 3);
    let mut actions = ScriptedActions::default();
    actions.set(1, a1_steps).set(2, 100).set(3, 100);
    let log = run(&mut sb, 8, &mut conditions, &mut actions);
    let state = |name: &str| match sb.find(name) {
        Some(id) => sb.state(id),
        None => panic!("no {name}"),
    };
    let states = [state("E1"), state("E2"), state("E3")];
    let events: Vec<String> = lines(&log)
        .into_iter()
        .filter(|line| ["E1", "A1", "E2", "A2"].contains(&line.split(' ').nth(1).unwrap_or("")))
        .collect();
    (events, actions.calls, states)
}

#[test]
fn override_stops_the_running_events_of_its_maneuver() {
    let (log, calls, states) = run_priority(e2(Priority::Override, 1), 100);
    assert_eq!(
        log,
        [
            "0.100 E1 standbyState -> startTransition -> runningState",
            "0.100 A1 initState -> startTransition -> runningState",
            // E1 and its action stop before E2 starts; E1 had 2 executions left.
            "0.300 E1 runningState -> stopTransition -> completeState",
            "0.300 A1 runningState -> stopTransition -> completeState",
            "0.300 E2 standbyState -> startTransition -> runningState",
            "0.300 A2 initState -> startTransition -> runningState",
        ]
    );
    assert_eq!(
        calls,
        ["start 3 @0", "start 1 @1", "stop 1 @3", "start 2 @3"]
    );
    // E3, in another Maneuver of the same group, is out of scope and keeps running.
    assert_eq!(
        states,
        [
            ElementState::Complete,
            ElementState::Running,
            ElementState::Running
        ]
    );
}

#[test]
fn skip_takes_a_skip_transition_while_another_event_runs() {
    let (log, calls, states) = run_priority(e2(Priority::Skip, 1), 100);
    assert_eq!(
        log[2..],
        ["0.300 E2 standbyState -> skipTransition -> completeState"]
    );
    assert_eq!(calls, ["start 3 @0", "start 1 @1"]);
    assert_eq!(states[..2], [ElementState::Running, ElementState::Complete]);
}

#[test]
fn skip_counts_as_an_execution_and_returns_to_standby_while_executions_are_left() {
    // Count 2: the skip at k = 3 is execution 1 (back to standby, trigger evaluated again from
    // k = 4); the skip at k = 4 is execution 2 = maximum, into completeState.
    let (log, _, _) = run_priority(e2(Priority::Skip, 2), 100);
    assert_eq!(
        log[2..],
        [
            "0.300 E2 standbyState -> skipTransition -> standbyState",
            "0.400 E2 standbyState -> skipTransition -> completeState",
        ]
    );
}

#[test]
fn skip_starts_when_no_other_event_of_the_maneuver_runs() {
    // E1 (count 1, A1 of 1 step) runs k = 1..2 and is complete at k = 3, when E2 (skip) is
    // triggered: nothing of the Maneuver runs, so E2 starts.
    let mg = group(
        1,
        vec![
            event("E1", Priority::Parallel, 1, when(1), 1),
            e2(Priority::Skip, 1),
        ],
    );
    let mut sb = build(&storyboard(act(None, None, mg)));
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 1).set(2, |k| k >= 3);
    let mut actions = ScriptedActions::default();
    actions.set(1, 1).set(2, 100);
    let log = run(&mut sb, 6, &mut conditions, &mut actions);
    assert_eq!(
        lines_of(&log, "E1"),
        [
            "0.100 E1 standbyState -> startTransition -> runningState",
            "0.200 E1 runningState -> endTransition -> completeState",
        ]
    );
    assert_eq!(
        lines_of(&log, "E2"),
        ["0.300 E2 standbyState -> startTransition -> runningState"]
    );
}

#[test]
fn parallel_starts_regardless() {
    let (log, calls, states) = run_priority(e2(Priority::Parallel, 1), 100);
    assert_eq!(
        log[2..],
        [
            "0.300 E2 standbyState -> startTransition -> runningState",
            "0.300 A2 initState -> startTransition -> runningState",
        ]
    );
    assert_eq!(calls, ["start 3 @0", "start 1 @1", "start 2 @3"]);
    assert_eq!(states, [ElementState::Running; 3]);
}

#[test]
fn events_without_trigger_meet_the_priority_rule_in_document_order() {
    // Both Events inherit the Act's (fired) trigger and start with their Maneuver at t = 0, in
    // document order: F2 (override) finds F1 running and stops it in the same step.
    let mg = group(
        1,
        vec![
            event("F1", Priority::Parallel, 1, None, 1),
            event("F2", Priority::Override, 1, None, 2),
        ],
    );
    let mut sb = build(&storyboard(act(None, None, mg)));
    let mut conditions = ScriptedConditions::default();
    let mut actions = ScriptedActions::default();
    actions.set(1, 100).set(2, 100);
    let log = run(&mut sb, 2, &mut conditions, &mut actions);
    let events: Vec<String> = lines(&log).split_off(5);
    assert_eq!(
        events,
        [
            "0.000 F1 standbyState -> startTransition -> runningState",
            "0.000 A1 initState -> startTransition -> runningState",
            "0.000 F1 runningState -> stopTransition -> completeState",
            "0.000 A1 runningState -> stopTransition -> completeState",
            "0.000 F2 standbyState -> startTransition -> runningState",
            "0.000 A2 initState -> startTransition -> runningState",
        ]
    );
    assert_eq!(actions.calls, ["start 1 @0", "stop 1 @0", "start 2 @0"]);
}
