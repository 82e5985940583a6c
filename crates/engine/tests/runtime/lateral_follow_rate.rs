//! oscsim's lane change beside a moving entity at a rate (`LaneChangeTarget::Beside` with
//! `follow`, dynamics of dimension `rate`; module doc of `engine::actions::lateral_follow`)
//! against its closed form, on lateral_follow_rate.xosc: Npc's offset in lane −1 (centre t =
//! −1.535 m) goes 0 → 1.0 m over [1, 3] s, sinusoidal: t_n(τ) = −1.535 + (1 − cos(πτ/2))/2.
//! Ego's "Follow" from t = 1 s: 0.5 m right of Npc (d = −0.5), linear at 0.5 m/s: its t₀ =
//! −1.535 m, Npc's t + d then −2.035 m, T = 0.5/0.5 = 1 s; t(τ) = (1 − τ)·t₀ + τ·(t_n(τ) − 0.5)
//! to τ = 1, then t_n(τ) − 0.5 held (−1.035 m from 3 s, where Npc's change ends).

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig};
use scenario::{
    ActionKind, DynamicsDimension, DynamicsShape, LaneChangeTarget, LateralAction, PlanRoads,
    PrivateAction, Scenario, TransitionDynamics,
};

use crate::runtime_support::{file, Recorder};

/// The road is straight along x: y is t, exact up to round-off.
const Y_TOL: f64 = 1e-9;

#[test]
fn a_move_beside_a_moving_entity_at_a_rate_blends_at_its_shape_then_holds() {
    let mut scenario = Scenario::load(&file("lateral_follow_rate.xosc")).expect("loads");
    let follow = &mut scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events
        [0]
    .actions[0];
    follow.kind = ActionKind::Private(PrivateAction::Lateral(LateralAction::LaneChange {
        target_lane_offset: None,
        dynamics: TransitionDynamics {
            dynamics_shape: DynamicsShape::Linear,
            dynamics_dimension: DynamicsDimension::Rate,
            value: 0.5,
            following_mode: None,
        },
        target: LaneChangeTarget::Beside {
            entity_ref: "Npc".to_string(),
            t: -0.5,
            what: "the test's follow".to_string(),
            follow: true,
            roads: PlanRoads::default(),
        },
    }));
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::<engine::EventRecord>::new());
    engine.run(&mut frames, &mut events).expect("runs");
    let pi = std::f64::consts::PI;
    let npc = |tau: f64| -1.535 + (1.0 - (pi * tau.min(2.0) / 2.0).cos()) / 2.0;
    for k in 0..=60 {
        let t = 1.0 + 0.05 * f64::from(k);
        let (tau, f) = (t - 1.0, (t - 1.0).min(1.0));
        assert_abs_diff_eq!(frames.at("Npc", t).y, npc(tau), epsilon = Y_TOL);
        let want = (1.0 - f) * -1.535 + f * (npc(tau) - 0.5);
        assert_abs_diff_eq!(frames.at("Ego", t).y, want, epsilon = Y_TOL);
    }
    // By hand: half way −0.5·1.535 + 0.5·(−1.535 + (1 − cos(π/4))/2 − 0.5) at 1.5 s.
    assert_abs_diff_eq!(frames.at("Ego", 1.5).y, -1.7117767, epsilon = 1e-7);
    assert_abs_diff_eq!(frames.at("Ego", 4.0).y, -1.035, epsilon = Y_TOL);
}
