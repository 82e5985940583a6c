//! OpenSCENARIO 1.3 §8.4.2.1 "Execution count": executions are start plus skip transitions; an
//! Event ending with executions left returns to standbyState, else completes; a standby Event
//! whose executions are used up completes with skipTransition. §8.3.2: "Each ManeuverGroup is
//! executed as often as defined in its maximumExecutionCount."
//!
//! Steps are k at t = 0.1·k.

use crate::storyboard_support;

use engine::storyboard::{ElementState, Priority};
use storyboard_support::*;

#[test]
fn event_with_maximum_execution_count_3_runs_three_start_end_cycles() {
    // E: trigger C1 (edge none, always true), action A1 takes 2 steps.
    // Execution 1 starts at k = 0 and ends at k = 2 (standby, 1 < 3); its trigger is evaluated
    // again from the next step, k = 3, where it starts execution 2 (ends k = 5); execution 3
    // starts k = 6 and ends k = 8 into completeState (3 = 3), and the Maneuver ends with it.
    let desc = storyboard(act(
        None,
        None,
        group(1, vec![event("E", Priority::Parallel, 3, when(1), 1)]),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |_| true);
    let mut actions = ScriptedActions::default();
    actions.set(1, 2);
    let log = run(&mut sb, 12, &mut conditions, &mut actions);
    assert_eq!(
        lines_of(&log, "E"),
        [
            "0.000 E standbyState -> startTransition -> runningState",
            "0.200 E runningState -> endTransition -> standbyState",
            "0.300 E standbyState -> startTransition -> runningState",
            "0.500 E runningState -> endTransition -> standbyState",
            "0.600 E standbyState -> startTransition -> runningState",
            "0.800 E runningState -> endTransition -> completeState",
        ]
    );
    // Each execution restarts the action from initState.
    assert_eq!(
        lines_of(&log, "A1")[2],
        "0.300 A1 initState -> startTransition -> runningState"
    );
    assert_eq!(actions.calls, ["start 1 @0", "start 1 @3", "start 1 @6"]);
    assert_eq!(
        lines_of(&log, "M"),
        [
            "0.000 M initState -> startTransition -> runningState",
            "0.800 M runningState -> endTransition -> completeState",
        ]
    );
    let Some(e) = sb.find("E") else {
        panic!("no E");
    };
    assert_eq!(sb.view().executions(e), 3);
}

#[test]
fn standby_event_with_executions_used_up_completes_by_skip() {
    // maximumExecutionCount 0 (the XSD's UnsignedInt allows it): in standby with 0 = 0
    // executions, the Event completes with skipTransition at once; its trigger is never asked
    // and its action never starts. The skip counts as an execution (§8.4.2.1).
    let desc = storyboard(act(
        None,
        None,
        group(1, vec![event("E", Priority::Parallel, 0, when(1), 1)]),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |_| true);
    let mut actions = ScriptedActions::default();
    let log = run(&mut sb, 3, &mut conditions, &mut actions);
    assert_eq!(
        lines_of(&log, "E"),
        ["0.000 E standbyState -> skipTransition -> completeState"]
    );
    assert_eq!(
        lines_of(&log, "M"),
        [
            "0.000 M initState -> startTransition -> runningState",
            "0.000 M runningState -> endTransition -> completeState",
        ]
    );
    assert!(conditions.asked.is_empty());
    assert!(actions.calls.is_empty());
}

#[test]
fn maneuver_group_with_maximum_execution_count_2_runs_twice() {
    // MG (count 2) → M → E (no trigger, count 1) → A1 (1 step).
    // Execution 1: k = 0 start, k = 1 A1, E, M end; MG ends into standby (1 < 2). Its start
    // trigger is the Act's, which has fired, so it starts again at the next step, k = 2, with a
    // fresh subtree (M, E and A1 from initState); at k = 3 everything ends and the MG completes,
    // then the Act and the Story.
    let desc = storyboard(act(
        None,
        None,
        group(2, vec![event("E", Priority::Parallel, 1, None, 1)]),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    let mut actions = ScriptedActions::default();
    actions.set(1, 1);
    let log = run(&mut sb, 6, &mut conditions, &mut actions);
    let after_first_start: Vec<String> = lines(&log).split_off(7);
    assert_eq!(
        after_first_start,
        [
            "0.100 A1 runningState -> endTransition -> completeState",
            "0.100 E runningState -> endTransition -> completeState",
            "0.100 M runningState -> endTransition -> completeState",
            "0.100 MG runningState -> endTransition -> standbyState",
            "0.200 MG standbyState -> startTransition -> runningState",
            "0.200 M initState -> startTransition -> runningState",
            "0.200 E standbyState -> startTransition -> runningState",
            "0.200 A1 initState -> startTransition -> runningState",
            "0.300 A1 runningState -> endTransition -> completeState",
            "0.300 E runningState -> endTransition -> completeState",
            "0.300 M runningState -> endTransition -> completeState",
            "0.300 MG runningState -> endTransition -> completeState",
            "0.300 Act runningState -> endTransition -> completeState",
            "0.300 S runningState -> endTransition -> completeState",
        ]
    );
    let Some(mg) = sb.find("MG") else {
        panic!("no MG");
    };
    assert_eq!(sb.state(mg), ElementState::Complete);
    assert_eq!(sb.view().executions(mg), 2);
}
