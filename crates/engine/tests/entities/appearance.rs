//! AppearanceAction and EnvironmentAction state (OpenSCENARIO 1.3 XSD `LightStateAction`,
//! `EnvironmentAction`): kept per entity / in the world and written to the event log.

use crate::runtime_support;

use engine::output::EventRecord;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};
use runtime_support::{corpus, esmini_reference_events, first_transition};
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
    let light = |engine: &Engine| {
        let car1 = engine.entity("Car1").expect("in the scene");
        car1.lights.get("indicatorLeft").cloned().expect("set")
    };
    let on = step_until(&mut engine, &mut events, "light indicatorLeft flashing");
    assert_eq!(on.1, "actionBlinkingLeft");
    let state = light(&engine);
    assert_eq!(state.mode, LightMode::Flashing);
    assert_eq!(state.luminous_intensity, Some(500.0));
    let off = step_until(&mut engine, &mut events, "light indicatorLeft off");
    assert!(off.1 == "actionStopBlinkingLeft" && off.0 > on.0, "{off:?}");
    assert_eq!(light(&engine).mode, LightMode::Off);
}

/// Runs the scenario at `path` to its end; returns its event log.
fn run_log(path: &std::path::Path) -> Vec<EventRecord> {
    let mut engine = Engine::load(path, &[], EngineConfig::default()).expect("loads");
    let mut events = Vec::new();
    engine.run(&mut (), &mut events).expect("runs");
    events
}

/// The time of the first `transition` of storyboard element `element` in `events`.
fn transition_time(events: &[EventRecord], element: &str, transition: Transition) -> Option<f64> {
    events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == element && t.transition == transition => {
            Some(t.time)
        }
        _ => None,
    })
}

/// The time of `element`'s first `transition` in esmini's reference log of light_state.
fn reference_time(element: &str, transition: Transition) -> f64 {
    first_transition(&esmini_reference_events("light_state"), element, transition)
        .unwrap_or_else(|| panic!("{element} {transition} not in the reference"))
}

/// XSD `LightStateAction`: `transitionTime` is the "time to transition from current lightState
/// to given new lightState", and LightState the state "after execution": the action runs for
/// its transition time. In light_state.xosc (dt 0.05 s) actionLowBeamOn (line 532),
/// actionDRLOn (556) and actionHighBeamOn (580) have transitionTime 1 and start 33.150, 34.150
/// and 35.150 s (esmini's reference log, which these starts must match). Each ends in the step
/// whose advance reaches start + 1 s: at start + 0.95 s (esmini records start + 1.00 s). So
/// eventLowBeamOn and eventDRLOn have ended when the next override Event starts (end
/// transitions, as in esmini, not stops). eventManyLightsOn waits for eventHighBeamOn's end
/// with delay 1 and starts 1.05 s after it (the condition sees the end one step later):
/// 36.100 + 1.05 = 37.150 s, esmini 37.200 s. actionStartLPI (transitionTime 0, line 133)
/// starts and ends in one step.
#[test]
fn light_state_action_ends_after_its_transition_time() {
    let events = run_log(&corpus("esmini/xosc/light_state.xosc"));
    let find =
        |element: &str, transition: Transition| transition_time(&events, element, transition);
    let ours = |element: &str, transition: Transition| {
        find(element, transition).unwrap_or_else(|| panic!("no {transition:?} of {element}"))
    };
    for action in ["actionLowBeamOn", "actionDRLOn", "actionHighBeamOn"] {
        let start = ours(action, Transition::Start);
        assert!(
            (start - reference_time(action, Transition::Start)).abs() < 1e-6,
            "{action} start"
        );
        let end = ours(action, Transition::End);
        assert!(
            (end - start - 0.95).abs() < 1e-9,
            "{action}: {start} → {end}"
        );
        assert!(
            (reference_time(action, Transition::End) - end - 0.05).abs() < 1e-6,
            "{action} end"
        );
    }
    for event in ["eventLowBeamOn", "eventDRLOn"] {
        assert!(
            find(event, Transition::Stop).is_none(),
            "{event} was stopped"
        );
        assert!(
            (ours(event, Transition::End) - reference_time(event, Transition::End) + 0.05).abs()
                < 1e-6
        );
    }
    let lpi = ours("actionStartLPI", Transition::Start);
    assert!((ours("actionStartLPI", Transition::End) - lpi).abs() < 1e-9);
    let many = ours("eventManyLightsOn", Transition::Start);
    assert!((many - ours("eventHighBeamOn", Transition::End) - 1.05).abs() < 1e-9);
    assert!((many - 37.15).abs() < 1e-9, "{many}");
    assert!((reference_time("eventManyLightsOn", Transition::Start) - many - 0.05).abs() < 1e-6);
}

/// OpenSCENARIO 1.3 Annex A ("Action ends") for AnimationAction, on animation.xosc (dt 0.05 s),
/// every action started in the step at 1 s: "door" (loop false, animationDuration 2) ends in
/// the step whose advance reaches 3 s, at 2.95 s; "mirrors" (no duration) ends at once;
/// "window" (loop true: "no regular ending") and "walk" (a pedestrian motion, performed
/// continuously) run until the storyboard's stop trigger (first step with t > 4 s, 4.05 s)
/// stops them: stop transitions, no end.
#[test]
fn animation_actions_end_as_the_action_table_says() {
    let events = run_log(&crate::corpus::fixture("entities").join("animation.xosc"));
    let at = |element: &str, transition: Transition| transition_time(&events, element, transition);
    let close = |t: Option<f64>, expected: f64| t.is_some_and(|t| (t - expected).abs() < 1e-9);
    for action in ["door", "mirrors", "window", "walk"] {
        assert!(close(at(action, Transition::Start), 1.0), "{action} start");
    }
    assert!(close(at("door", Transition::End), 2.95));
    assert!(close(at("mirrors", Transition::End), 1.0));
    for action in ["window", "walk"] {
        assert_eq!(at(action, Transition::End), None, "{action} ended");
        assert!(close(at(action, Transition::Stop), 4.05), "{action} stop");
    }
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
    assert!(engine.environment().time_of_day_setting().is_none());
    while start_of(&events, "morningTimeEvent").is_none() {
        let night = start_of(&events, "nightTimeEvent");
        if let Some(at) = night {
            let environment = engine.environment();
            let (tod, set_at) = environment
                .time_of_day_setting()
                .expect("set by the night event");
            assert_eq!(tod.date_time, "2025-06-13T00:00:00.000+00:00");
            assert!(tod.animation && (set_at - at).abs() < 1e-9);
        }
        let stopped = engine.step(&mut (), &mut events).expect("runs");
        assert!(stopped.is_none(), "morningTimeEvent never started");
    }
    let at = start_of(&events, "morningTimeEvent").expect("started");
    let environment = engine.environment();
    let (tod, set_at) = environment.time_of_day_setting().expect("set");
    assert_eq!(tod.date_time, "2025-06-13T06:00:00.000+00:00");
    assert!((set_at - at).abs() < 1e-9);
}
