//! The finite-state guard of the step: every number of an entity's state (pose, speed,
//! velocity, acceleration, road position) is finite before a frame is written.
//!
//! Each input value is checked where it is read (the scenario crate refuses non-finite
//! attributes, parameters and expression results; actions refuse non-finite targets), but
//! finite extremes can still combine into an overflow: a speed of 1.7e308 m/s moves an
//! off-road entity past f64::MAX metres within a few steps, and a jump from 0 to 1e308 m/s in
//! 0.05 s is an acceleration of 2e309 m/s². Such a step is refused with an error naming the
//! entity, the quantity and the time, instead of writing inf or NaN to the outputs (the state
//! would be corrupt: OpenSCENARIO 1.3 §6.3 coordinates and §7.2.2 entity states are real
//! numbers).

use super::entity::Entity;
use super::error::{RuntimeError, RuntimeErrorKind};

/// The first state value of `e` that is not finite, by name.
fn first_non_finite(e: &Entity) -> Option<(&'static str, f64)> {
    let p = &e.pose;
    let v = &e.velocity;
    let a = &e.acceleration;
    let values = [
        ("x", p.x),
        ("y", p.y),
        ("z", p.z),
        ("heading", p.h),
        ("pitch", p.p),
        ("roll", p.r),
        ("speed", e.speed),
        ("velocity x", v.translational.x),
        ("velocity y", v.translational.y),
        ("velocity z", v.translational.z),
        ("yaw rate", v.rotational.z),
        ("acceleration x", a.translational.x),
        ("acceleration y", a.translational.y),
        ("acceleration z", a.translational.z),
    ];
    let road = e
        .road_position
        .as_ref()
        .map(|r| [("road s", r.s), ("road t", r.t), ("lane offset", r.offset)]);
    // On the stack, in the order of the message: no allocation per entity and step.
    values
        .into_iter()
        .chain(road.into_iter().flatten())
        .find(|(_, value)| !value.is_finite())
}

/// Checks every placed entity of `entities` at simulation time `time`; the first entity whose
/// state is not finite, by name, and the error.
pub(crate) fn check(entities: &[Entity], time: f64) -> Result<(), (String, RuntimeError)> {
    for e in entities.iter().filter(|e| e.placed) {
        if let Some((quantity, value)) = first_non_finite(e) {
            let error = RuntimeError::new(RuntimeErrorKind::NonFinite {
                entity: e.name.clone(),
                quantity,
                value,
                time,
            });
            return Err((e.name.clone(), error));
        }
    }
    Ok(())
}
