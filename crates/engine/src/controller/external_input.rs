//! What the host program asks of an entity under the `external` controller (OpenSCENARIO 1.3
//! §6.6: "controlled by the system under test"): an [`ExternalInput`] for the next step, and
//! the one check every binding's input goes through ([`ExternalInput::check`]). Plain data
//! below the controller that takes it (`external`), the view that shows it (`view`) and the
//! table that keeps it (`table`).

use opendrive::{Pose, Real};

use crate::models::single_track::{Brake, DriverInputs};

/// What the host asks of an `external` entity (module doc of `external`).
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
