//! OpenSCENARIO vehicle lights → ASAM OSI 3.8 `MovingObject.VehicleClassification.LightState`
//! (osi_object.proto).
//!
//! The input is what LightStateAction set (OpenSCENARIO 1.3 XSD `LightStateAction`,
//! `VehicleLight/@vehicleLightType`, `LightState/@mode`, `Color/@colorType`), one
//! [`VehicleLight`] per light an action touched; lights no action touched leave their OSI field
//! unset (unknown). The mapping, light by light:
//!
//! | OpenSCENARIO `vehicleLightType` | OSI field |
//! | --- | --- |
//! | `lowBeam` | `head_light` |
//! | `highBeam` | `high_beam` |
//! | `fogLights` | `front_fog_light` and `rear_fog_light` |
//! | `fogLightsFront` / `fogLightsRear` | `front_fog_light` / `rear_fog_light` |
//! | `reversingLights` | `reversing_light` |
//! | `licensePlateIllumination` | `license_plate_illumination_rear` |
//! | `brakeLights` | `brake_light_state`: on `NORMAL`, off `OFF`, flashing `OTHER` |
//! | `indicatorLeft`, `indicatorRight`, `warningLights` | `indicator_state` (below) |
//! | `specialPurposeLights` | a blue light `emergency_vehicle_illumination`, an amber (orange, yellow) one `service_vehicle_illumination` ("lighting of emergency / service vehicles"), else `emergency_vehicle_illumination` |
//! | `daytimeRunningLights`, user-defined lights | no OSI 3.8 field: left out |
//!
//! A generic light is `ON` or `OFF` by its mode; `flashing` is `FLASHING_BLUE` or
//! `FLASHING_AMBER` for a blue or amber (orange, yellow) light, else `OTHER` (OSI has no plain
//! flashing state). `indicator_state`: `WARNING` while the warning lights are on or flashing
//! (or both indicators are), else `LEFT` or `RIGHT` for the one indicator on or flashing, else
//! `OFF` once any of the three was set.

use crate::osi3::moving_object::vehicle_classification::light_state::{
    BrakeLightState, GenericLightState, IndicatorState,
};
use crate::osi3::moving_object::vehicle_classification::LightState;

/// `LightState/@mode` (XSD `LightMode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LightMode {
    /// `on`.
    On,
    /// `off`.
    Off,
    /// `flashing`.
    Flashing,
}

/// One light's state as a LightStateAction set it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct VehicleLight<'a> {
    /// `vehicleLightType` as written in the XSD (e.g. `lowBeam`), or a user-defined type.
    pub light: &'a str,
    /// The mode.
    pub mode: LightMode,
    /// `Color/@colorType` (e.g. `blue`), if the state gives a colour.
    pub color_type: Option<&'a str>,
}

/// Whether a colour type reads as amber in OSI's light states.
fn amber(color_type: Option<&str>) -> bool {
    matches!(color_type, Some("orange" | "yellow"))
}

/// A generic light's OSI state (module doc).
fn generic(l: &VehicleLight<'_>) -> GenericLightState {
    match l.mode {
        LightMode::On => GenericLightState::On,
        LightMode::Off => GenericLightState::Off,
        LightMode::Flashing if l.color_type == Some("blue") => GenericLightState::FlashingBlue,
        LightMode::Flashing if amber(l.color_type) => GenericLightState::FlashingAmber,
        LightMode::Flashing => GenericLightState::Other,
    }
}

/// The OSI light state of `lights` (module doc); `None` when no light maps to OSI.
pub fn light_state(lights: &[VehicleLight<'_>]) -> Option<LightState> {
    light_state_of(lights.iter().copied())
}

/// [`light_state`] of the lights an iterator gives (no list to build per frame).
pub fn light_state_of<'a>(
    lights: impl IntoIterator<Item = VehicleLight<'a>>,
) -> Option<LightState> {
    let mut state = LightState::default();
    let mut any = false;
    let (mut left, mut right, mut warning) = (None, None, None);
    for l in lights {
        let l = &l;
        let value = Some(generic(l) as i32);
        let lit = l.mode != LightMode::Off;
        match l.light {
            "lowBeam" => state.head_light = value,
            "highBeam" => state.high_beam = value,
            "fogLights" => {
                state.front_fog_light = value;
                state.rear_fog_light = value;
            }
            "fogLightsFront" => state.front_fog_light = value,
            "fogLightsRear" => state.rear_fog_light = value,
            "reversingLights" => state.reversing_light = value,
            "licensePlateIllumination" => state.license_plate_illumination_rear = value,
            "brakeLights" => {
                state.brake_light_state = Some(match l.mode {
                    LightMode::On => BrakeLightState::Normal,
                    LightMode::Off => BrakeLightState::Off,
                    LightMode::Flashing => BrakeLightState::Other,
                } as i32);
            }
            "specialPurposeLights" if amber(l.color_type) => {
                state.service_vehicle_illumination = value;
            }
            "specialPurposeLights" => state.emergency_vehicle_illumination = value,
            "indicatorLeft" => left = Some(lit),
            "indicatorRight" => right = Some(lit),
            "warningLights" => warning = Some(lit),
            _ => continue,
        }
        any = true;
    }
    if left.is_some() || right.is_some() || warning.is_some() {
        let (l, r, w) = (
            left == Some(true),
            right == Some(true),
            warning == Some(true),
        );
        state.indicator_state = Some(match (w || (l && r), l, r) {
            (true, _, _) => IndicatorState::Warning,
            (false, true, _) => IndicatorState::Left,
            (false, _, true) => IndicatorState::Right,
            _ => IndicatorState::Off,
        } as i32);
        any = true;
    }
    any.then_some(state)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn light(
        light: &'static str,
        mode: LightMode,
        color_type: Option<&'static str>,
    ) -> VehicleLight<'static> {
        VehicleLight {
            light,
            mode,
            color_type,
        }
    }

    /// Each row of the module doc's table, one light at a time.
    #[test]
    fn each_light_goes_to_its_field() {
        let one = |l: VehicleLight<'_>| light_state(&[l]).expect("maps");
        let on = Some(GenericLightState::On as i32);
        let off = Some(GenericLightState::Off as i32);
        assert_eq!(one(light("lowBeam", LightMode::On, None)).head_light, on);
        assert_eq!(one(light("highBeam", LightMode::Off, None)).high_beam, off);
        let fog = one(light("fogLights", LightMode::On, None));
        assert_eq!((fog.front_fog_light, fog.rear_fog_light), (on, on));
        let rear = one(light("fogLightsRear", LightMode::On, None));
        assert_eq!((rear.front_fog_light, rear.rear_fog_light), (None, on));
        assert_eq!(
            one(light("reversingLights", LightMode::On, None)).reversing_light,
            on
        );
        assert_eq!(
            one(light("licensePlateIllumination", LightMode::On, None))
                .license_plate_illumination_rear,
            on
        );
        assert_eq!(
            one(light("brakeLights", LightMode::On, None)).brake_light_state,
            Some(BrakeLightState::Normal as i32)
        );
        let blue = one(light(
            "specialPurposeLights",
            LightMode::Flashing,
            Some("blue"),
        ));
        assert_eq!(
            blue.emergency_vehicle_illumination,
            Some(GenericLightState::FlashingBlue as i32)
        );
        let amber = one(light(
            "specialPurposeLights",
            LightMode::Flashing,
            Some("orange"),
        ));
        assert_eq!(
            (
                amber.service_vehicle_illumination,
                amber.emergency_vehicle_illumination
            ),
            (Some(GenericLightState::FlashingAmber as i32), None)
        );
        let white = one(light("fogLightsFront", LightMode::Flashing, Some("white")));
        assert_eq!(white.front_fog_light, Some(GenericLightState::Other as i32));
        assert!(light_state(&[light("daytimeRunningLights", LightMode::On, None)]).is_none());
        assert!(light_state(&[]).is_none());
    }

    /// Warning lights win over the indicators; one indicator gives its side; all off is OFF.
    #[test]
    fn indicators_combine_into_one_state() {
        let state =
            |lights: &[VehicleLight<'_>]| light_state(lights).and_then(|s| s.indicator_state);
        let left = light("indicatorLeft", LightMode::Flashing, None);
        let right = light("indicatorRight", LightMode::Flashing, None);
        let right_off = light("indicatorRight", LightMode::Off, None);
        let warning = light("warningLights", LightMode::Flashing, None);
        let warning_off = light("warningLights", LightMode::Off, None);
        assert_eq!(state(&[left]), Some(IndicatorState::Left as i32));
        assert_eq!(state(&[right]), Some(IndicatorState::Right as i32));
        assert_eq!(state(&[left, right]), Some(IndicatorState::Warning as i32));
        assert_eq!(
            state(&[right, warning]),
            Some(IndicatorState::Warning as i32)
        );
        assert_eq!(
            state(&[left, warning_off]),
            Some(IndicatorState::Left as i32)
        );
        assert_eq!(
            state(&[right_off, warning_off]),
            Some(IndicatorState::Off as i32)
        );
    }
}
