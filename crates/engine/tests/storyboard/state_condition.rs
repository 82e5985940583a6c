//! What the storyboard answers for StoryboardElementStateCondition (OpenSCENARIO 1.3 class
//! `StoryboardElementStateCondition`, states §8.1, transitions §8.2): an element's current
//! state, found by name, and whether a transition happened — in the step of the transition (if
//! the observing trigger is evaluated after it) and the whole next step.
//!
//! Steps are k at t = 0.1·k.

use std::cell::RefCell;
use std::rc::Rc;

use crate::storyboard_support;

use engine::storyboard::{ElementKind, ElementState, Priority, Transition};
use storyboard_support::*;

#[test]
fn a_transition_is_seen_in_its_step_and_the_next() {
    // E (trigger C1: k ≥ 2) starts at k = 2. Observer O, after E in document order, records
    // per step whether E's startTransition happened: true at k = 2 (same step, E was visited
    // first) and k = 3 (next step), false from k = 4.
    let desc = storyboard(act(
        None,
        None,
        group(
            1,
            vec![
                event("E", Priority::Parallel, 1, when(1), 1),
                event("O", Priority::Parallel, 1, when(2), 2),
            ],
        ),
    ));
    let mut sb = build(&desc);
    let Some(e) = sb.find("E") else {
        panic!("no E");
    };
    let seen = Rc::new(RefCell::new(Vec::new()));
    let record = Rc::clone(&seen);
    let mut conditions = ScriptedConditions::default();
    conditions
        .set(1, |k| k >= 2)
        .set_with_view(2, move |k, view| {
            record.borrow_mut().push((
                k,
                view.transition_happened(e, Transition::Start),
                view.state(e),
            ));
            false
        });
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    run(&mut sb, 6, &mut conditions, &mut actions);
    use ElementState::{Running, Standby};
    assert_eq!(
        *seen.borrow(),
        [
            (0, false, Standby),
            (1, false, Standby),
            (2, true, Running),
            (3, true, Running),
            (4, false, Running),
            (5, false, Running),
        ]
    );
    assert_eq!(
        sb.view().last_transition_step(e, Transition::Start),
        Some(2)
    );
    assert_eq!(sb.view().last_transition_step(e, Transition::End), None);
}

#[test]
fn elements_are_found_by_name_and_kind() {
    // Names may repeat (esmini's acc-test.xosc has two Events "EgoSpeedEvent"): find returns
    // the first in document order, find_all all of them.
    let desc = storyboard(act(
        None,
        None,
        group(
            1,
            vec![
                event("Twin", Priority::Parallel, 1, None, 1),
                event("Twin", Priority::Parallel, 1, None, 2),
            ],
        ),
    ));
    let sb = build(&desc);
    let view = sb.view();
    let twins: Vec<_> = view.find_all("Twin").collect();
    assert_eq!(twins.len(), 2);
    assert_eq!(view.find("Twin"), Some(twins[0]));
    assert!(twins[0] < twins[1]);
    assert_eq!(view.find_kind(ElementKind::Event, "Act"), None);
    let Some(act_id) = view.find_kind(ElementKind::Act, "Act") else {
        panic!("no Act");
    };
    assert_eq!(view.kind(act_id), ElementKind::Act);
    assert_eq!(view.name(act_id), "Act");
    assert_eq!(view.find("nothing"), None);
    // Before the first step every element is in initState.
    assert!(view.ids().all(|id| view.state(id) == ElementState::Init));
    assert_eq!(view.ids().count(), view.len());
    // The tree: Twin → its action; Twin's parent is the Maneuver.
    let Some(maneuver) = view.parent(twins[0]) else {
        panic!("Event without parent");
    };
    assert_eq!(view.kind(maneuver), ElementKind::Maneuver);
    assert_eq!(view.children(maneuver), twins.as_slice());
}
