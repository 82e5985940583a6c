//! oscsim's RelativeAccelerationAction with a transition (`LongitudinalAction::
//! RelativeAcceleration { transition, .. }`, no XML form; module doc of
//! `engine::actions::relative_acceleration`) against closed forms, on
//! relative_acceleration_shape.xosc: Ego at 20 m/s, Lead braking at 2 m/s² from 8 to 4 m/s over
//! [1, 3] s, then at 4 m/s. Ego's "Follow" (at t = 1 s) goes from its acceleration 0 to Lead's
//! −2 m/s² + 1 at a jerk of 1 m/s³ (linear): T = |−1 − 0|/1 = 1 s, a = −τ, v = 20 − τ²/2:
//! 19.875 m/s at 1.5 s, 19.5 m/s at 2 s. The runtime sets in each step the speed of the
//! step's end, so the frame at t shows v(t).

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig, EventRecord};
use scenario::{
    ActionKind, DynamicsDimension, DynamicsShape, LongitudinalAction, PrivateAction, Scenario,
    TransitionDynamics,
};

use crate::runtime_support::{end_time, file, Recorder};

/// Sums of a few hundred f64 terms.
const EXACT: f64 = 1e-9;

/// The file with Ego's action `name` made `action`.
fn with(scenario: &mut Scenario, name: &str, action: LongitudinalAction) {
    let events = &mut scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events;
    let a = events
        .iter_mut()
        .flat_map(|e| e.actions.iter_mut())
        .find(|a| a.name == name)
        .expect("the action");
    a.kind = ActionKind::Private(PrivateAction::Longitudinal(action));
}

/// Runs the file with Ego's "Follow" to Lead's acceleration + 1 m/s² at a jerk of 1 m/s³
/// (`continuous` and `ends_at_target` as given) and "Hold" an AccelerationAction keeping the
/// acceleration it starts with.
fn run(continuous: bool, ends_at_target: bool) -> (Recorder, Vec<EventRecord>) {
    let mut scenario = Scenario::load(&file("relative_acceleration_shape.xosc")).expect("loads");
    let follow = LongitudinalAction::RelativeAcceleration {
        entity_ref: "Lead".to_string(),
        value: 1.0,
        continuous,
        to_speed: None,
        transition: Some(TransitionDynamics {
            dynamics_shape: DynamicsShape::Linear,
            dynamics_dimension: DynamicsDimension::Rate,
            value: 1.0,
            following_mode: None,
        }),
        ends_at_target,
    };
    with(&mut scenario, "Follow", follow);
    let hold = LongitudinalAction::Acceleration {
        target: None,
        dynamics: TransitionDynamics {
            dynamics_shape: DynamicsShape::Step,
            dynamics_dimension: DynamicsDimension::Time,
            value: 0.0,
            following_mode: None,
        },
        ends_at_target: false,
    };
    with(&mut scenario, "Hold", hold);
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    engine.run(&mut frames, &mut events).expect("runs");
    (frames, events)
}

/// Following (`continuous`, not ending): after the transition, Lead's acceleration + 1: −1
/// m/s² to 3 s (18.5 m/s), then +1 m/s² (Lead holds 4 m/s): 19.5 m/s at 4 s, 20.5 m/s at 5 s.
/// "Hold" never starts ("Follow" does not end).
#[test]
fn a_transition_to_the_references_acceleration_then_follows_it() {
    let (frames, events) = run(true, false);
    for (t, v) in [
        (1.0, 20.0),
        (1.5, 19.875),
        (2.0, 19.5),
        (3.0, 18.5),
        (4.0, 19.5),
        (5.0, 20.5),
    ] {
        assert_abs_diff_eq!(frames.at("Ego", t).speed, v, epsilon = EXACT);
    }
    assert!(end_time(&events, "Follow").is_none());
}

/// Projected (Lead's −2 m/s² over the first step, fixed) and ending at the target: "Follow"
/// ends in the step 1.95 … 2.00 s that completes the transition, at −1 m/s²; "Hold", an
/// AccelerationAction keeping the acceleration it starts with, starts at 2 s from the −1 m/s²
/// reached (not the step's mean, −0.975): 18.5, 17.5, 16.5 m/s at 3, 4, 5 s.
#[test]
fn a_transition_that_ends_at_its_target_hands_it_to_the_acceleration_kept_after() {
    let (frames, events) = run(false, true);
    for (t, v) in [
        (1.5, 19.875),
        (2.0, 19.5),
        (3.0, 18.5),
        (4.0, 17.5),
        (5.0, 16.5),
    ] {
        assert_abs_diff_eq!(frames.at("Ego", t).speed, v, epsilon = EXACT);
    }
    assert_abs_diff_eq!(
        end_time(&events, "Follow").expect("ends"),
        1.95,
        epsilon = EXACT
    );
}
