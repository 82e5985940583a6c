//! oscsim's held state check (`StateCheck::throughout`, no XML form; module doc of
//! `engine::actions::check_held`) reads every entity at one time. held_check_time.xosc gives
//! Lead and Ego the same linear SpeedAction, 10 → 20 m/s over [1, 5] s (2.5 m/s²), so at every
//! time t both have v(t) = 10 + 2.5·(t − 1); Ego's held check asks for Lead's speed within
//! 0.01 m/s. Lead's SpeedAction comes before the check in the action stage's order and Ego's
//! after it: read as the stage went, the check saw Lead at the step's end, v(t + dt), and Ego
//! at its start, v(t), 2.5·0.05 = 0.125 m/s apart, and failed the run at t = 1.000 s.
//! ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.1 `at: all`: "the constraint holds throughout the
//! phase", a relation between states at one time; OpenSCENARIO 1.3 §8.4.2 evaluates a step's
//! conditions on the state at its start, and the checks read the same state.

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig};
use scenario::{ActionKind, PrivateAction, Scenario, StateCheck};

use crate::runtime_support::{file, Recorder};

/// held_check_time.xosc with its action "Check" made the held check of Ego at Lead's speed.
fn scenario() -> Scenario {
    let mut scenario = Scenario::load(&file("held_check_time.xosc")).expect("loads");
    let check = scenario.storyboard.stories[0].acts[0].maneuver_groups[1].maneuvers[0].events[0]
        .actions
        .iter_mut()
        .find(|a| a.name == "Check")
        .expect("the action Check");
    check.kind = ActionKind::Private(PrivateAction::Check(Box::new(StateCheck {
        what: "the test's speed(same_as: Lead)".into(),
        speed: Some((Some("Lead".into()), 0.0, 0.01)),
        throughout: true,
        ..StateCheck::default()
    })));
    scenario
}

#[test]
fn a_held_check_reads_every_entity_at_the_steps_start() {
    let scenario = scenario();
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    engine
        .run(&mut frames, &mut events)
        .expect("runs: the check holds at every step");
    // Both at v(t) in every frame: the ramp by hand, and one speed.
    for k in 0..=120 {
        let t = k as f64 * 0.05;
        let v = 10.0 + 2.5 * (t.clamp(1.0, 5.0) - 1.0);
        assert_abs_diff_eq!(frames.at("Lead", t).speed, v, epsilon = 1e-9);
        assert_abs_diff_eq!(frames.at("Ego", t).speed, v, epsilon = 1e-9);
    }
}
