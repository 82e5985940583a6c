//! The `external` controller (OpenSCENARIO 1.3 §6.6: "specifying that a vehicle is
//! controlled by the system under test"): the host program drives the entity through the
//! library API. Before each [`Engine::step`](crate::Engine::step) it reads the world and may
//! give the entity an [`ExternalInput`] with
//! [`Engine::set_external_input`](crate::Engine::set_external_input):
//!
//! - [`ExternalInput::Pose`]: where the entity is at the end of the step (both domains; the
//!   speed is the distance moved per step along the heading, the road position is looked up);
//! - [`ExternalInput::Acceleration`]: an acceleration along the direction of travel, and a
//!   front wheel angle (single-track model on the entity's axles), or none to keep the lane as
//!   the default controller does;
//! - [`ExternalInput::Driver`]: pedals, gear and steering wheel through the vehicle model of
//!   `vehicle_dynamics` (module `vehicle_dynamics`; the scenario's
//!   OverrideControllerValueActions still override the inputs they name).
//!
//! An input holds until the host gives another (a pose that is not renewed keeps the entity
//! standing there). Until the first input the entity drives as under the default controller.
//! Only the domains the controller holds take the input: on the longitudinal domain alone, a
//! pose or wheel angle is not applied and the lane is kept.

use opendrive::{Pose, Real};

use super::command::{Command, Controller, Lateral, Longitudinal};
use super::vehicle_dynamics::{vehicle_parameters, VehicleDynamicsController};
use super::view::ControllerView;
use crate::models::single_track::{Brake, DriverInputs};

/// What the host asks of an `external` entity (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum ExternalInput {
    /// The pose at the end of the step.
    Pose(Pose),
    /// Acceleration (m/s², along the direction of travel) and, optionally, the front wheel
    /// angle (rad, positive left); without one the entity keeps its lane.
    Acceleration {
        /// Acceleration.
        acceleration: Real,
        /// Front wheel angle.
        steering: Option<Real>,
    },
    /// Driver inputs through the vehicle model.
    Driver(DriverInputs),
}

impl ExternalInput {
    /// The input checked as [`Engine::set_external_input`](crate::Engine::set_external_input)
    /// takes it, for every binding alike: every number finite (a steering of `None` keeps
    /// the lane); throttle, clutch and a brake percentage in 0..1 (the `BrakePercent`,
    /// `Throttle` and `Clutch` ranges of OpenSCENARIO 1.3 §7.7.2.5), a brake force not
    /// negative. The error says what was expected and gives the value.
    pub fn check(&self) -> Result<(), InputError> {
        let refuse = |expected: String, found: String| Err(InputError { expected, found });
        let finite = |name: &str, v: Real| {
            if v.is_finite() {
                Ok(())
            } else {
                refuse(format!("a finite {name}"), v.to_string())
            }
        };
        let unit = |name: &str, v: Real| {
            finite(name, v)?;
            if (0.0..=1.0).contains(&v) {
                Ok(())
            } else {
                refuse(format!("{name} in 0..1"), v.to_string())
            }
        };
        let brake = |name: &str, b: Brake| match b {
            Brake::Percent(p) => unit(name, p),
            Brake::Force(f) => {
                finite(name, f)?;
                if f >= 0.0 {
                    Ok(())
                } else {
                    refuse(format!("a {name} force of at least 0 N"), f.to_string())
                }
            }
        };
        match *self {
            ExternalInput::Pose(p) => {
                let all = [p.x, p.y, p.z, p.h, p.p, p.r];
                if all.iter().all(|v| v.is_finite()) {
                    Ok(())
                } else {
                    refuse("a finite pose".to_owned(), format!("{all:?}"))
                }
            }
            ExternalInput::Acceleration {
                acceleration,
                steering,
            } => {
                finite("acceleration", acceleration)?;
                steering.map_or(Ok(()), |s| finite("steering", s))
            }
            ExternalInput::Driver(d) => {
                unit("throttle", d.throttle)?;
                brake("brake", d.brake)?;
                unit("clutch", d.clutch)?;
                brake("parking brake", d.parking_brake)?;
                finite("steering wheel angle", d.steering_wheel)
            }
        }
    }
}

/// An [`ExternalInput`] the engine does not take ([`ExternalInput::check`]); the engine
/// returns it as [`ErrorKind::ExternalInput`](crate::ErrorKind::ExternalInput).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InputError {
    /// What the input must be ("a finite acceleration", "throttle in 0..1").
    pub expected: String,
    /// The value given.
    pub found: String,
}

/// The `external` controller.
#[derive(Debug, Clone)]
pub struct ExternalController {
    vehicle: VehicleDynamicsController,
}

impl ExternalController {
    /// A new controller; the vehicle model's steering ratio and inertia are its defaults.
    pub fn new() -> Self {
        ExternalController {
            vehicle: VehicleDynamicsController::new(None, None),
        }
    }
}

impl Default for ExternalController {
    fn default() -> Self {
        Self::new()
    }
}

impl Controller for ExternalController {
    fn model(&self) -> &'static str {
        "external"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.vehicle.activate(view);
    }

    fn step(&mut self, view: &ControllerView<'_>, dt: Real) -> Command {
        match view.external_input() {
            None => Command::NONE,
            Some(ExternalInput::Pose(p)) => Command::Pose(p),
            Some(ExternalInput::Acceleration {
                acceleration,
                steering,
            }) => {
                let lateral = steering.map(|delta| {
                    let p = vehicle_parameters(view.entity(), None, None);
                    let delta = delta.clamp(-p.max_steering, p.max_steering);
                    Lateral::Curvature(if p.wheelbase > 0.0 {
                        delta.tan() / p.wheelbase
                    } else {
                        0.0
                    })
                });
                Command::Motion {
                    longitudinal: Some(Longitudinal::Acceleration(acceleration)),
                    lateral,
                }
            }
            Some(ExternalInput::Driver(inputs)) => self.vehicle.drive(view, Some(inputs), dt),
        }
    }
}
