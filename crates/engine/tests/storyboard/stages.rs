//! The fixed order of a step's stages (OpenSCENARIO 1.3 §8.3–8.5; pitfall 6 in
//! semantics-pitfalls.md), shown by the per-stage counters of the first step:
//! init phase → stop triggers → start triggers → completions.

use crate::storyboard_support;

use engine::storyboard::{StageCount, StageCounters};
use storyboard_support::*;

#[test]
fn each_stage_counts_its_own_work() {
    // Act: start trigger C1 (always true), stop trigger C2 (never asked: the Act runs only
    // between the start and completion stages of step 0). E has no trigger; A1 is instantaneous.
    let mut act = simple_act();
    act.start_trigger = when(1);
    act.stop_trigger = when(2);
    let mut sb = build(&storyboard(act));
    let mut conditions = ScriptedConditions::default();
    conditions.set(1, |_| true).set(2, |_| false);
    let mut actions = ScriptedActions::default();
    actions.set(1, 0);

    run(&mut sb, 1, &mut conditions, &mut actions);
    assert_eq!(
        sb.counters(),
        StageCounters {
            // SB and S start; the Act waits for its trigger.
            init_phase: StageCount {
                conditions: 0,
                transitions: 2,
            },
            // No Act runs yet.
            stop_triggers: StageCount::default(),
            // C1 asked; Act, MG, M, E, A1 start.
            start_triggers: StageCount {
                conditions: 1,
                transitions: 5,
            },
            // A1, E, M, MG, Act, S end.
            completions: StageCount {
                conditions: 0,
                transitions: 6,
            },
        }
    );

    let mut log = Vec::new();
    actions.now = 1;
    if let Err(error) = sb.step(DT, DT, &mut conditions, &mut actions, &mut log) {
        panic!("{error}");
    }
    assert_eq!(sb.counters(), StageCounters::default());
    assert!(log.is_empty());
    assert_eq!(conditions.asked_steps(2), Vec::<i64>::new());
}
