//! The system under test in the loop: entities driven by an `external` controller
//! (OpenSCENARIO 1.3 §6.6: "a vehicle is controlled by the system under test") take their
//! input from C before each step, in the engine's three forms
//! (`engine::controller::ExternalInput`): an acceleration with an optional front wheel angle,
//! pedals and steering wheel through the engine's vehicle model, or the pose at the end of the
//! step. An input holds until the next; before the first the entity drives as under the
//! default controller.

use std::ffi::c_char;

use engine::controller::ExternalInput;
use engine::models::single_track::{Brake, DriverInputs, GearSelection};
use engine::ErrorKind;

use crate::error::{Failure, OscsimStatus};
use crate::simulation::{text, with_sim, OscsimSimulation};

/// The failure of an engine call on an external controller.
fn failure(e: engine::Error) -> Failure {
    let status = match e.kind() {
        ErrorKind::NotExternal { .. } => OscsimStatus::NotExternal,
        ErrorKind::ExternalInput { .. } => OscsimStatus::Argument,
        _ => OscsimStatus::Step,
    };
    Failure::new(status, e.to_string())
}

/// Gives `name`'s external controller `input`.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string.
unsafe fn set(
    sim: *mut OscsimSimulation,
    name: *const c_char,
    input: impl FnOnce() -> Result<ExternalInput, Failure>,
) -> OscsimStatus {
    // SAFETY: passed on from the caller.
    unsafe {
        with_sim(sim, |sim| {
            let name = text(name, "an entity name")?;
            let input = input()?;
            sim.engine.set_external_input(name, input).map_err(failure)
        })
    }
}

/// Hands entity `name` to the program: assigns it an `external` controller active on the
/// longitudinal and lateral domains and stops the motion actions running on it. Call it after
/// the first step, which places the entities; an entity the scenario already gives an active
/// `external` controller needs no call. [`OscsimStatus::NotExternal`] when there is no such
/// entity.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_attach_external(
    sim: *mut OscsimSimulation,
    name: *const c_char,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        with_sim(sim, |sim| {
            let name = text(name, "an entity name")?;
            sim.engine.attach_external(name).map_err(failure)
        })
    }
}

/// From the next step on, drives entity `name` at `acceleration` (m/s², along its direction of
/// travel) with front wheel angle `steering` (rad, positive left; NaN keeps the lane as the
/// default controller does). [`OscsimStatus::NotExternal`] unless an `external` controller
/// holds the entity.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_set_acceleration(
    sim: *mut OscsimSimulation,
    name: *const c_char,
    acceleration: f64,
    steering: f64,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        set(sim, name, || {
            Ok(ExternalInput::Acceleration {
                acceleration,
                steering: (!steering.is_nan()).then_some(steering),
            })
        })
    }
}

/// From the next step on, drives vehicle `name` by pedals (`throttle`, `brake`: 0..1) and
/// steering wheel angle (rad, positive left), in drive, through the engine's vehicle model.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_set_pedals(
    sim: *mut OscsimSimulation,
    name: *const c_char,
    throttle: f64,
    brake: f64,
    steering_wheel: f64,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        set(sim, name, || {
            Ok(ExternalInput::Driver(DriverInputs {
                throttle,
                brake: Brake::Percent(brake),
                steering_wheel,
                gear: GearSelection::Drive,
                ..DriverInputs::default()
            }))
        })
    }
}

/// Places entity `name` at the end of the next step at world pose x, y, z (m), heading, pitch,
/// roll (rad); it stays there until the next input.
///
/// # Safety
/// `sim` is a live handle; `name` is a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn oscsim_simulation_set_pose(
    sim: *mut OscsimSimulation,
    name: *const c_char,
    x: f64,
    y: f64,
    z: f64,
    h: f64,
    p: f64,
    r: f64,
) -> OscsimStatus {
    // SAFETY: the caller's contract.
    unsafe {
        set(sim, name, || {
            Ok(ExternalInput::Pose(opendrive::Pose { x, y, z, h, p, r }))
        })
    }
}
