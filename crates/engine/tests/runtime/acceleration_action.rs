//! oscsim's AccelerationAction (`LongitudinalAction::Acceleration`, no XML form; module doc of
//! `engine::actions::acceleration`) against closed forms. speed_shapes.xosc puts Ego at
//! s = 100 m at 10 m/s and starts its action "Speed" at t = 1 s; here that action is replaced
//! in the loaded model. The runtime sets in each step the speed of the step's end and moves
//! with it, so the frame at t shows v(t) and the distance is Σ v(tₖ)·dt over the step ends.

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig, EventRecord};
use scenario::{
    ActionKind, DynamicsDimension, DynamicsShape, LongitudinalAction, PrivateAction, Scenario,
    TransitionDynamics,
};

use crate::runtime_support::{end_time, file, Recorder};

/// Tolerance for values that are sums of a few hundred f64 terms.
const EXACT: f64 = 1e-9;

fn dynamics(shape: DynamicsShape, dimension: DynamicsDimension, value: f64) -> TransitionDynamics {
    TransitionDynamics {
        dynamics_shape: shape,
        dynamics_dimension: dimension,
        value,
        following_mode: None,
    }
}

/// speed_shapes.xosc with its action "Speed" made `action`.
pub(crate) fn speed_shapes_with(action: LongitudinalAction) -> Scenario {
    let mut scenario = Scenario::load(&file("speed_shapes.xosc")).expect("loads");
    let speed = scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0]
        .actions
        .iter_mut()
        .find(|a| a.name == "Speed")
        .expect("the action Speed");
    speed.kind = ActionKind::Private(PrivateAction::Longitudinal(action));
    scenario
}

/// Runs speed_shapes.xosc with its action "Speed" made an AccelerationAction.
fn run(target: Option<f64>, dynamics: TransitionDynamics) -> (Recorder, Vec<EventRecord>) {
    run_action(LongitudinalAction::Acceleration {
        target,
        dynamics,
        ends_at_target: false,
    })
}

/// Runs speed_shapes.xosc with its action "Speed" made `action`.
fn run_action(action: LongitudinalAction) -> (Recorder, Vec<EventRecord>) {
    let scenario = speed_shapes_with(action);
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    engine.run(&mut frames, &mut events).expect("runs");
    (frames, events)
}

fn s_at(frames: &Recorder, t: f64) -> f64 {
    frames.at("Ego", t).road.as_ref().map_or(f64::NAN, |r| r.2)
}

/// A step to 2 m/s² at t = 1 s: v = 10 + 2·(t − 1). Over the N = 80 steps to t = 5 s Ego
/// covers Σ (10 + 2·k·dt)·dt = 10·4 + 2·dt²·N(N+1)/2 = 40 + 16.2 m: s(5) = 100 + 10 + 56.2.
#[test]
fn a_step_to_an_acceleration_holds_it() {
    let (frames, _) = run(
        Some(2.0),
        dynamics(DynamicsShape::Step, DynamicsDimension::Time, 0.0),
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(1.0), 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), 14.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 18.0, epsilon = EXACT);
    assert_abs_diff_eq!(s_at(&frames, 5.0), 166.2, epsilon = EXACT);
}

/// From 0 to 2 m/s² at a jerk of 1 m/s³ (linear, T = 2 s), then holding: after τ s,
/// v = 10 + τ²/2 while τ ≤ 2, then 12 + 2·(τ − 2): v(2) = 10.5, v(3) = 12, v(5) = 16.
#[test]
fn a_linear_change_of_acceleration_at_a_jerk() {
    let (frames, _) = run(
        Some(2.0),
        dynamics(DynamicsShape::Linear, DynamicsDimension::Rate, 1.0),
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(2.0), 10.5, epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), 12.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 16.0, epsilon = EXACT);
}

/// A sinusoidal change from 0 to −4 m/s² over 2 s: v = 10 − 4·(τ − (2/π)·sin(πτ/2))/2 while
/// τ ≤ 2 (at τ = 1: 10 − 2·(1 − 2/π); at τ = 2: 6, the change's mean −2 m/s² over 2 s), then
/// −4 m/s² until standing: 6 − 4·(τ − 2) reaches 0 at τ = 3.5 (t = 4.5 s), where the action
/// ends and Ego stands.
#[test]
fn a_sinusoidal_change_brakes_to_a_stop_and_ends_there() {
    let (frames, events) = run(
        Some(-4.0),
        dynamics(DynamicsShape::Sinusoidal, DynamicsDimension::Time, 2.0),
    );
    let v = |t: f64| frames.at("Ego", t).speed;
    let pi = std::f64::consts::PI;
    assert_abs_diff_eq!(v(2.0), 10.0 - 2.0 * (1.0 - 2.0 / pi), epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), 6.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(4.0), 2.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 0.0, epsilon = EXACT);
    // The step 4.45 … 4.50 s brings it to 0 m/s and ends the action; the storyboard logs the
    // end with the next step, as for the distance actions.
    assert_abs_diff_eq!(
        end_time(&events, "Speed").expect("ends"),
        4.5,
        epsilon = EXACT
    );
}

/// `ends_at_target`: from 0 to 2 m/s² at a jerk of 1 m/s³ from t = 1 s (T = 2 s) the action
/// ends in the step 2.95 … 3.00 s, at v = 10 + T²/2 = 12 m/s; the storyboard logs its end in
/// that step (2.95 s), whose motion completes it, as a SpeedAction's. Nothing holds the
/// acceleration after it: Ego keeps 12 m/s (the default controller), 12 m/s at 5 s where the
/// held change gives 16 m/s.
#[test]
fn a_change_that_ends_at_its_target_ends_when_the_transition_is_over() {
    let (frames, events) = run_action(LongitudinalAction::Acceleration {
        target: Some(2.0),
        dynamics: dynamics(DynamicsShape::Linear, DynamicsDimension::Rate, 1.0),
        ends_at_target: true,
    });
    for (t, v) in [
        (2.0, 10.5),
        (2.95, 10.0 + 1.95 * 1.95 / 2.0),
        (3.0, 12.0),
        (5.0, 12.0),
    ] {
        assert_abs_diff_eq!(frames.at("Ego", t).speed, v, epsilon = EXACT);
    }
    let end = end_time(&events, "Speed").expect("ends");
    assert_abs_diff_eq!(end, 2.95, epsilon = EXACT);
}

/// No target: the acceleration at the start (0: Ego cruises) is kept.
#[test]
fn without_a_target_the_acceleration_at_the_start_is_kept() {
    let (frames, events) = run(
        None,
        dynamics(DynamicsShape::Step, DynamicsDimension::Time, 0.0),
    );
    assert_abs_diff_eq!(frames.at("Ego", 5.0).speed, 10.0, epsilon = EXACT);
    assert!(end_time(&events, "Speed").is_none(), "it runs to the end");
}

/// A step to 2 m/s² at t = 1 s and, in the same Event (so the same step), a linear change to
/// 0 at a jerk of 2.5 m/s³ that replaces it before it acted: the change starts from the 2 m/s²
/// the step would have reached at once (not from the last step's 0), over 2/2.5 = 0.8 s:
/// v = 10 + 2τ − 1.25τ², v(1.4) = 10.6, v(1.8) = 10.8 m/s, then held: v(5) = 10.8 m/s.
#[test]
fn a_change_replacing_a_step_in_its_step_starts_from_the_step() {
    let mut scenario = speed_shapes_with(LongitudinalAction::Acceleration {
        target: Some(2.0),
        dynamics: dynamics(DynamicsShape::Step, DynamicsDimension::Time, 0.0),
        ends_at_target: false,
    });
    let event =
        &mut scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0];
    let mut change = event.actions[0].clone();
    change.name = "Change".to_string();
    change.kind = ActionKind::Private(PrivateAction::Longitudinal(
        LongitudinalAction::Acceleration {
            target: Some(0.0),
            dynamics: dynamics(DynamicsShape::Linear, DynamicsDimension::Rate, 2.5),
            ends_at_target: false,
        },
    ));
    event.actions.push(change);
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::<EventRecord>::new());
    engine.run(&mut frames, &mut events).expect("runs");
    let v = |t: f64| frames.at("Ego", t).speed;
    assert_abs_diff_eq!(v(1.0), 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(1.4), 10.6, epsilon = EXACT);
    assert_abs_diff_eq!(v(1.8), 10.8, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 10.8, epsilon = EXACT);
}
