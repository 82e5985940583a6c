//! oscsim's TravelAction (`LongitudinalAction::Travel`, no XML form; module doc of
//! `engine::actions::travel`) against closed forms. speed_shapes.xosc puts Ego in lane -1 of a
//! straight road at s = 100 m at 10 m/s and starts its action "Speed" at t = 1 s (Ego then at
//! s = 110 m); here that action is replaced in the loaded model. The runtime sets in each step
//! the speed of the step's end and moves with it.

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig, ErrorKind};
use scenario::{LongitudinalAction, Scenario, Travel, TravelGoal};

use crate::acceleration_action::speed_shapes_with;
use crate::runtime_support::Recorder;

/// Tolerance for values that are sums of a few hundred f64 terms.
const EXACT: f64 = 1e-9;

/// speed_shapes.xosc with its action "Speed" made a TravelAction to `goal` over `duration`.
fn scenario(goal: TravelGoal, duration: f64, end_speed: Option<f64>) -> Scenario {
    speed_shapes_with(LongitudinalAction::Travel(Box::new(Travel {
        what: "the test's travel".into(),
        goal,
        duration,
        end_speed,
        end_speed_of: None,
        monotonous: false,
        limits: (70.0, 10.0),
        roads: scenario::PlanRoads::default(),
    })))
}

/// To s = 170 m over 4 s from s = 110 m at 10 m/s: Δs = 60 m, v_m = (4·60/4 − 10 − 10)/2 =
/// 20 m/s at t = 3 s, back to 10 m/s at 5 s. With v_e = v₀ the step ends' sum is the
/// integral: s(5) = 170 m.
#[test]
fn a_travel_to_a_road_s_runs_the_two_halves_worked_out_at_its_start() {
    let scenario = scenario(TravelGoal::RoadS(170.0), 4.0, None);
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    engine.run(&mut frames, &mut events).expect("runs");
    let v = |t: f64| frames.at("Ego", t).speed;
    let s = |t: f64| frames.at("Ego", t).road.as_ref().map_or(f64::NAN, |r| r.2);
    assert_abs_diff_eq!(s(1.0), 110.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(2.0), 15.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(3.0), 20.0, epsilon = EXACT);
    assert_abs_diff_eq!(v(5.0), 10.0, epsilon = EXACT);
    assert_abs_diff_eq!(s(5.0), 170.0, epsilon = EXACT);
}

/// distance(30 m) in 2 s ending at 5 m/s from 10 m/s: v_m = (4·30/2 − 10 − 5)/2 = 22.5 m/s,
/// 12.5 m/s² in the first half and 17.5 m/s² in the second, the larger named, above the
/// 10 m/s² limit: the run stops at t = 1 s with the action's error.
#[test]
fn a_travel_beyond_its_limits_fails_the_run() {
    let scenario = scenario(TravelGoal::Distance(30.0), 2.0, Some(5.0));
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    let error = engine.run(&mut frames, &mut events).expect_err("fails");
    assert!(
        matches!(error.kind(), ErrorKind::CheckFailed { time, .. } if (time - 1.0).abs() < EXACT),
        "{error}"
    );
    assert_eq!(
        error.to_string(),
        "expected 'Ego' accelerating at 10 m/s² or less (the test's travel), found 30.000 m in 2 s from 10.000 m/s: 10.000 → 22.500 → 5.000 m/s, 17.500 m/s² at t = 1.000 s"
    );
}
