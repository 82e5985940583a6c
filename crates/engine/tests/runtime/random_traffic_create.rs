//! oscsim's creation of random traffic (`PrivateAction::CreateRandomTraffic`, no XML form;
//! module doc of `engine::actions::random_traffic`). speed_shapes.xosc puts Ego (5 m box,
//! centre 1.4 m ahead of its reference point: front 3.9 m, rear 1.1 m) in lane -1 of road 1 at
//! s = 100 m at 10 m/s and starts its action "Speed" at t = 1 s (Ego then at s = 110 m);
//! here that action is replaced by the creation, and members A, B, C (copies of Ego with no
//! Init: out of the world until created) are added to the model. Members at 10 m/s with Ego's
//! 10 m/s: the gap s0 + v_max·T = 2 + 1.6·10 = 18 m.

use approx::assert_abs_diff_eq;
use engine::{load, Engine, EngineConfig, EventRecord};
use scenario::traffic_deal::LaneSpan;
use scenario::{ActionKind, PrivateAction, RandomTrafficCreation, Scenario};

use crate::runtime_support::{file, Recorder};

/// Sums of a few metres (m).
const EXACT: f64 = 1e-9;

/// speed_shapes.xosc with members `names` and its action "Speed" made a creation of them at
/// 10 m/s over lane -1 from `from` to `to` (m).
fn scenario(names: &[&str], from: f64, to: f64) -> Scenario {
    let lane = |lane| LaneSpan {
        against: false,
        lane,
        from,
        to,
    };
    creating(names, vec![lane(-1)], None)
}

/// speed_shapes.xosc with members `names` and its action "Speed" made a creation of them at
/// 10 m/s over `lanes`, `beside` another entity.
fn creating(names: &[&str], lanes: Vec<LaneSpan>, beside: Option<(String, i64)>) -> Scenario {
    let mut scenario = Scenario::load(&file("speed_shapes.xosc")).expect("loads");
    let ego = scenario.entities.scenario_objects[0].clone();
    for n in names {
        let mut m = ego.clone();
        m.name = (*n).to_string();
        scenario.entities.scenario_objects.push(m);
    }
    let speed = scenario.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0]
        .actions
        .iter_mut()
        .find(|a| a.name == "Speed")
        .expect("the action Speed");
    speed.kind = ActionKind::Private(PrivateAction::CreateRandomTraffic(Box::new(
        RandomTrafficCreation {
            group: "g".into(),
            members: names.iter().map(|n| ((*n).to_string(), 10.0)).collect(),
            roads: vec![("1".into(), 0.0)],
            length: 500.0,
            lanes,
            beside,
            seed: 7,
        },
    )));
    scenario
}

fn run(scenario: &Scenario) -> (Recorder, Vec<EventRecord>, Option<engine::Error>) {
    let network = load::road_network(scenario).expect("road loads");
    let mut engine = Engine::new(scenario, network, EngineConfig::default()).expect("builds");
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    let error = engine.run(&mut frames, &mut events).err();
    (frames, events, error)
}

/// Lane and s of `name` in the frame at `t`.
fn place(frames: &Recorder, name: &str, t: f64) -> (i32, f64) {
    let r = frames.at(name, t);
    r.road.as_ref().map_or((0, f64::NAN), |r| (r.1, r.2))
}

/// Lane -1 over [0, 28] m holds two 5 m members 18 m apart and nothing more: no slack, so
/// A's rear at 0 (s = 1.1 m) and B's at 23 m (s = 24.1 m), shown from the frame of 1.05 s (at
/// rest: no SpeedAction here), and in no frame before 1 s.
#[test]
fn members_fill_a_stretch_with_no_slack_at_the_gap() {
    let (frames, _, error) = run(&scenario(&["A", "B"], 0.0, 28.0));
    assert!(error.is_none(), "{error:?}");
    assert!(!frames
        .0
        .iter()
        .any(|r| r.name == "A" && r.time < 1.0 - 1e-9));
    let (a, b) = (place(&frames, "A", 1.05), place(&frames, "B", 1.05));
    assert_eq!((a.0, b.0), (-1, -1));
    assert_abs_diff_eq!(a.1, 1.1, epsilon = EXACT);
    assert_abs_diff_eq!(b.1, 24.1, epsilon = EXACT);
    assert_abs_diff_eq!(frames.at("A", 1.05).speed, 0.0, epsilon = EXACT);
}

/// Lane -1 over [80, 150] m with Ego's box at [108.9, 113.9] m when the creation starts: the
/// free stretches [80, 90.9] and [131.9, 150] m, each room for one member (two need
/// 5 + 18 + 5 = 28 m). One member lies wholly within one of them.
#[test]
fn members_keep_the_gap_from_where_the_others_are_when_it_starts() {
    let (frames, _, error) = run(&scenario(&["A"], 80.0, 150.0));
    assert!(error.is_none(), "{error:?}");
    let (_, s) = place(&frames, "A", 1.05);
    let (rear, front) = (s - 1.1, s + 3.9);
    let within = |a: f64, b: f64| rear >= a - EXACT && front <= b + EXACT;
    assert!(
        within(80.0, 90.9) || within(131.9, 150.0),
        "A at {rear}..{front}"
    );
}

/// Three members there: room for two, then the error, recorded at 1 s, fails the run.
#[test]
fn no_room_when_it_starts_fails_the_run() {
    let (_, events, error) = run(&scenario(&["A", "B", "C"], 80.0, 150.0));
    let error = error.expect("fails");
    let want = "expected room on the plan's driving lanes for the 3 members of random traffic `g` (each its length plus a gap of 18.0 m to the next vehicle: s0 + v·T at the fastest start speed 10.00 m/s), found room for 2";
    assert!(error.to_string().starts_with(want), "{error}");
    assert!(events
        .iter()
        .any(|e| matches!(e, EventRecord::Error { time, message, .. }
        if (time - 1.0).abs() < EXACT && message.starts_with(want))));
}

/// Beside Ego (lane -1 of road 1, driven in +s) with lane -1 over [0, 28] m and lane 1
/// (driven in −s) over u in [0, 28] m offered: `same_as` (0 lanes) keeps lane -1 only, where
/// A and B fill [0, 28] m exactly as above; one lane to Ego's left (towards the centre line)
/// is lane 0, no driving lane: the error, at 1 s.
#[test]
fn beside_an_entity_the_lane_is_read_from_where_it_is_when_it_starts() {
    let lanes = vec![
        LaneSpan {
            against: false,
            lane: -1,
            from: 0.0,
            to: 28.0,
        },
        LaneSpan {
            against: true,
            lane: 1,
            from: 0.0,
            to: 28.0,
        },
    ];
    let (frames, _, error) = run(&creating(
        &["A", "B"],
        lanes.clone(),
        Some(("Ego".into(), 0)),
    ));
    assert!(error.is_none(), "{error:?}");
    let (a, b) = (place(&frames, "A", 1.05), place(&frames, "B", 1.05));
    assert_eq!((a.0, b.0), (-1, -1));
    assert_abs_diff_eq!(a.1, 1.1, epsilon = EXACT);
    assert_abs_diff_eq!(b.1, 24.1, epsilon = EXACT);
    let (_, _, error) = run(&creating(&["A"], lanes, Some(("Ego".into(), 1))));
    let error = error.expect("fails");
    assert!(
        error.to_string().starts_with("expected a driving lane 1 lanes to the left of 'Ego''s lane -1 for random traffic `g`, found none there"),
        "{error}"
    );
}

/// Lane 1 (driven in −s) over u in [0, 28] m, u = 500 − s on the 500 m road: A's reference
/// point at u = 1.1 m (s = 498.9 m), B's at u = 24.1 m (s = 475.9 m), both facing −s.
#[test]
fn members_in_a_lane_driven_against_s_are_placed_at_s_of_l_less_u() {
    let lanes = vec![LaneSpan {
        against: true,
        lane: 1,
        from: 0.0,
        to: 28.0,
    }];
    let (frames, _, error) = run(&creating(&["A", "B"], lanes, None));
    assert!(error.is_none(), "{error:?}");
    let (a, b) = (place(&frames, "A", 1.05), place(&frames, "B", 1.05));
    assert_eq!((a.0, b.0), (1, 1));
    assert_abs_diff_eq!(a.1, 498.9, epsilon = EXACT);
    assert_abs_diff_eq!(b.1, 475.9, epsilon = EXACT);
    let h = frames.at("A", 1.05).h;
    assert_abs_diff_eq!(h.cos(), -1.0, epsilon = 1e-9);
}
