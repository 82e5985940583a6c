//! The system under test in the loop: inputs for an entity driven by an `external`
//! controller (OpenSCENARIO 1.3 §6.6: "a vehicle is controlled by the system under test"), in
//! the three forms the engine takes (`engine::controller::ExternalInput`): an acceleration with
//! an optional front wheel angle, driver inputs (pedals and steering wheel through the
//! engine's vehicle model), or the pose at the end of the step.
//!
//! `Simulation.control(name, …)` builds the input from keyword arguments here; a Python
//! controller's `step` returns `oscsim.Acceleration`, `oscsim.Pedals` or `oscsim.Pose`, which
//! `oscsim.Simulation` (python/oscsim/__init__.py) turns into the same call.

use engine::controller::ExternalInput;
use engine::models::single_track::{Brake, DriverInputs, GearSelection};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::state::Pose;

/// The keyword arguments of `Simulation.control`.
#[derive(Debug, Default)]
pub struct Control {
    /// Acceleration along the direction of travel (m/s²).
    pub acceleration: Option<f64>,
    /// Front wheel angle (rad, positive left), with `acceleration`.
    pub steering: Option<f64>,
    /// Throttle pedal 0..1.
    pub throttle: Option<f64>,
    /// Brake pedal 0..1.
    pub brake: Option<f64>,
    /// Steering wheel angle (rad, positive left), with the pedals.
    pub steering_wheel: Option<f64>,
    /// The pose at the end of the step.
    pub pose: Option<Pose>,
}

impl Control {
    /// The engine input: exactly one of acceleration (with steering), pedals (throttle,
    /// brake, steering_wheel) or pose. Its values are checked by the engine
    /// (`ExternalInput::check`: finite numbers, pedals in 0..1), as for the C API.
    pub fn input(self) -> PyResult<ExternalInput> {
        let pedals =
            self.throttle.is_some() || self.brake.is_some() || self.steering_wheel.is_some();
        let forms = [self.acceleration.is_some(), pedals, self.pose.is_some()];
        if forms.iter().filter(|f| **f).count() != 1
            || (self.steering.is_some() && self.acceleration.is_none())
        {
            return Err(PyValueError::new_err(
                "expected one of: acceleration (with optional steering); throttle, brake, \
                 steering_wheel; pose",
            ));
        }
        if let Some(acceleration) = self.acceleration {
            return Ok(ExternalInput::Acceleration {
                acceleration,
                steering: self.steering,
            });
        }
        if let Some(pose) = self.pose {
            return Ok(ExternalInput::Pose(opendrive::Pose::from(pose)));
        }
        Ok(ExternalInput::Driver(DriverInputs {
            throttle: self.throttle.unwrap_or(0.0),
            brake: Brake::Percent(self.brake.unwrap_or(0.0)),
            steering_wheel: self.steering_wheel.unwrap_or(0.0),
            gear: GearSelection::Drive,
            ..DriverInputs::default()
        }))
    }
}
