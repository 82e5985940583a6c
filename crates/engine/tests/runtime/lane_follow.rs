//! oscsim's following of lane changes (`LateralAction::FollowLanes`, no XML form; module doc of
//! `engine::actions::lane_follow`) on lane_follow.xosc: Car follows Ego's lane changes, Ego
//! follows Npc's and Truck's; Car's action is first in the storyboard. On straight_500m.xodr
//! lanes -1 and 1 are 3.07 m wide, centres t = -1.535 and +1.535 m, and a sinusoidal 2 s
//! change from `a` has weight f(τ) = (1 − cos(π·τ/2))/2 at τ s after its start (the frame at
//! the start shows weight 0).

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig};
use scenario::{ActionKind, FollowedLane, LateralAction, PrivateAction, Scenario};

use crate::runtime_support::{file, Recorder};

/// The road is straight along x: t is y, exact up to round-off.
const T_TOL: f64 = 1e-9;

/// The weight of a 2 s sinusoidal change started at `a`, at `t`.
fn f(a: f64, t: f64) -> f64 {
    (1.0 - (std::f64::consts::PI * (t - a).clamp(0.0, 2.0) / 2.0).cos()) / 2.0
}

/// lane_follow.xosc with Truck's change from `truck_start`, Ego following `ego` (in this
/// order) and Car following Ego: the frames.
fn run(truck_start: &str, ego: &[&str]) -> Recorder {
    let base = Scenario::load(&file("lane_follow.xosc")).expect("loads");
    let mut scenario = base
        .with_parameters(&[("TruckStart".to_string(), truck_start.to_string())])
        .expect("the parameter applies");
    let follow = |refs: &[&str]| {
        let refs = refs.iter().map(|x| FollowedLane {
            entity_ref: x.to_string(),
            value: 0,
        });
        ActionKind::Private(PrivateAction::Lateral(LateralAction::FollowLanes(
            refs.collect(),
        )))
    };
    let groups = &mut scenario.storyboard.stories[0].acts[0].maneuver_groups;
    groups[0].maneuvers[0].events[0].actions[0].kind = follow(&["Ego"]);
    groups[1].maneuvers[0].events[0].actions[0].kind = follow(ego);
    let network = load::road_network(&scenario).expect("road loads");
    let mut engine = Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::<engine::EventRecord>::new());
    engine.run(&mut frames, &mut events).expect("runs");
    frames
}

/// `name`'s t and lane at `t`.
fn place(frames: &Recorder, name: &str, t: f64) -> (f64, i32) {
    let road = frames.at(name, t).road.clone().unwrap_or_default();
    (road.3, road.1)
}

/// Npc's change from 1 s, Truck's from 2 s. Ego mirrors Npc's from 1 s: t = −1.535 +
/// 3.07·f(1, t), 0 at 2 s; Truck begins at 2 s and Ego takes its lane counted from Truck's new
/// one, -1, from where it is: t = (1 − f(2, t))·0 + f(2, t)·(−1.535) (−0.224796 m at 2.5 s,
/// −0.7675 m at 3 s, −1.535 m from 4 s, when Truck's change ends), the lane Truck's from 2 s.
/// Car, whose action comes before Ego's, steps its following after Ego's and so reads Ego's
/// lane and weight of the same step: its t is Ego's at every step (one step late it would be
/// −1.535 m at 1.05 s, where Ego is at −1.535 + 3.07·f(1, 1.05) = −1.530268 m).
#[test]
fn a_chain_follows_in_the_same_step_and_the_reference_that_just_began_takes_over() {
    let frames = run("1.99", &["Npc", "Truck"]);
    for k in 0..=100 {
        let t = 0.05 * f64::from(k);
        let npc = -1.535 + 3.07 * f(1.0, t);
        assert_abs_diff_eq!(place(&frames, "Npc", t).0, npc, epsilon = T_TOL);
        let ego = match t < 2.0 - 1e-9 {
            true => npc,
            false => -1.535 * f(2.0, t),
        };
        let (e, lane) = place(&frames, "Ego", t);
        assert_abs_diff_eq!(e, ego, epsilon = T_TOL);
        assert_abs_diff_eq!(place(&frames, "Car", t).0, ego, epsilon = T_TOL);
        if t > 2.0 + 1e-9 {
            assert_eq!(lane, -1, "{t}");
        }
    }
    // By hand.
    assert_abs_diff_eq!(place(&frames, "Car", 1.05).0, -1.530268, epsilon = 1e-6);
    assert_abs_diff_eq!(place(&frames, "Car", 1.5).0, -1.085409, epsilon = 1e-6);
    assert_abs_diff_eq!(place(&frames, "Ego", 2.5).0, -0.224796, epsilon = 1e-6);
    assert_abs_diff_eq!(place(&frames, "Car", 3.0).0, -0.7675, epsilon = 1e-9);
    let (car, lane) = place(&frames, "Car", 4.5);
    assert_abs_diff_eq!(car, -1.535, epsilon = T_TOL);
    assert_eq!(lane, -1);
}

/// Npc's and Truck's changes both from 1 s, into lanes 1 and -1: the references Ego follows
/// begin at once and disagree; Ego follows the first of its list: with [Npc, Truck] Npc's,
/// t = −1.535 + 3.07·f(1, t), in lane 1 from 2.05 s (1.535 m at 3 s); with [Truck, Npc] Truck's
/// new lane -1, its own: it stays at −1.535 m.
#[test]
fn references_that_begin_at_once_are_followed_in_the_lists_order() {
    let frames = run("0.99", &["Npc", "Truck"]);
    for k in 0..=100 {
        let t = 0.05 * f64::from(k);
        let npc = -1.535 + 3.07 * f(1.0, t);
        assert_abs_diff_eq!(place(&frames, "Ego", t).0, npc, epsilon = T_TOL);
        assert_abs_diff_eq!(place(&frames, "Car", t).0, npc, epsilon = T_TOL);
    }
    assert_eq!(place(&frames, "Ego", 3.0).1, 1);
    let frames = run("0.99", &["Truck", "Npc"]);
    for k in 0..=100 {
        let t = 0.05 * f64::from(k);
        assert_abs_diff_eq!(
            place(&frames, "Truck", t).0,
            1.535 - 3.07 * f(1.0, t),
            epsilon = T_TOL
        );
        let (ego, lane) = place(&frames, "Ego", t);
        assert_abs_diff_eq!(ego, -1.535, epsilon = T_TOL);
        assert_eq!(lane, -1, "{t}");
    }
}
