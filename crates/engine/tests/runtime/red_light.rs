//! Run option `stop_at_red_lights` (EngineConfig::stop_at_red_lights, engine signals/red_light.rs)
//! on `tests/files/signals/red_light.xosc`: light L at s = 100 (for +s traffic) is red for
//! t in [0, 20), green from 20; Ego drives +s at 10 m/s from s = 10 (x = s on this road).
//!
//! By hand: Ego's front is 1.4 + 4.5 / 2 = 3.65 m ahead of its reference point, so it stands
//! with the reference point at 100 − STOP_GAP (1 m) − 3.65 = 95.35. It begins to brake when
//! the comfortable braking distance v² / (2 · 3 m/s²) = 16.67 m reaches the distance to that
//! point, at s ≈ 78.68 (t ≈ 6.87 s), and stands after about v / a = 3.3 s more. From t = 20 it
//! accelerates at 2 m/s² (its maxAcceleration 5 is higher) back to 10 m/s, reached at t = 25
//! after 0.05 · (0.1 + 0.2 + … + 10) = 0.005 · 5050 = 25.25 m (the steps integrate the speed
//! at each step's end), so x(25) = 120.6 and x(30) = 170.6. Oncoming (lane 1, −s) meets the
//! light from behind and is not held: x = 200 − 10 t. Without the option Ego never brakes.

use crate::runtime_support;

use engine::runtime::TrafficModel;
use engine::{Engine, EngineConfig};
use runtime_support::Recorder;

/// Stop point of Ego's reference point (module doc).
const STOP_X: f64 = 95.35;
/// Positions integrate sums of f64 step lengths.
const EPS: f64 = 1e-6;

fn run(stop_at_red_lights: bool) -> Recorder {
    run_with(stop_at_red_lights, None)
}

/// The run with `vehicle_model` driving both vehicles (EngineConfig::vehicle_model).
fn run_with(stop_at_red_lights: bool, vehicle_model: Option<TrafficModel>) -> Recorder {
    run_on("red_light.xodr", stop_at_red_lights, vehicle_model)
}

/// The run on road file `road` (the scenario's parameter Road).
fn run_on(road: &str, stop_at_red_lights: bool, vehicle_model: Option<TrafficModel>) -> Recorder {
    let path = std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/signals/red_light.xosc"
    ));
    let config = EngineConfig {
        stop_at_red_lights,
        vehicle_model,
        ..EngineConfig::default()
    };
    let params = [("Road".to_owned(), road.to_owned())];
    let mut engine = Engine::load(&path, &params, config).expect("loads");
    let mut frames = Recorder::default();
    engine.run(&mut frames, &mut Vec::new()).expect("runs");
    frames
}

#[test]
fn with_the_option_a_vehicle_stops_before_a_red_light_and_drives_on_at_green() {
    let f = run(true);
    // Constant speed until braking begins (between 6.85 and 6.95 s, module doc).
    assert_eq!(f.at("Ego", 6.85).speed, 10.0);
    assert!((f.at("Ego", 6.85).x - 78.5).abs() < EPS);
    let braking = f.at("Ego", 8.0).speed;
    assert!(braking > 5.0 && braking < 8.0, "{braking}");
    // Never past the stop point while red; standing there from 11 s to the green at 20 s.
    for row in f.0.iter().filter(|r| r.name == "Ego" && r.time < 20.0) {
        assert!(row.x <= STOP_X + EPS, "t = {}: x = {}", row.time, row.x);
    }
    for t in [11.0, 15.0, 20.0] {
        let row = f.at("Ego", t);
        assert!(
            (row.x - STOP_X).abs() < EPS && row.speed == 0.0,
            "{t}: {row:?}"
        );
    }
    // Driving on at 2 m/s².
    assert!((f.at("Ego", 21.0).speed - 2.0).abs() < EPS);
    assert!((f.at("Ego", 25.0).speed - 10.0).abs() < EPS);
    assert!((f.at("Ego", 25.0).x - 120.6).abs() < EPS);
    assert!((f.at("Ego", 30.0).x - 170.6).abs() < EPS);
    // The light is not for Oncoming.
    for t in [5.0, 10.0, 15.0] {
        assert!((f.at("Oncoming", t).x - (200.0 - 10.0 * t)).abs() < EPS);
    }
}

#[test]
fn without_the_option_signals_do_not_change_the_motion() {
    let f = run(false);
    for t in [5.0, 10.0, 15.0] {
        assert!((f.at("Ego", t).x - (10.0 + 10.0 * t)).abs() < EPS);
        assert_eq!(f.at("Ego", t).speed, 10.0);
    }
}

/// The IDM stops for a red light as behind a standing vehicle at the signal (controller module
/// car_following, `with_red_light`): both vehicles on `idm` (default parameters, desired speed
/// 10 m/s from the Init SpeedAction). Ego can stop (10² / (2 · 8) = 6.25 m ≤ 86.35 m to the
/// light), so it brakes from the start (s* = 2 + 10 · 1.6 + 10 · 10 / (2 √(0.73 · 1.67)) =
/// 63.3 m against a gap of 86.35 m: a = −0.73 · (63.3 / 86.35)² = −0.39 m/s²) and comes to rest
/// with its front the IDM's minimum gap s0 = 2 m before the signal, reference point at
/// 100 − 2 − 3.65 = 94.35 (within the IDM model test's 0.3 m), never beyond it while red; at
/// green it drives on past the light. Oncoming (lane 1, −s) is not held: no leader, at its
/// desired speed, the IDM's acceleration is 0 and x = 200 − 10 t. Without the option the
/// IDM Ego never brakes: x = 10 + 10 t.
#[test]
fn with_the_option_an_idm_vehicle_stops_at_its_minimum_gap_before_a_red_light() {
    const IDM_STAND_X: f64 = 94.35;
    const IDM_GAP_TOLERANCE: f64 = 0.3;
    let f = run_with(true, Some(TrafficModel::Idm));
    assert!(
        f.at("Ego", 1.0).speed < 10.0 - 0.3,
        "braking from the start"
    );
    for row in f.0.iter().filter(|r| r.name == "Ego" && r.time < 20.0) {
        assert!(
            row.x <= IDM_STAND_X + IDM_GAP_TOLERANCE,
            "t = {}: x = {}",
            row.time,
            row.x
        );
    }
    let standing = f.at("Ego", 19.95);
    assert!(
        (standing.x - IDM_STAND_X).abs() < IDM_GAP_TOLERANCE && standing.speed < 0.1,
        "{standing:?}"
    );
    assert!(f.at("Ego", 30.0).x > 100.0, "drives on at green");
    for t in [5.0, 10.0, 15.0] {
        assert!((f.at("Oncoming", t).x - (200.0 - 10.0 * t)).abs() < EPS);
    }
    let free = run_with(false, Some(TrafficModel::Idm));
    for t in [5.0, 10.0, 15.0] {
        assert!((free.at("Ego", t).x - (10.0 + 10.0 * t)).abs() < EPS);
    }
}

/// red_light_validity.xodr: the same light for both directions (orientation "none") but only
/// for lane −1 (`<validity fromLane="-1" toLane="-1"/>`, OpenDRIVE 1.8 §14.2). Ego (lane −1)
/// stops exactly as on red_light.xodr (x = 95.35 from 11 s to 20 s); Oncoming (lane 1, −s)
/// would be held by orientation "none" alone, but its lane is outside the validity: it passes
/// the light at t = 10 s and x = 200 − 10 t throughout.
#[test]
fn a_light_with_lane_validity_holds_only_its_lanes() {
    let f = run_on("red_light_validity.xodr", true, None);
    for t in [11.0, 15.0, 19.95] {
        let row = f.at("Ego", t);
        assert!(
            (row.x - STOP_X).abs() < EPS && row.speed == 0.0,
            "{t}: {row:?}"
        );
    }
    for t in [5.0, 10.0, 15.0, 20.0] {
        assert!(
            (f.at("Oncoming", t).x - (200.0 - 10.0 * t)).abs() < EPS,
            "{t}"
        );
    }
}
