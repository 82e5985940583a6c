//! UserDefinedValueCondition reads values set from outside the scenario (OpenSCENARIO 1.3
//! §7.6.2: "a value provided by an external source"): through `Engine::set_user_value` between
//! steps and a time series given with `Engine::schedule_user_values`, on
//! `tests/files/runtime/user_values.xosc` (three Events, each setting a monitor when it starts:
//! Mode equalTo "go", Speed greaterThan 10, Armed equalTo true).

use crate::runtime_support;

use engine::output::EventRecord;
use engine::user_values::{parse_csv, parse_value};
use engine::{Engine, EngineConfig};
use runtime_support::{file, monitor_values, Recorder};

/// Times at which monitor `name` became true.
fn set_true(events: &[EventRecord], name: &str) -> Vec<f64> {
    monitor_values(events, name)
        .into_iter()
        .filter_map(|(t, v)| v.then_some(t))
        .collect()
}

#[test]
fn scheduled_and_direct_values_start_their_events_at_the_right_steps() {
    let mut engine =
        Engine::load(&file("user_values.xosc"), &[], EngineConfig::default()).expect("loads");
    // Speed 8 at 1 s is not above 10; Mode "go" at 2 s; Speed 12.5 at 3 s is. A value due at
    // t is set before the triggers of the step that begins at t, so its Event starts at t.
    let series = parse_csv(
        "time,name,value\n1.0,Speed,8\n2.0,Mode,go\n3.0,Speed,12.5\n",
        "series.csv",
    )
    .unwrap();
    engine.schedule_user_values(&series);
    let mut events = Vec::new();
    let mut frames = Recorder::default();
    // Armed is set directly by the host before the step at t = 0.5 s (step 10 at dt 0.05).
    for _ in 0..10 {
        engine.step(&mut frames, &mut events).unwrap();
    }
    engine.set_user_value("Armed", parse_value("true"));
    engine.run(&mut frames, &mut events).unwrap();
    let close = |got: Vec<f64>, want: f64| got.len() == 1 && (got[0] - want).abs() < 1e-9;
    assert!(close(set_true(&events, "ArmedSeen"), 0.5));
    assert!(close(set_true(&events, "ModeGoSeen"), 2.0));
    assert!(close(set_true(&events, "FastSeen"), 3.0));
    assert_eq!(
        engine.monitors(),
        [
            ("ArmedSeen".to_owned(), true),
            ("FastSeen".to_owned(), true),
            ("ModeGoSeen".to_owned(), true)
        ]
    );
}

#[test]
fn a_value_nobody_sets_never_holds() {
    let mut engine =
        Engine::load(&file("user_values.xosc"), &[], EngineConfig::default()).expect("loads");
    let mut events = Vec::new();
    engine.run(&mut Recorder::default(), &mut events).unwrap();
    assert!(engine.monitors().iter().all(|(_, v)| !v));
}
