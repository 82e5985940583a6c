//! `oscsim run --osi`: LightStateAction (OpenSCENARIO 1.3 XSD `LightStateAction`) in
//! `MovingObject.vehicle_classification.light_state` (OSI 3.8 osi_object.proto), mapped by the
//! table of `osi::lights`.
//!
//! `tests/files/osi_lights.xosc` switches Ego's lights in the steps at 0.5 s ("leftOn": left
//! indicator flashing, low beam on), 1 s ("warning": warning lights flashing, a blue flashing
//! special-purpose light, rear fog light on, brake lights on) and 1.5 s ("allOff": warning
//! lights, left indicator and low beam off). An action of the step at T shapes the frames
//! after T. Expected per frame, from the scenario text and the table:
//! - up to 0.5 s: no light_state (no light was set);
//! - to 1 s: indicator LEFT, head light ON, the rest unset;
//! - to 1.5 s: indicator WARNING, head light ON, emergency illumination FLASHING_BLUE, rear fog
//!   light ON, brake lights NORMAL;
//! - to 2 s: indicator OFF, head light OFF, the other three as before.

use crate::osi_common;

use std::path::Path;

use osi::osi3::moving_object::vehicle_classification::light_state::{
    BrakeLightState, GenericLightState as G, IndicatorState,
};
use osi::osi3::moving_object::vehicle_classification::LightState;
use osi::osi3::GroundTruth;
use osi_common::traced_run;

fn seconds(gt: &GroundTruth) -> f64 {
    let ts = gt.timestamp.expect("every frame has a timestamp");
    ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9
}

#[test]
fn light_state_actions_reach_the_vehicles_light_state() {
    let scenario = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/osi_lights.xosc");
    let (trace, _) = traced_run("osi_lights", &scenario, 2.0);
    assert_eq!(trace.len(), 41, "frames 0 to 2 s");

    let left = LightState {
        indicator_state: Some(IndicatorState::Left as i32),
        head_light: Some(G::On as i32),
        ..Default::default()
    };
    let warning = LightState {
        indicator_state: Some(IndicatorState::Warning as i32),
        emergency_vehicle_illumination: Some(G::FlashingBlue as i32),
        rear_fog_light: Some(G::On as i32),
        brake_light_state: Some(BrakeLightState::Normal as i32),
        ..left
    };
    let off = LightState {
        indicator_state: Some(IndicatorState::Off as i32),
        head_light: Some(G::Off as i32),
        ..warning
    };
    let slack = 1e-6;
    for gt in &trace {
        let t = seconds(gt);
        let ego = &gt.moving_object[0];
        assert_eq!(ego.source_reference[0].identifier[1], "Ego");
        let state = ego
            .vehicle_classification
            .as_ref()
            .expect("a vehicle has a classification")
            .light_state;
        let expected = if t <= 0.5 + slack {
            None
        } else if t <= 1.0 + slack {
            Some(left)
        } else if t <= 1.5 + slack {
            Some(warning)
        } else {
            Some(off)
        };
        assert_eq!(state, expected, "light_state at {t}");
    }
}
