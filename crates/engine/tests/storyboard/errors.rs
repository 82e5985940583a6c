//! Bad descriptions and bad step times are errors with the place and what was expected, never
//! panics. Limits from OpenSCENARIO 1.3: `Condition/@delay` has range [0..inf[,
//! `ConditionGroup` holds 1..* conditions.

use crate::storyboard_support;

use engine::storyboard::{
    ConditionEdge, ConditionGroupDesc, ErrorKind, Storyboard, StoryboardDesc, TriggerDesc,
};
use storyboard_support::*;

fn with_act_trigger(trigger: TriggerDesc) -> StoryboardDesc {
    let mut act = simple_act();
    act.start_trigger = Some(trigger);
    storyboard(act)
}

#[test]
fn a_negative_delay_is_rejected_with_its_place() {
    let mut condition = cond(1, ConditionEdge::Rising, -1.0);
    condition.origin = Some("cut-in.xosc:129:28".to_owned());
    let error = match Storyboard::new(&with_act_trigger(TriggerDesc::single(condition))) {
        Ok(_) => panic!("accepted a negative delay"),
        Err(error) => error,
    };
    assert!(matches!(error.kind(), ErrorKind::InvalidDelay { .. }));
    assert_eq!(
        error.to_string(),
        "expected a finite delay >= 0 s, found -1 in condition 'C1' of the StartTrigger of act \
         'Act' at cut-in.xosc:129:28"
    );
}

#[test]
fn a_nan_or_infinite_delay_is_rejected() {
    for delay in [f64::NAN, f64::INFINITY] {
        let mut desc = storyboard(simple_act());
        desc.stop_trigger = Some(TriggerDesc::single(cond(3, ConditionEdge::None, delay)));
        let error = match Storyboard::new(&desc) {
            Ok(_) => panic!("accepted delay {delay}"),
            Err(error) => error,
        };
        assert_eq!(
            error.to_string(),
            format!(
                "expected a finite delay >= 0 s, found {delay} in condition 'C3' of the \
                 StopTrigger of storyboard 'SB'"
            )
        );
    }
}

#[test]
fn an_empty_condition_group_is_rejected() {
    let trigger = TriggerDesc {
        condition_groups: vec![
            ConditionGroupDesc {
                conditions: vec![cond(1, ConditionEdge::None, 0.0)],
            },
            ConditionGroupDesc::default(),
        ],
    };
    let error = match Storyboard::new(&with_act_trigger(trigger)) {
        Ok(_) => panic!("accepted an empty group"),
        Err(error) => error,
    };
    assert_eq!(
        error.to_string(),
        "expected at least one Condition, found an empty ConditionGroup #2 in the StartTrigger \
         of act 'Act'"
    );
}

#[test]
fn bad_step_times_are_rejected_and_change_nothing() {
    let mut sb = build(&storyboard(simple_act()));
    let mut conditions = ScriptedConditions::default();
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    let mut log = Vec::new();
    let mut step = |sb: &mut Storyboard, time: f64, dt: f64, log: &mut Vec<_>| {
        sb.step(time, dt, &mut conditions, &mut actions, log)
            .map_err(|error| error.to_string())
    };
    assert_eq!(
        step(&mut sb, f64::NAN, DT, &mut log),
        Err("expected a finite simulation time, found NaN s".to_owned())
    );
    assert_eq!(
        step(&mut sb, 0.0, 0.0, &mut log),
        Err("expected a finite step length > 0 s, found 0 s".to_owned())
    );
    assert!(log.is_empty());
    assert_eq!(step(&mut sb, 0.0, DT, &mut log), Ok(()));
    let records = log.len();
    assert_eq!(
        step(&mut sb, 0.0, DT, &mut log),
        Err("expected a simulation time after the previous step's 0 s, found 0 s".to_owned())
    );
    assert_eq!(log.len(), records);
    assert_eq!(step(&mut sb, 0.1, DT, &mut log), Ok(()));
}
