//! Controller-value overrides and appearance (OpenSCENARIO 1.3, "Actions", XSD
//! `OverrideControllerValueAction`, `LightStateAction`, `AnimationAction`).

use crate::model::{
    AutomaticGearType, ColorType, LightMode, PedestrianGestureType, PedestrianMotionType,
    VehicleComponentType, VehicleLightType,
};

/// Overrides of driver inputs (XSD `OverrideControllerValueAction`); each present part
/// activates (or releases, `active = false`) one input.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct OverrideControllerValueAction {
    /// Throttle pedal, 0..1.
    pub throttle: Option<PedalOverride>,
    /// Brake: percent (0..1) or force (N).
    pub brake: Option<BrakeOverride>,
    /// Clutch pedal, 0..1.
    pub clutch: Option<PedalOverride>,
    /// Parking brake.
    pub parking_brake: Option<BrakeOverride>,
    /// Steering wheel angle, rad (max rate rad/s, max torque N·m).
    pub steering_wheel: Option<SteeringOverride>,
    /// Gear.
    pub gear: Option<GearOverride>,
}

/// A pedal override (XSD `OverrideThrottleAction`, `OverrideClutchAction`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PedalOverride {
    /// Active.
    pub active: bool,
    /// Pedal position, 0..1.
    pub value: f64,
    /// Maximum rate, 1/s (1.2+).
    pub max_rate: Option<f64>,
}

/// A brake override (XSD `OverrideBrakeAction`, `OverrideParkingBrakeAction`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrakeOverride {
    /// Active.
    pub active: bool,
    /// The input (the deprecated `value` reads as a percentage).
    pub input: BrakeInput,
    /// Maximum rate, 1/s or N/s (1.2+).
    pub max_rate: Option<f64>,
}

/// Brake input (XSD group `BrakeInput`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum BrakeInput {
    /// BrakePercent, 0..1.
    Percent(f64),
    /// BrakeForce, N.
    Force(f64),
}

/// A steering override (XSD `OverrideSteeringWheelAction`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringOverride {
    /// Active.
    pub active: bool,
    /// Steering wheel angle, rad.
    pub value: f64,
    /// rad/s.
    pub max_rate: Option<f64>,
    /// N·m.
    pub max_torque: Option<f64>,
}

/// A gear override (XSD `OverrideGearAction`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearOverride {
    /// Active.
    pub active: bool,
    /// The gear (the deprecated `number` reads as a manual gear).
    pub gear: Gear,
}

/// A gear (XSD group `Gear`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Gear {
    /// ManualGear number (negative: reverse).
    Manual(i32),
    /// AutomaticGear selector.
    Automatic(AutomaticGearType),
}

/// LightStateAction (XSD `LightStateAction`, 1.2+).
#[derive(Debug, Clone, PartialEq)]
pub struct LightStateAction {
    /// The light: a VehicleLight type or a user-defined name.
    pub light_type: LightKind,
    /// LightState.
    pub light_state: LightState,
    /// Transition time, s.
    pub transition_time: Option<f64>,
}

/// A light (XSD `LightType`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LightKind {
    /// VehicleLight.
    Vehicle(VehicleLightType),
    /// UserDefinedLight type.
    UserDefined(String),
}

/// A light state (XSD `LightState`).
#[derive(Debug, Clone, PartialEq)]
pub struct LightState {
    /// Mode.
    pub mode: LightMode,
    /// Luminous intensity, cd.
    pub luminous_intensity: Option<f64>,
    /// Flashing on time, s.
    pub flashing_on_duration: Option<f64>,
    /// Flashing off time, s.
    pub flashing_off_duration: Option<f64>,
    /// Colour.
    pub color: Option<Color>,
}

/// A colour (XSD `Color`).
#[derive(Debug, Clone, PartialEq)]
pub struct Color {
    /// colorType.
    pub color_type: ColorType,
    /// ColorRgb (0..1 each) or ColorCmyk (0..1 each).
    pub value: ColorValue,
}

/// A colour value (XSD `Color` choice).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum ColorValue {
    /// ColorRgb.
    Rgb {
        /// 0..1.
        red: f64,
        /// 0..1.
        green: f64,
        /// 0..1.
        blue: f64,
    },
    /// ColorCmyk.
    Cmyk {
        /// 0..1.
        cyan: f64,
        /// 0..1.
        magenta: f64,
        /// 0..1.
        yellow: f64,
        /// 0..1.
        key: f64,
    },
}

/// AnimationAction (XSD `AnimationAction`, 1.2+).
#[derive(Debug, Clone, PartialEq)]
pub struct AnimationAction {
    /// The animation.
    pub animation_type: AnimationType,
    /// Loop.
    pub looping: Option<bool>,
    /// Duration, s.
    pub animation_duration: Option<f64>,
    /// AnimationState: target state 0..1.
    pub state: Option<f64>,
}

/// Kinds of animation (XSD `AnimationType`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum AnimationType {
    /// ComponentAnimation of a vehicle component.
    VehicleComponent(VehicleComponentType),
    /// ComponentAnimation of a user-defined component.
    UserDefinedComponent(String),
    /// PedestrianAnimation: motion and gestures.
    Pedestrian {
        /// Motion.
        motion: Option<PedestrianMotionType>,
        /// User-defined animation name.
        user_defined: Option<String>,
        /// Gestures.
        gestures: Vec<PedestrianGestureType>,
    },
    /// AnimationFile: path and time offset, s.
    File {
        /// Path as written.
        filepath: String,
        /// s.
        time_offset: Option<f64>,
    },
    /// UserDefinedAnimation type.
    UserDefined(String),
}
