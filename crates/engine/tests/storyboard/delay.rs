//! OpenSCENARIO 1.3 class `Condition`, attribute `delay`: "time elapsed after the edge
//! condition is verified, until the condition returns true to the scenario". oscsim applies the
//! edge first and shifts its output by `delay` (pitfall 5 in semantics-pitfalls.md; esmini
//! #202, #237, #371). A shift differs from a timer started once: the delayed condition is true
//! exactly as long as the original was, `delay` later.
//!
//! The Act's start trigger is one condition group; steps are k at t = 0.1·k, delay 0.5 s = 5
//! steps.

use crate::storyboard_support;

use engine::storyboard::{ConditionEdge, TriggerDesc};
use storyboard_support::*;

/// C1 (edge none, delay 0.5 s) AND C2 (edge none, no delay), scripted by step.
fn delayed_and_undelayed(
    c1: impl Fn(i64) -> bool + 'static,
    c2: impl Fn(i64) -> bool + 'static,
) -> Option<i64> {
    let trigger = TriggerDesc::all_of(vec![
        cond(1, ConditionEdge::None, 0.5),
        cond(2, ConditionEdge::None, 0.0),
    ]);
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, c1).set(2, c2);
    act_start_step(trigger, &mut conditions, 30)
}

#[test]
fn and_of_delayed_and_undelayed_uses_the_shifted_signal() {
    // C1 true at k = 2, 3 only → delayed C1 true at k = 7, 8 only.
    // C2 true from k = 10: the two are never true together, so the Act never starts.
    // A timer started at k = 2 and latched after 0.5 s would be true from k = 7 on and fire at
    // k = 10.
    assert_eq!(
        delayed_and_undelayed(|k| (2..=3).contains(&k), |k| k >= 10),
        None
    );
}

#[test]
fn and_of_delayed_and_undelayed_fires_inside_the_shifted_window() {
    // Same C1; C2 true at k = 8 only, the last step of the shifted window → fires at k = 8.
    assert_eq!(
        delayed_and_undelayed(|k| (2..=3).contains(&k), |k| k == 8),
        Some(8)
    );
    // C2 true at k = 9 only, one step after the window → never.
    assert_eq!(
        delayed_and_undelayed(|k| (2..=3).contains(&k), |k| k == 9),
        None
    );
    // C2 true at k = 3 only, inside the unshifted window → never: the raw C1 does not count.
    assert_eq!(
        delayed_and_undelayed(|k| (2..=3).contains(&k), |k| k == 3),
        None
    );
}

#[test]
fn a_rising_edge_is_reported_delay_seconds_later() {
    // C1 rises at k = 2 (t = 0.2); with delay 0.5 s the condition is true at t = 0.7.
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |k| k >= 2);
    let trigger = TriggerDesc::single(cond(1, ConditionEdge::Rising, 0.5));
    assert_eq!(act_start_step(trigger, &mut conditions, 30), Some(7));
}

#[test]
fn the_edge_is_applied_before_the_delay() {
    // C1 true from the first evaluation on, rising, delay 0.5 s. Edge first: the first
    // evaluation gives false and there is never a false→true change, so the Act never starts.
    // Delaying first would turn the series into F F F F F T T … and see a rising edge at k = 5.
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |_| true);
    let trigger = TriggerDesc::single(cond(1, ConditionEdge::Rising, 0.5));
    assert_eq!(act_start_step(trigger, &mut conditions, 30), None);
}

#[test]
fn with_delay_a_true_condition_reports_false_until_delay_has_passed() {
    // Edge none, always true, delay 0.5 s: false before any sample is 0.5 s old, so the Act
    // starts at t = 0.5.
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |_| true);
    let trigger = TriggerDesc::single(cond(1, ConditionEdge::None, 0.5));
    assert_eq!(act_start_step(trigger, &mut conditions, 30), Some(5));
}
