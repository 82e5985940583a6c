//! Stop triggers, OpenSCENARIO 1.3 §7.2.1 (Storyboard stopTrigger "determines the end of the
//! scenario"), §8.4.2 (an Event "transfers to completeState with stopTransition" when "a stop
//! trigger is issued by the enclosing Act or Storyboard") and §8.4.1 (an Action completes "when
//! its execution is stopped"). Stop triggers are evaluated while their element runs; a firing
//! one moves the element and every executing (standby or running) descendant to completeState
//! with stopTransition, parent first.
//!
//! Steps are k at t = 0.1·k.

use crate::storyboard_support;

use engine::storyboard::{ActionDesc, ActionId, Priority, StoryboardDesc};
use storyboard_support::*;

#[test]
fn act_stop_trigger_stops_its_running_and_standby_children() {
    // Act runs from k = 0 with E1 (no trigger, A1 of 100 steps) running and E2 waiting for a
    // trigger that never fires. The Act's stop trigger C9 holds from k = 3.
    let desc = storyboard(act(
        None,
        when(9),
        group(
            1,
            vec![
                event("E1", Priority::Parallel, 1, None, 1),
                event("E2", Priority::Parallel, 1, when(2), 2),
            ],
        ),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(9, |k| k >= 3).set(2, |_| false);
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    let log = run(&mut sb, 6, &mut conditions, &mut actions);
    let at_stop: Vec<String> = lines(&log)
        .into_iter()
        .filter(|line| line.starts_with("0.300"))
        .collect();
    assert_eq!(
        at_stop,
        [
            "0.300 Act runningState -> stopTransition -> completeState",
            "0.300 MG runningState -> stopTransition -> completeState",
            "0.300 M runningState -> stopTransition -> completeState",
            "0.300 E1 runningState -> stopTransition -> completeState",
            "0.300 A1 runningState -> stopTransition -> completeState",
            "0.300 E2 standbyState -> stopTransition -> completeState",
            // The Story's only Act is complete: the Story ends regularly.
            "0.300 S runningState -> endTransition -> completeState",
        ]
    );
    assert_eq!(actions.calls, ["start 1 @0", "stop 1 @3"]);
    // Nothing happens after the stop; the storyboard itself keeps running.
    assert!(log.iter().all(|r| step_of(r.time) <= 3));
    assert!(!sb.is_complete());
}

#[test]
fn act_stop_trigger_is_evaluated_only_while_the_act_runs() {
    // Act starts on C1 (k ≥ 5) in the start stage of step 5, after the stop stage; its stop
    // trigger C9 (always true) is first evaluated at k = 6 and stops it then.
    let desc = storyboard(act(
        when(1),
        when(9),
        group(1, vec![event("E", Priority::Parallel, 1, None, 1)]),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 5).set(9, |_| true);
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    let log = run(&mut sb, 8, &mut conditions, &mut actions);
    assert_eq!(
        lines_of(&log, "Act"),
        [
            "0.500 Act standbyState -> startTransition -> runningState",
            "0.600 Act runningState -> stopTransition -> completeState",
        ]
    );
    let stop_asked = conditions.asked_steps(9);
    assert_eq!(stop_asked, [6]);
}

#[test]
fn storyboard_stop_trigger_stops_everything_and_ends_the_run() {
    // Init action I (id 7) takes 10 steps; E1's action 100 steps. The storyboard's stop
    // trigger C9 holds from k = 4: the storyboard, the running Init action and the whole story
    // stop at t = 0.4; later steps do nothing.
    let desc = StoryboardDesc {
        init_actions: vec![ActionDesc {
            name: "I".to_owned(),
            id: ActionId(7),
        }],
        stop_trigger: when(9),
        ..storyboard(act(
            None,
            None,
            group(1, vec![event("E1", Priority::Parallel, 1, None, 1)]),
        ))
    };
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(9, |k| k >= 4);
    let mut actions = ScriptedActions::default();
    actions.set(7, 10).set(1, 100);
    let log = run(&mut sb, 8, &mut conditions, &mut actions);
    let at_stop: Vec<String> = lines(&log)
        .into_iter()
        .filter(|line| !line.starts_with("0.000"))
        .collect();
    assert_eq!(
        at_stop,
        [
            "0.400 SB runningState -> stopTransition -> completeState",
            "0.400 I runningState -> stopTransition -> completeState",
            "0.400 S runningState -> stopTransition -> completeState",
            "0.400 Act runningState -> stopTransition -> completeState",
            "0.400 MG runningState -> stopTransition -> completeState",
            "0.400 M runningState -> stopTransition -> completeState",
            "0.400 E1 runningState -> stopTransition -> completeState",
            "0.400 A1 runningState -> stopTransition -> completeState",
        ]
    );
    assert_eq!(
        actions.calls,
        ["start 7 @0", "start 1 @0", "stop 7 @4", "stop 1 @4"]
    );
    assert!(sb.is_complete());
    // The stop trigger was evaluated from the storyboard's start until it fired, not after.
    let stop_asked: Vec<i64> = conditions.asked.iter().map(|&(_, k)| k).collect();
    assert_eq!(stop_asked, [0, 1, 2, 3, 4]);
}
