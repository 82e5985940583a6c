//! Entity conditions on motion (OpenSCENARIO 1.3 §7.6.3; XSD `SpeedCondition`,
//! `RelativeSpeedCondition`, `AccelerationCondition`, `StandStillCondition`,
//! `TraveledDistanceCondition`).
//!
//! * SpeedCondition: with `direction` (1.2+) the component of the entity's velocity along its
//!   own longitudinal (x), lateral (y) or vertical (z) axis. Without `direction`, the entity's
//!   signed speed along its heading (`EntityView::speed`, negative when reversing), as in 1.0
//!   ("the speed of the entity") and as esmini reads it. The 1.2 annotation "the total speed is
//!   considered" would make a magnitude of it, which no scenario of the corpus expects: its
//!   1.3 light-state catalog switches reversing lights on at `SpeedCondition lessThan −0.01`.
//! * RelativeSpeedCondition: the triggering entity's speed minus the reference entity's ("the
//!   relative speed of the triggering entity to the reference entity"): signed speeds without
//!   `direction`; with it, the component of the velocity difference (both in world axes) along
//!   the triggering entity's axis.
//! * AccelerationCondition: with `direction` as SpeedCondition on the acceleration vector;
//!   without, the signed longitudinal acceleration (negative when braking), for the same reason.
//! * StandStillCondition: |speed| at most [`STAND_STILL_SPEED`] without a break for
//!   `duration` s (memory in `ConditionState`).
//! * TraveledDistanceCondition: the odometer has reached `value` m.

use opendrive::{Pose, Real};
use scenario::DirectionalDimension;

use super::measure::world_velocity;
use crate::domain::Vector3;
use crate::position::EntityView;

/// Speeds at or below this (m/s) count as standing still: numerical integration leaves
/// residues far below it, and no scenario moves this slowly on purpose.
pub const STAND_STILL_SPEED: Real = 1e-3;

/// Durations compare with this slack (s), so that a duration that is a multiple of the step
/// is reached at that step despite the round-off of summed times.
pub const DURATION_TOLERANCE: Real = crate::tolerance::TIME;

/// A vector's component along `direction` of the object's own axes (x when absent).
pub(crate) fn component(v: Vector3, direction: Option<DirectionalDimension>) -> Real {
    match direction {
        Some(DirectionalDimension::Lateral) => v.y,
        Some(DirectionalDimension::Vertical) => v.z,
        _ => v.x,
    }
}

/// SpeedCondition's measured value.
pub(crate) fn speed(e: &EntityView<'_>, direction: Option<DirectionalDimension>) -> Real {
    match direction {
        None => e.speed,
        Some(_) => component(e.velocity.translational, direction),
    }
}

/// AccelerationCondition's measured value.
pub(crate) fn acceleration(e: &EntityView<'_>, direction: Option<DirectionalDimension>) -> Real {
    component(e.acceleration.translational, direction)
}

/// RelativeSpeedCondition's measured value: `e` relative to `reference`.
pub(crate) fn relative_speed(
    e: &EntityView<'_>,
    reference: &EntityView<'_>,
    direction: Option<DirectionalDimension>,
) -> Real {
    if direction.is_none() {
        return speed(e, None) - speed(reference, None);
    }
    let (a, b) = (world_velocity(e), world_velocity(reference));
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    component(to_local(&e.pose, d), direction)
}

/// A world vector in the axes of an object at `pose` (the transpose of
/// `position::local_to_world`).
fn to_local(pose: &Pose, d: [Real; 3]) -> Vector3 {
    let (sh, ch) = pose.h.sin_cos();
    let (sp, cp) = pose.p.sin_cos();
    let (sr, cr) = pose.r.sin_cos();
    // Undo heading, then pitch, then roll.
    let (x1, y1, z1) = (ch * d[0] + sh * d[1], -sh * d[0] + ch * d[1], d[2]);
    let (x2, y2, z2) = (cp * x1 - sp * z1, y1, sp * x1 + cp * z1);
    Vector3::new(x2, cr * y2 + sr * z2, -sr * y2 + cr * z2)
}

/// True while the entity stands still.
pub(crate) fn stands_still(e: &EntityView<'_>) -> bool {
    e.speed.abs() <= STAND_STILL_SPEED
}
