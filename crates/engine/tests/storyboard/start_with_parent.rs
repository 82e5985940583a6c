//! OpenSCENARIO 1.3 §8.3: "When a storyboard element enters runningState, its direct child
//! elements are set into standbyState if the child element defines a start trigger, runningState
//! in all other cases", and §8.3.1: only start triggers, actions and stop triggers take simulation
//! time, so a just-started element's children are handled in the same step.

use crate::storyboard_support;

use engine::storyboard::{ElementKind, Priority, Transition};
use storyboard_support::*;

#[test]
fn children_without_start_trigger_start_with_their_parent() {
    // Story, Act, ManeuverGroup, Maneuver and Event have no start trigger: all start at t = 0
    // with the storyboard. The Event enters standbyState with its Maneuver and, inheriting the
    // Act's (fired) trigger, starts from there in the same step (§8.4.2); the instantaneous action (0 steps) ends in the same step, and the
    // ends propagate up to the Story. The Storyboard itself only ends by its stop trigger
    // (§7.2.1), so it stays running.
    let desc = storyboard(simple_act());
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    let mut actions = ScriptedActions::default();
    actions.set(1, 0);
    let log = run(&mut sb, 3, &mut conditions, &mut actions);
    assert_eq!(
        lines(&log),
        [
            "0.000 SB initState -> startTransition -> runningState",
            "0.000 S initState -> startTransition -> runningState",
            "0.000 Act initState -> startTransition -> runningState",
            "0.000 MG initState -> startTransition -> runningState",
            "0.000 M initState -> startTransition -> runningState",
            "0.000 E standbyState -> startTransition -> runningState",
            "0.000 A1 initState -> startTransition -> runningState",
            "0.000 A1 runningState -> endTransition -> completeState",
            "0.000 E runningState -> endTransition -> completeState",
            "0.000 M runningState -> endTransition -> completeState",
            "0.000 MG runningState -> endTransition -> completeState",
            "0.000 Act runningState -> endTransition -> completeState",
            "0.000 S runningState -> endTransition -> completeState",
        ]
    );
    assert!(sb.stories_complete());
    assert!(!sb.is_complete());
    assert_eq!(actions.calls, ["start 1 @0"]);
}

#[test]
fn children_of_a_just_started_act_are_handled_in_the_same_step() {
    // Act starts when C1 (k >= 3) holds. E1 waits for "Act startTransition" (a
    // StoryboardElementStateCondition, C2); E2 has no trigger. Both start at t = 0.3, the Act's
    // step. Actions run 100 steps, so nothing ends.
    let desc = storyboard(act(
        when(1),
        None,
        group(
            1,
            vec![
                event("E1", Priority::Parallel, 1, when(2), 1),
                event("E2", Priority::Parallel, 1, None, 2),
            ],
        ),
    ));
    let mut sb = build(&desc);
    let act_id = sb.view().find_kind(ElementKind::Act, "Act");
    let Some(act_id) = act_id else {
        panic!("no Act in the tree");
    };
    let mut conditions = ScriptedConditions::default();
    conditions
        .set(1, |k| k >= 3)
        .set_with_view(2, move |_, view| {
            view.transition_happened(act_id, Transition::Start)
        });
    let mut actions = ScriptedActions::default();
    actions.set(1, 100).set(2, 100);
    let log = run(&mut sb, 6, &mut conditions, &mut actions);
    let after_start: Vec<String> = lines(&log).split_off(2);
    assert_eq!(
        after_start,
        [
            "0.300 Act standbyState -> startTransition -> runningState",
            "0.300 MG initState -> startTransition -> runningState",
            "0.300 M initState -> startTransition -> runningState",
            "0.300 E1 standbyState -> startTransition -> runningState",
            "0.300 A1 initState -> startTransition -> runningState",
            "0.300 E2 standbyState -> startTransition -> runningState",
            "0.300 A2 initState -> startTransition -> runningState",
        ]
    );
    // Only triggers being evaluated are asked for: the Act's start trigger while the Act waits
    // (steps 0–3), E1's once, in the Act's step.
    assert_eq!(conditions.asked_steps(1), [0, 1, 2, 3]);
    assert_eq!(conditions.asked_steps(2), [3]);
}

#[test]
fn esmini_also_starts_an_event_in_the_step_of_its_act() {
    // esmini 3.6.0's reference log of cut-in.xosc: OverTakerStartSpeedEvent waits for the
    // startTransition of CutInAndBrakeAct and starts in the same step (0.050 s). The test above
    // shows oscsim does the same.
    let text = esmini_events("cut-in");
    let start_time = |element: &str| -> Option<String> {
        text.lines()
            .find(|line| {
                line.split_whitespace().nth(1) == Some(element)
                    && line.contains("standbyState -> startTransition")
            })
            .and_then(|line| line.split_whitespace().next().map(str::to_owned))
    };
    assert_eq!(start_time("CutInAndBrakeAct").as_deref(), Some("0.050"));
    assert_eq!(
        start_time("OverTakerStartSpeedEvent").as_deref(),
        Some("0.050")
    );
}
