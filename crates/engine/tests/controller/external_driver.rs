//! The `external` controller driven with pedals, gear and steering wheel (issue 13: "pedal +
//! steering inputs (through `vehicle_dynamics`)"), as a library user drives it: only the public
//! API (`Engine::attach_external`, `Engine::set_external_input`, `ExternalInput::Driver`,
//! `models::single_track::DriverInputs`). Ego of idm_free_road.xosc: at rest on the straight
//! road along +x, Performance maxAcceleration = maxDeceleration = 10 m/s², wheelbase 2.98 m
//! (front axle positionX − rear), front axle maxSteering 0.5 rad; the vehicle model's steering
//! ratio is its default 15 (models/single_track.rs).

use std::path::PathBuf;

use engine::controller::ExternalInput;
use engine::models::single_track::{Brake, DriverInputs, GearSelection};
use engine::{Engine, EngineConfig};

/// Exact up to rounding: each phase has constant inputs, for which ballistic steps and arc
/// steps are exact.
const EXACT: f64 = 1e-9;

fn ego(engine: &Engine) -> (f64, f64, f64) {
    let e = engine.entity("Ego").expect("Ego is in the scene");
    (e.pose.x, e.speed, e.pose.h)
}

/// idm_free_road.xosc with Ego's `external` controller attached, after its first step.
fn attached() -> Engine {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/files/controller/idm_free_road.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    engine.attach_external("Ego").expect("attached");
    engine.step(&mut (), &mut ()).expect("init step");
    engine
}

fn steps(engine: &mut Engine, input: DriverInputs, n: usize) {
    engine
        .set_external_input("Ego", ExternalInput::Driver(input))
        .expect("Ego has an external controller");
    for _ in 0..n {
        engine.step(&mut (), &mut ()).expect("steps");
    }
}

/// Throttle 0.25 in `d` for 1 s (20 steps of 0.05 s): a = 0.25 · 10 = 2.5 m/s², v = 2.5 m/s,
/// x advances ½ · 2.5 · 1² = 1.25 m. Then no throttle, steering wheel 1.5 rad for 1 s: no
/// resistance in the model, so v stays 2.5 m/s; the front wheel angle δ = 1.5 / 15 = 0.1 rad,
/// the curvature κ = tan 0.1 / 2.98 = 0.100335 / 2.98 = 0.0336693 1/m, over 2.5 m the heading turns by
/// 0.0841733 rad (left). Then neutral with full throttle for 0.5 s: no drive, v stays. Then
/// BrakePercent 0.5: 5 m/s² stops it in 0.5 s, and it stays stopped (brakes never reverse).
#[test]
fn external_driver_inputs_drive_the_vehicle_model() {
    let mut engine = attached();
    let (x0, v0, h0) = ego(&engine);
    assert_eq!((v0, h0), (0.0, 0.0));

    let throttle = DriverInputs {
        throttle: 0.25,
        gear: GearSelection::Drive,
        ..DriverInputs::default()
    };
    steps(&mut engine, throttle, 20);
    let (x1, v1, h1) = ego(&engine);
    assert!((v1 - 2.5).abs() < EXACT, "{v1}");
    assert!((x1 - x0 - 1.25).abs() < EXACT, "{x1} from {x0}");
    assert!(h1.abs() < EXACT);

    let steer = DriverInputs {
        steering_wheel: 1.5,
        ..DriverInputs::default()
    };
    steps(&mut engine, steer, 20);
    let (_, v2, h2) = ego(&engine);
    assert!((v2 - 2.5).abs() < EXACT, "{v2}");
    let turn = 0.1_f64.tan() / 2.98 * 2.5;
    assert!((turn - 0.0841733).abs() < 1e-6);
    assert!((h2 - turn).abs() < EXACT, "heading {h2}, expected {turn}");

    let neutral = DriverInputs {
        throttle: 1.0,
        gear: GearSelection::Neutral,
        ..DriverInputs::default()
    };
    steps(&mut engine, neutral, 10);
    assert!((ego(&engine).1 - 2.5).abs() < EXACT);

    let brake = DriverInputs {
        brake: Brake::Percent(0.5),
        ..DriverInputs::default()
    };
    steps(&mut engine, brake, 9);
    // 0.45 s of 5 m/s²: 2.5 − 2.25 = 0.25 m/s left.
    assert!((ego(&engine).1 - 0.25).abs() < EXACT, "{}", ego(&engine).1);
    steps(&mut engine, brake, 11);
    assert_eq!(ego(&engine).1, 0.0);
}

/// The engine refuses inputs that are not finite or out of range, whichever binding gives
/// them (issue 33: `set_external_input` took NaN), and keeps the input in force: Ego, at
/// rest, told 2 m/s² and then given four bad inputs, is at 2 · 1 = 2 m/s after 1 s (20 steps
/// of 0.05 s).
#[test]
fn bad_external_inputs_are_refused_and_the_last_good_one_holds() {
    let mut engine = attached();
    let accelerate = ExternalInput::Acceleration {
        acceleration: 2.0,
        steering: None,
    };
    engine
        .set_external_input("Ego", accelerate)
        .expect("a good input");
    let bad = [
        (
            ExternalInput::Acceleration {
                acceleration: f64::NAN,
                steering: None,
            },
            "expected a finite acceleration, found NaN",
        ),
        (
            ExternalInput::Acceleration {
                acceleration: 1.0,
                steering: Some(f64::INFINITY),
            },
            "expected a finite steering, found inf",
        ),
        (
            ExternalInput::Driver(DriverInputs {
                throttle: 1.5,
                ..DriverInputs::default()
            }),
            "expected throttle in 0..1, found 1.5",
        ),
        (
            ExternalInput::Driver(DriverInputs {
                brake: Brake::Force(-1.0),
                ..DriverInputs::default()
            }),
            "expected a brake force of at least 0 N, found -1",
        ),
        (
            ExternalInput::Pose(opendrive::Pose {
                x: f64::NAN,
                ..opendrive::Pose::default()
            }),
            "expected a finite pose, found [NaN, 0.0, 0.0, 0.0, 0.0, 0.0]",
        ),
    ];
    for (input, message) in bad {
        let e = engine
            .set_external_input("Ego", input)
            .expect_err("refused");
        assert!(
            matches!(e.kind(), engine::ErrorKind::ExternalInput { .. }),
            "{e}"
        );
        assert_eq!(e.to_string(), message);
    }
    for _ in 0..20 {
        engine.step(&mut (), &mut ()).expect("steps");
    }
    let (_, v, _) = ego(&engine);
    assert!((v - 2.0).abs() < EXACT, "speed {v}");
}

/// A controller's command whose result overflows is caught by the step's guard with the same
/// error as before the guard moved into the moves' walk (issue 31): Ego, at rest at x0, is
/// given the pose x = 1.7e308 (finite) in the step from 0.05 s; its speed along the heading,
/// (1.7e308 − x0) / 0.05 s = 3.4e309 m/s, is beyond f64::MAX. The step is refused at
/// t = 0.10 s naming Ego's speed, the first state value (pose, then speed) that is not
/// finite.
#[test]
fn a_command_that_overflows_is_refused_with_the_guards_error() {
    let mut engine = attached();
    let far = opendrive::Pose {
        x: 1.7e308,
        ..opendrive::Pose::default()
    };
    engine
        .set_external_input("Ego", ExternalInput::Pose(far))
        .expect("a finite pose");
    let error = engine
        .step(&mut (), &mut ())
        .expect_err("the overflow is refused");
    assert!(matches!(error.kind(), engine::ErrorKind::NonFinite { .. }));
    assert_eq!(
        error.to_string(),
        "expected a finite speed of entity 'Ego' at t = 0.100 s, found inf (an overflow of \
         extreme values)"
    );
}
