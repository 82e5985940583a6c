//! AppearanceAction and EnvironmentAction state (OpenSCENARIO 1.3 XSD `LightStateAction`,
//! `EnvironmentAction`): kept per entity / in the world and written to the event log.

mod runtime_support;

use engine::output::EventRecord;
use engine::{Engine, EngineConfig};
use runtime_support::corpus;
use scenario::LightMode;

/// The first `entity` record of Car1 with `change` (time, element).
fn change(events: &[EventRecord], what: &str) -> Option<(f64, String)> {
    events.iter().find_map(|e| match e {
        EventRecord::Entity {
            time,
            element,
            entity,
            change,
        } if entity == "Car1" && change == what => Some((*time, element.clone())),
        _ => None,
    })
}

/// Steps `engine` until Car1's `what` record is in `events`.
fn step_until(engine: &mut Engine, events: &mut Vec<EventRecord>, what: &str) -> (f64, String) {
    loop {
        if let Some(found) = change(events, what) {
            return found;
        }
        let stopped = engine.step(&mut (), events).expect("runs");
        assert!(stopped.is_none(), "no '{what}' record");
    }
}

/// esmini's light_state.xosc: "actionBlinkingLeft" (line 207) sets Car1's indicatorLeft to
/// `flashing` with luminousIntensity 500; "actionStopBlinkingLeft" turns it `off` later. Right
/// after each record the state is the one the action wrote, and each change is an `entity`
/// record naming the action and the light.
#[test]
fn light_state_action_is_kept_and_logged() {
    let path = corpus("esmini/xosc/light_state.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut events = Vec::new();
    let car1 = engine.world().id("Car1").expect("declared");
    let on = step_until(&mut engine, &mut events, "light indicatorLeft flashing");
    assert_eq!(on.1, "actionBlinkingLeft");
    {
        let world = engine.world();
        let state = world.light_state(car1, "indicatorLeft").expect("set");
        assert_eq!(state.mode, LightMode::Flashing);
        assert_eq!(state.luminous_intensity, Some(500.0));
    }
    let off = step_until(&mut engine, &mut events, "light indicatorLeft off");
    assert!(off.1 == "actionStopBlinkingLeft" && off.0 > on.0, "{off:?}");
    let world = engine.world();
    let state = world.light_state(car1, "indicatorLeft").expect("set");
    assert_eq!(state.mode, LightMode::Off);
}

/// esmini's cut-in_environment.xosc: "nightTimeAction" sets TimeOfDay 00:00 (line 92),
/// "morningTimeAction" 06:00 (line 112), both with animation. After each, the world's time of
/// day is that dateTime, stamped with the start time of its event.
#[test]
fn environment_action_sets_the_time_of_day() {
    let path = corpus("esmini/xosc/cut-in_environment.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut events = Vec::new();
    let start_of = |events: &Vec<EventRecord>, name: &str| {
        events.iter().find_map(|e| match e {
            EventRecord::Transition(t) if t.name == name => Some(t.time),
            _ => None,
        })
    };
    assert!(engine.world().time_of_day_setting().is_none());
    while start_of(&events, "morningTimeEvent").is_none() {
        let night = start_of(&events, "nightTimeEvent");
        if let Some(at) = night {
            let world = engine.world();
            let (tod, set_at) = world.time_of_day_setting().expect("set by the night event");
            assert_eq!(tod.date_time, "2025-06-13T00:00:00.000+00:00");
            assert!(tod.animation && (set_at - at).abs() < 1e-9);
        }
        let stopped = engine.step(&mut (), &mut events).expect("runs");
        assert!(stopped.is_none(), "morningTimeEvent never started");
    }
    let at = start_of(&events, "morningTimeEvent").expect("started");
    let world = engine.world();
    let (tod, set_at) = world.time_of_day_setting().expect("set");
    assert_eq!(tod.date_time, "2025-06-13T06:00:00.000+00:00");
    assert!((set_at - at).abs() < 1e-9);
}
