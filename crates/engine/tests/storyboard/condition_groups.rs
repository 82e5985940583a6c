//! OpenSCENARIO 1.3 §7.6.1: "A conditionGroup is evaluated to true when all its associated
//! conditions are evaluated to true"; "A trigger evaluates to true when at least one of its
//! condition groups evaluates to true". Here on an Act's start trigger
//! T = (C1 ∧ C2) ∨ C3, all edges none, steps k at t = 0.1·k.

use crate::storyboard_support;

use engine::storyboard::{ConditionEdge, ConditionGroupDesc, TriggerDesc};
use storyboard_support::*;

fn trigger() -> TriggerDesc {
    let none = |id| cond(id, ConditionEdge::None, 0.0);
    TriggerDesc {
        condition_groups: vec![
            ConditionGroupDesc {
                conditions: vec![none(1), none(2)],
            },
            ConditionGroupDesc {
                conditions: vec![none(3)],
            },
        ],
    }
}

/// The step at which the Act starts with C1 true from k ≥ 2, C2 from k ≥ `c2_from`, C3 at
/// `c3_at` only.
fn start(c2_from: i64, c3_at: i64) -> Option<i64> {
    let mut conditions = ScriptedConditions::default();
    conditions
        .set(1, |k| k >= 2)
        .set(2, move |k| k >= c2_from)
        .set(3, move |k| k == c3_at);
    act_start_step(trigger(), &mut conditions, 10)
}

#[test]
fn a_group_needs_all_its_conditions() {
    // C1 from k = 2, C2 from k = 4, no C3: the first group holds from k = 4.
    assert_eq!(start(4, -1), Some(4));
    // C2 from k = 0 but C1 only from k = 2: still k = 2, not earlier.
    assert_eq!(start(0, -1), Some(2));
}

#[test]
fn any_group_fires_the_trigger() {
    // C3 alone at k = 3 fires before the first group holds at k = 4.
    assert_eq!(start(4, 3), Some(3));
    // C3 at k = 6, after the first group fired at k = 4: k = 4.
    assert_eq!(start(4, 6), Some(4));
}
