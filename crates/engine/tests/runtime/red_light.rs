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

use engine::{Engine, EngineConfig};
use runtime_support::Recorder;

/// Stop point of Ego's reference point (module doc).
const STOP_X: f64 = 95.35;
/// Positions integrate sums of f64 step lengths.
const EPS: f64 = 1e-6;

fn run(stop_at_red_lights: bool) -> Recorder {
    let path = std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/signals/red_light.xosc"
    ));
    let config = EngineConfig {
        stop_at_red_lights,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(&path, &[], config).expect("loads");
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
