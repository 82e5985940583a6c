//! The init phase, OpenSCENARIO 1.3 §8.5: Init actions are "handled prior to the execution of
//! the Storyboard"; instantaneous ones "reach the completeState" in the init phase,
//! non-instantaneous ones are "left in runningState" and treated like any other action once the
//! storyboard runs. So Init actions have taken effect before any story trigger is evaluated
//! (pitfall 6 in semantics-pitfalls.md).
//!
//! Steps are k at t = 0.1·k.

use std::cell::RefCell;
use std::rc::Rc;

use crate::storyboard_support;

use engine::storyboard::{ActionDesc, ActionId, ElementState, Priority, StoryboardDesc};
use storyboard_support::*;

#[test]
fn init_actions_complete_before_any_story_trigger_is_evaluated() {
    // I1 is instantaneous (0 steps), I2 takes 3 steps. The Act waits for C1, whose script
    // records the states of I1 and I2 seen by the trigger at each evaluation.
    let desc = StoryboardDesc {
        init_actions: vec![
            ActionDesc {
                name: "I1".to_owned(),
                id: ActionId(11),
            },
            ActionDesc {
                name: "I2".to_owned(),
                id: ActionId(12),
            },
        ],
        ..storyboard(act(
            when(1),
            None,
            group(1, vec![event("E", Priority::Parallel, 1, None, 1)]),
        ))
    };
    let mut sb = build(&desc);
    let Some(i1) = sb.find("I1") else {
        panic!("no I1");
    };
    let Some(i2) = sb.find("I2") else {
        panic!("no I2");
    };
    let seen = Rc::new(RefCell::new(Vec::new()));
    let record = Rc::clone(&seen);
    let mut conditions = ScriptedConditions::default();
    conditions.set_with_view(1, move |k, view| {
        record
            .borrow_mut()
            .push((k, view.state(i1), view.state(i2)));
        false
    });
    let mut actions = ScriptedActions::default();
    actions.set(11, 0).set(12, 3);
    let log = run(&mut sb, 5, &mut conditions, &mut actions);
    assert_eq!(
        lines(&log),
        [
            "0.000 I1 initState -> startTransition -> runningState",
            "0.000 I2 initState -> startTransition -> runningState",
            "0.000 I1 runningState -> endTransition -> completeState",
            "0.000 SB initState -> startTransition -> runningState",
            "0.000 S initState -> startTransition -> runningState",
            "0.300 I2 runningState -> endTransition -> completeState",
        ]
    );
    // At the first evaluation of the story's first trigger (t = 0) the instantaneous Init
    // action is complete and the other one runs.
    assert_eq!(
        seen.borrow()[0],
        (0, ElementState::Complete, ElementState::Running)
    );
    assert!(sb.init_complete());
}

#[test]
fn init_is_running_until_its_last_action_ends() {
    let desc = StoryboardDesc {
        init_actions: vec![ActionDesc {
            name: "I".to_owned(),
            id: ActionId(5),
        }],
        ..storyboard(simple_act())
    };
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    let mut actions = ScriptedActions::default();
    actions.set(5, 2).set(1, 100);
    run(&mut sb, 2, &mut conditions, &mut actions);
    assert!(!sb.init_complete());
    let mut log = Vec::new();
    actions.now = 2;
    if let Err(error) = sb.step(0.2, DT, &mut conditions, &mut actions, &mut log) {
        panic!("{error}");
    }
    assert!(sb.init_complete());
    assert_eq!(
        lines(&log),
        ["0.200 I runningState -> endTransition -> completeState"]
    );
}
