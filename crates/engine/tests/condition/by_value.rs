//! ByValueConditions (OpenSCENARIO 1.3 §7.6.2) against a fake runtime.

use crate::condition_support;

use condition_support::{condition, corpus_road, eval, eval_error, FakeWorld};
use scenario::expr::Value;
use scenario::{
    ByValueCondition, ConditionKind, Rule, StoryboardElementState, StoryboardElementType,
};

fn world() -> FakeWorld {
    FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"))
}

fn by_value(c: ByValueCondition) -> scenario::Condition {
    condition(ConditionKind::ByValue(c))
}

fn sim_time(value: f64, rule: Rule) -> scenario::Condition {
    by_value(ByValueCondition::SimulationTime { value, rule })
}

#[test]
fn simulation_time_rules_and_the_equal_tolerance() {
    let mut w = world();
    // 100 steps of 0.05 s summed in f64 miss 5.0 by round-off (about 1e-14); equalTo must
    // still hold there (tolerance 1e-9 · max(1, |v|)), and the strict rules must not.
    w.time = (0..100).fold(0.0, |t, _| t + 0.05);
    assert!(w.time != 5.0, "the sum is expected to be inexact");
    assert!(eval(&w, &sim_time(5.0, Rule::EqualTo)));
    assert!(!eval(&w, &sim_time(5.0, Rule::GreaterThan)));
    assert!(!eval(&w, &sim_time(5.0, Rule::LessThan)));
    assert!(eval(&w, &sim_time(5.0, Rule::GreaterOrEqual)));
    assert!(eval(&w, &sim_time(5.0, Rule::LessOrEqual)));
    assert!(!eval(&w, &sim_time(5.0, Rule::NotEqualTo)));
    w.time = 5.05;
    assert!(eval(&w, &sim_time(5.0, Rule::GreaterThan)));
    assert!(eval(&w, &sim_time(5.0, Rule::NotEqualTo)));
    assert!(!eval(&w, &sim_time(5.0, Rule::LessOrEqual)));
}

#[test]
fn parameter_and_variable_compare_as_their_declared_type() {
    let mut w = world();
    w.parameters.insert("Speed".into(), Value::Double(13.9));
    w.parameters
        .insert("Mode".into(), Value::String("fast".into()));
    w.variables.insert("Count".into(), Value::Int(3));
    w.variables.insert("Flag".into(), Value::Bool(true));
    let param = |name: &str, rule, value: &str| {
        by_value(ByValueCondition::Parameter {
            parameter_ref: name.into(),
            rule,
            value: value.into(),
        })
    };
    let var = |name: &str, rule, value: &str| {
        by_value(ByValueCondition::Variable {
            variable_ref: name.into(),
            rule,
            value: value.into(),
        })
    };
    assert!(eval(&w, &param("Speed", Rule::GreaterThan, "13.8")));
    assert!(eval(&w, &param("Speed", Rule::EqualTo, "1.39e1")));
    assert!(eval(&w, &param("Mode", Rule::EqualTo, "fast")));
    assert!(eval(&w, &param("Mode", Rule::NotEqualTo, "slow")));
    assert!(eval(&w, &var("Count", Rule::GreaterOrEqual, "3")));
    assert!(!eval(&w, &var("Count", Rule::LessThan, "3")));
    assert!(eval(&w, &var("Flag", Rule::EqualTo, "true")));
    assert_eq!(
        eval_error(&w, &param("Mode", Rule::GreaterThan, "a")),
        "expected equalTo or notEqualTo for a string value, found rule greaterThan at test.xosc:7:9"
    );
    assert_eq!(
        eval_error(&w, &var("Count", Rule::EqualTo, "three")),
        "expected a int value, found \"three\" at test.xosc:7:9"
    );
    assert_eq!(
        eval_error(&w, &var("Nope", Rule::EqualTo, "1")),
        "expected a declared variable named \"Nope\", found none at test.xosc:7:9"
    );
}

#[test]
fn user_defined_values_come_from_the_registry() {
    let mut w = world();
    let c = by_value(ByValueCondition::UserDefinedValue {
        name: "Throttle".into(),
        rule: Rule::GreaterThan,
        value: "0.5".into(),
    });
    // Nothing registered yet: false, not an error (it may be registered later).
    assert!(!eval(&w, &c));
    w.user_values.insert("Throttle".into(), Value::Double(0.7));
    assert!(eval(&w, &c));
}

#[test]
fn storyboard_element_states_after_the_first_step() {
    let mut w = world();
    // Before any step: nothing runs.
    let state = |kind, name: &str, state| {
        by_value(ByValueCondition::StoryboardElementState {
            storyboard_element_type: kind,
            storyboard_element_ref: name.into(),
            state,
        })
    };
    assert!(!eval(
        &w,
        &state(
            StoryboardElementType::Act,
            "A",
            StoryboardElementState::RunningState
        )
    ));
    w.step_storyboard(0.0);
    // Act "A" has no start trigger: it starts with its Story (pitfall 1), in this step, so its
    // startTransition is seen now. Event "E" waits for a trigger that never holds: standby.
    assert!(eval(
        &w,
        &state(
            StoryboardElementType::Act,
            "A",
            StoryboardElementState::RunningState
        )
    ));
    assert!(eval(
        &w,
        &state(
            StoryboardElementType::Act,
            "A",
            StoryboardElementState::StartTransition
        )
    ));
    assert!(eval(
        &w,
        &state(
            StoryboardElementType::Event,
            "E",
            StoryboardElementState::StandbyState
        )
    ));
    assert!(!eval(
        &w,
        &state(
            StoryboardElementType::Event,
            "E",
            StoryboardElementState::RunningState
        )
    ));
    assert!(!eval(
        &w,
        &state(
            StoryboardElementType::Event,
            "E",
            StoryboardElementState::CompleteState
        )
    ));
    assert_eq!(
        eval_error(
            &w,
            &state(
                StoryboardElementType::Maneuver,
                "A",
                StoryboardElementState::RunningState
            )
        ),
        "expected a storyboard element maneuver named \"A\", found none at test.xosc:7:9"
    );
}

/// oscsim's clock from an Act's start (the DSL's every/elapsed in an invoked behavior's
/// handler): Act "A" starts in the first step (step 0); at 0.05 s steps, every(0.5 s, offset:
/// 0.25 s) since it holds in steps 5 and 15 (0.25 s and 0.75 s after it), elapsed(0.3 s) since
/// it from step 6 on; an unknown Act is an error naming it.
#[test]
fn the_clock_since_an_acts_start_counts_its_steps() {
    let mut w = world();
    let every = |act: &str| {
        by_value(ByValueCondition::SimulationTimeEvery {
            period: 0.5,
            offset: 0.25,
            step: 0.05,
            since: Some(act.into()),
        })
    };
    let elapsed = by_value(ByValueCondition::ElapsedSinceStart {
        act: "A".into(),
        value: 0.3,
        step: 0.05,
    });
    // Before the first step the Act has not started: neither holds.
    assert!(!eval(&w, &every("A")) && !eval(&w, &elapsed));
    let mut ticks = Vec::new();
    for k in 0..=20u32 {
        w.step_storyboard(f64::from(k) * 0.05);
        if eval(&w, &every("A")) {
            ticks.push(k);
        }
        // From step 6 (0.30 s after the start) on.
        assert_eq!(eval(&w, &elapsed), k >= 6, "step {k}");
    }
    assert_eq!(ticks, [5, 15]);
    assert_eq!(
        eval_error(&w, &every("B")),
        "expected a storyboard element act named \"B\", found none at test.xosc:7:9"
    );
}

#[test]
fn time_of_day_and_traffic_signals() {
    let mut w = world();
    let c = by_value(ByValueCondition::TimeOfDay {
        rule: Rule::GreaterOrEqual,
        date_time: "2021-06-01T12:00:00".into(),
    });
    // No TimeOfDay set: false.
    assert!(!eval(&w, &c));
    // 2021-06-01 is day 18 779 after 1970-01-01 (51 years · 365 + 13 leap days + 151 days of
    // January–May); 12:00:30 is 30 s after the condition's noon.
    w.time_of_day = Some(18_779.0 * 86_400.0 + 12.0 * 3600.0 + 30.0);
    assert!(eval(&w, &c));
    w.time_of_day = Some(18_779.0 * 86_400.0 + 11.0 * 3600.0);
    assert!(!eval(&w, &c));
    assert_eq!(
        eval_error(
            &w,
            &by_value(ByValueCondition::TimeOfDay {
                rule: Rule::EqualTo,
                date_time: "noon".into()
            })
        ),
        "expected an xsd:dateTime like 2020-10-12T12:00:00, found \"noon\" at test.xosc:7:9"
    );
    w.signals.insert("S1".into(), "off;off;on".into());
    w.controller_phases.insert("Ctrl".into(), "go".into());
    let signal = |state: &str| {
        by_value(ByValueCondition::TrafficSignal {
            name: "S1".into(),
            state: state.into(),
        })
    };
    assert!(eval(&w, &signal("off;off;on")));
    assert!(!eval(&w, &signal("on;off;off")));
    let phase = |p: &str| {
        by_value(ByValueCondition::TrafficSignalController {
            traffic_signal_controller_ref: "Ctrl".into(),
            phase: p.into(),
        })
    };
    assert!(eval(&w, &phase("go")));
    assert!(!eval(&w, &phase("stop")));
}
