//! OverrideControllerValueAction (OpenSCENARIO 1.3 §7.7.2.5, XSD
//! `OverrideControllerValueAction`): the overrides are kept per input on the entity, each
//! change is in the event log, and the default controller's motion is unchanged (the standard
//! maps none of the inputs to motion; actions/override_controller.rs).
//!
//! tests/files/sync/override_values.xosc: Ego drives at 10 m/s; at 1 s one action releases the
//! throttle and overrides brake (50 %), clutch (0.25), parking brake (800 N), steering wheel
//! (0.1 rad) and gear (manual 2); at 2 s another releases brake and parking brake only.

use crate::runtime_support;

use engine::output::EventRecord;
use scenario::{BrakeInput, Gear};

/// The changes logged for Ego, with their times.
fn changes(events: &[EventRecord]) -> Vec<(f64, String)> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Entity {
                time,
                entity,
                change,
                ..
            } if entity == "Ego" => Some((*time, change.clone())),
            _ => None,
        })
        .collect()
}

#[test]
fn overrides_are_recorded_per_input_and_logged() {
    let (engine, frames, events) = runtime_support::run("../sync/override_values.xosc");
    let logged = changes(&events);
    let texts: Vec<&str> = logged.iter().map(|(_, c)| c.as_str()).collect();
    assert_eq!(
        texts,
        [
            "override throttle off",
            "override brake on 0.5",
            "override clutch on 0.25",
            "override parkingBrake on 800 N",
            "override steeringWheel on 0.1 rad",
            "override gear on manual 2",
            "override brake off",
            "override parkingBrake off",
        ]
    );
    // The first six at the first step with t ≥ 1 s, the last two at the first with t ≥ 2 s
    // (one step, 0.05 s, of storyboard latency allowed).
    for (time, change) in &logged {
        let due = if change.ends_with("off") && !change.contains("throttle") {
            2.0
        } else {
            1.0
        };
        assert!(
            *time >= due - 1e-9 && *time <= due + 0.05 + 1e-9,
            "{change} at {time}"
        );
    }
    // The state after the run: the second action released brake and parking brake and left
    // the other inputs as the first set them.
    let ego = engine.entity("Ego").expect("in the scene").overrides;
    let brake = ego.brake.map(|b| (b.active, b.input));
    assert_eq!(brake, Some((false, BrakeInput::Percent(0.0))));
    assert_eq!(ego.parking_brake.map(|b| b.active), Some(false));
    assert_eq!(ego.throttle.map(|t| t.active), Some(false));
    let clutch = ego.clutch.map(|c| (c.active, c.value));
    assert_eq!(clutch, Some((true, 0.25)));
    let steering = ego
        .steering_wheel
        .map(|s| (s.active, s.value, s.max_torque));
    assert_eq!(steering, Some((true, 0.1, Some(3.0))));
    assert_eq!(
        ego.gear.map(|g| (g.active, g.gear)),
        Some((true, Gear::Manual(2)))
    );
    // No effect on motion: 10 m/s throughout, so x = 50 + 10·t on the straight road (x = s).
    for row in frames.0.iter().filter(|r| r.name == "Ego") {
        assert!((row.speed - 10.0).abs() < 1e-12, "speed {}", row.speed);
        assert!(
            (row.x - (50.0 + 10.0 * row.time)).abs() < 1e-9,
            "x {}",
            row.x
        );
    }
}
