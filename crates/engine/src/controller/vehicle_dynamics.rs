//! The `vehicle_dynamics` controller (OpenSCENARIO 1.3 §6.6; §7.7.2.5
//! OverrideControllerValueAction "overrides the output of a controller"): a driver and a
//! vehicle model ([`crate::models::single_track`]).
//!
//! Its driver does what the default controller does, through the pedals: it keeps the speed
//! the entity had when the controller was activated, or the one a SpeedAction on the
//! longitudinal domain asks for since (acceleration wanted = [`DRIVER_GAIN`] × speed error,
//! as throttle share of `maxAcceleration` or brake share of `maxDeceleration`), in gear `d`,
//! and it follows the lane as the default controller does. Each input an
//! OverrideControllerValueAction makes active replaces the driver's, with the action's
//! `maxRate` / `maxTorque`; a released input (`active="false"`) goes back to the driver. An
//! active brake or parking-brake override also takes the driver's foot off the throttle (a
//! brake pedal press ends cruise control). While the steering wheel is overridden the entity
//! leaves its lane and drives the arc of the single-track model; released, it keeps the lane
//! and offset it has then.
//!
//! The vehicle's constants: wheelbase = FrontAxle `positionX` − RearAxle `positionX`
//! (without a front axle, [`FALLBACK_WHEELBASE_SHARE`] of the box length), largest wheel angle
//! = FrontAxle `maxSteering`, `mass` (without one, [`FALLBACK_MASS`]), Performance limits;
//! `steeringRatio` and `steeringWheelInertia` from the controller's properties or the model's
//! defaults.

use opendrive::Real;
use scenario::{AutomaticGearType, BrakeInput, Gear};

use super::command::{Command, Controller, Lateral, Longitudinal, Strategy};
use super::view::ControllerView;
use crate::models::single_track::{
    Brake, DriverInputs, GearSelection, InputLimits, VehicleParameters, VehicleState,
    DEFAULT_STEERING_INERTIA, DEFAULT_STEERING_RATIO,
};
use crate::world::{ControllerOverrides, Entity};

/// Gain of the driver's speed keeping (1/s): the acceleration asked for per m/s of error.
pub const DRIVER_GAIN: Real = 1.0;
/// Wheelbase of a vehicle without a front axle, as a share of its box length.
pub const FALLBACK_WHEELBASE_SHARE: Real = 0.6;
/// Mass of a vehicle without one (kg), for BrakeForce inputs.
pub const FALLBACK_MASS: Real = 1500.0;
/// Largest front wheel angle without a front axle (rad).
pub const FALLBACK_MAX_STEERING: Real = 0.5;

/// The vehicle model's constants for `e` (module doc).
pub(crate) fn vehicle_parameters(
    e: &Entity,
    steering_ratio: Option<Real>,
    steering_inertia: Option<Real>,
) -> VehicleParameters {
    let front = e.axles.as_ref().and_then(|a| a.front_axle);
    let rear_x = e.axles.as_ref().map_or(0.0, |a| a.rear_axle.position_x);
    let wheelbase = front.map_or(FALLBACK_WHEELBASE_SHARE * e.bounding_box.length(), |f| {
        f.position_x - rear_x
    });
    let p = e.performance;
    VehicleParameters {
        wheelbase,
        max_steering: front.map_or(FALLBACK_MAX_STEERING, |f| f.max_steering),
        steering_ratio: steering_ratio.unwrap_or(DEFAULT_STEERING_RATIO),
        steering_inertia: steering_inertia.unwrap_or(DEFAULT_STEERING_INERTIA),
        mass: e.mass.unwrap_or(FALLBACK_MASS),
        max_speed: e.max_speed(),
        max_acceleration: p.map_or(Real::INFINITY, |p| p.max_acceleration),
        max_deceleration: p.map_or(Real::INFINITY, |p| p.max_deceleration),
        max_acceleration_rate: p.and_then(|p| p.max_acceleration_rate),
        max_deceleration_rate: p.and_then(|p| p.max_deceleration_rate),
    }
}

fn brake(input: BrakeInput) -> Brake {
    match input {
        BrakeInput::Force(f) => Brake::Force(f),
        BrakeInput::Percent(p) => Brake::Percent(p),
        _ => Brake::Percent(0.0),
    }
}

/// The gear an override selects.
pub(crate) fn gear(g: Gear) -> GearSelection {
    match g {
        Gear::Manual(n) => GearSelection::Manual(n),
        Gear::Automatic(AutomaticGearType::P) => GearSelection::Park,
        Gear::Automatic(AutomaticGearType::R) => GearSelection::Reverse,
        Gear::Automatic(AutomaticGearType::N) => GearSelection::Neutral,
        _ => GearSelection::Drive,
    }
}

/// `driver`'s inputs with the active overrides of `o` in their place, and the overrides'
/// rate limits; `true` when the steering wheel is overridden.
pub(crate) fn overridden(
    driver: DriverInputs,
    o: &ControllerOverrides,
) -> (DriverInputs, InputLimits, bool) {
    let mut inputs = driver;
    let mut limits = InputLimits::default();
    if let Some(t) = o.throttle.filter(|t| t.active) {
        inputs.throttle = t.value;
        limits.throttle_rate = t.max_rate;
    }
    let mut braking = false;
    if let Some(b) = o.brake.filter(|b| b.active) {
        inputs.brake = brake(b.input);
        limits.brake_rate = b.max_rate;
        braking = true;
    }
    if let Some(b) = o.parking_brake.filter(|b| b.active) {
        inputs.parking_brake = brake(b.input);
        limits.parking_brake_rate = b.max_rate;
        braking = true;
    }
    if braking && o.throttle.filter(|t| t.active).is_none() {
        inputs.throttle = 0.0;
    }
    if let Some(c) = o.clutch.filter(|c| c.active) {
        inputs.clutch = c.value;
        limits.clutch_rate = c.max_rate;
    }
    if let Some(g) = o.gear.filter(|g| g.active) {
        inputs.gear = gear(g.gear);
    }
    let steering = o.steering_wheel.filter(|s| s.active);
    if let Some(s) = steering {
        inputs.steering_wheel = s.value;
        limits.steering_rate = s.max_rate;
        limits.steering_torque = s.max_torque;
    }
    (inputs, limits, steering.is_some())
}

/// The `vehicle_dynamics` controller.
#[derive(Debug, Clone)]
pub struct VehicleDynamicsController {
    steering_ratio: Option<Real>,
    steering_inertia: Option<Real>,
    params: Option<VehicleParameters>,
    state: VehicleState,
    /// The speed the driver keeps (m/s).
    reference: Real,
}

impl VehicleDynamicsController {
    /// A controller with the optional `steeringRatio` and `steeringWheelInertia`.
    pub fn new(steering_ratio: Option<Real>, steering_inertia: Option<Real>) -> Self {
        VehicleDynamicsController {
            steering_ratio,
            steering_inertia,
            params: None,
            state: VehicleState::default(),
            reference: 0.0,
        }
    }

    /// The driver's own inputs: pedals for the reference speed, gear d, no steering.
    fn driver(&self, p: &VehicleParameters, v: Real) -> DriverInputs {
        let wanted = DRIVER_GAIN * (self.reference - v);
        DriverInputs {
            throttle: (wanted / p.max_acceleration).clamp(0.0, 1.0),
            brake: Brake::Percent((-wanted / p.max_deceleration).clamp(0.0, 1.0)),
            gear: GearSelection::Drive,
            ..DriverInputs::default()
        }
    }

    /// Steps the vehicle from the view's entity with `driver`'s inputs (the host's, for
    /// `external`), else its own driver's, after the overrides. The host's steering wheel
    /// steers; its own driver does not steer (the lane is kept) unless the wheel is overridden.
    pub(crate) fn drive(
        &mut self,
        view: &ControllerView<'_>,
        driver: Option<DriverInputs>,
        dt: Real,
    ) -> Command {
        let e = view.entity();
        let p = *self.params.get_or_insert_with(|| {
            vehicle_parameters(e, self.steering_ratio, self.steering_inertia)
        });
        let host = driver.is_some();
        let own = driver.unwrap_or_else(|| self.driver(&p, e.speed));
        let (inputs, limits, overridden_wheel) = overridden(own, &e.overrides);
        let steered = host || overridden_wheel;
        let m = p.step(&mut self.state, &inputs, &limits, e.speed, dt);
        Command::Motion {
            longitudinal: Some(Longitudinal::Motion {
                speed: m.speed,
                distance: m.distance,
                acceleration: m.acceleration,
            }),
            lateral: steered.then_some(Lateral::Curvature(m.curvature)),
        }
    }
}

impl Controller for VehicleDynamicsController {
    fn model(&self) -> &'static str {
        "vehicle_dynamics"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        let e = view.entity();
        self.params = Some(vehicle_parameters(
            e,
            self.steering_ratio,
            self.steering_inertia,
        ));
        self.reference = e.speed;
        self.state = VehicleState::default();
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        let Strategy::Speed(v) = strategy else {
            return None;
        };
        self.reference = v;
        Some(format!("driver keeps {v} m/s"))
    }

    fn step(&mut self, view: &ControllerView<'_>, dt: Real) -> Command {
        self.drive(view, None, dt)
    }
}
