//! OpenSCENARIO 1.3 §7.6 and class `Condition` (`conditionEdge`): each edge on a trigger, and
//! the first-evaluation rule. The OpenSCENARIO 1.0 User Guide: conditions with rising, falling or
//! risingOrFalling edges "return false the first time they are checked by a simulation engine"
//! (pitfall 4 in semantics-pitfalls.md; esmini #29, #111, #134).
//!
//! Each test puts one condition on the start trigger of the Act, which waits from t = 0, and
//! reads the time of the Act's start transition. Steps are k = 0, 1, … at t = 0.1·k.

use crate::storyboard_support;

use engine::storyboard::{ConditionEdge, Priority, TriggerDesc};
use storyboard_support::*;

/// The step at which the Act starts within 20 steps, if it does, with condition C1 given by
/// `raw` and edge `edge`.
fn act_start_step(edge: ConditionEdge, raw: impl Fn(i64) -> bool + 'static) -> Option<i64> {
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, raw);
    storyboard_support::act_start_step(TriggerDesc::single(cond(1, edge, 0.0)), &mut conditions, 20)
}

#[test]
fn rising_fires_when_false_turns_true() {
    // F at k = 0..2, T from k = 3: rising edge at k = 3.
    assert_eq!(act_start_step(ConditionEdge::Rising, |k| k >= 3), Some(3));
}

#[test]
fn simulation_time_greater_than_zero_rising_fires_at_the_second_step() {
    // "SimulationTime > 0, rising" on an Act: 0 > 0 is false at the first evaluation (t = 0),
    // true at t = 0.1, so the Act starts at 0.1, the first step after 0, as esmini does
    // (corpus README, "Known esmini traits").
    assert_eq!(
        act_start_step(ConditionEdge::Rising, |k| k as f64 * DT > 0.0),
        Some(1)
    );
}

#[test]
fn rising_never_fires_on_a_first_evaluation_that_is_true() {
    // True from the first evaluation on: no false→true change is ever seen.
    assert_eq!(act_start_step(ConditionEdge::Rising, |_| true), None);
    // Once the value falls (k = 5) and rises again (k = 8), it fires.
    assert_eq!(
        act_start_step(ConditionEdge::Rising, |k| !(5..8).contains(&k)),
        Some(8)
    );
}

#[test]
fn falling_fires_when_true_turns_false() {
    assert_eq!(act_start_step(ConditionEdge::Falling, |k| k < 4), Some(4));
}

#[test]
fn falling_never_fires_on_a_first_evaluation_that_is_false() {
    assert_eq!(act_start_step(ConditionEdge::Falling, |_| false), None);
}

#[test]
fn rising_or_falling_fires_on_either_change() {
    assert_eq!(
        act_start_step(ConditionEdge::RisingOrFalling, |k| k >= 2),
        Some(2)
    );
    assert_eq!(
        act_start_step(ConditionEdge::RisingOrFalling, |k| k < 6),
        Some(6)
    );
    // No change, no edge, whatever the first value.
    assert_eq!(
        act_start_step(ConditionEdge::RisingOrFalling, |_| true),
        None
    );
    assert_eq!(
        act_start_step(ConditionEdge::RisingOrFalling, |_| false),
        None
    );
}

#[test]
fn none_fires_whenever_true_including_the_first_evaluation() {
    assert_eq!(act_start_step(ConditionEdge::None, |_| true), Some(0));
    assert_eq!(act_start_step(ConditionEdge::None, |k| k >= 7), Some(7));
    assert_eq!(act_start_step(ConditionEdge::None, |_| false), None);
}

#[test]
fn an_event_back_in_standby_needs_a_new_edge() {
    // Event E (maximumExecutionCount 2) starts on C1 rising; its action takes 1 step.
    // C1 rises at k = 1 and stays true: E runs at k = 1, ends at k = 2 back to standby, where
    // its trigger starts a new series (first evaluation false), so it waits until C1 falls
    // (k = 6) and rises again (k = 8).
    let trigger = Some(TriggerDesc::single(cond(1, ConditionEdge::Rising, 0.0)));
    let desc = storyboard(act(
        None,
        None,
        group(1, vec![event("E", Priority::Parallel, 2, trigger, 1)]),
    ));
    let mut sb = build(&desc);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 1 && !(6..8).contains(&k));
    let mut actions = ScriptedActions::default();
    actions.set(1, 1);
    let log = run(&mut sb, 12, &mut conditions, &mut actions);
    assert_eq!(
        lines_of(&log, "E"),
        [
            "0.100 E standbyState -> startTransition -> runningState",
            "0.200 E runningState -> endTransition -> standbyState",
            "0.800 E standbyState -> startTransition -> runningState",
            "0.900 E runningState -> endTransition -> completeState",
        ]
    );
}
