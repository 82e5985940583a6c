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

use opendrive::Real;

use super::command::{Command, Controller, Lateral, Longitudinal};
use super::external_input::ExternalInput;
use super::vehicle_dynamics::{vehicle_parameters, VehicleDynamicsController};
use super::view::ControllerView;

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
