//! AngleCondition and RelativeAngleCondition (OpenSCENARIO 1.3 §7.6.3, new in 1.3): an
//! entity's heading, pitch or roll compared with `angle` within `angleTolerance` (both rad),
//! modulo 2π.
//!
//! * AngleCondition: the entity's own angle in `coordinateSystem`: world (and entity, or
//!   absent: the world frame, the only one an entity's own absolute angle can be read in);
//!   road: minus the road's reference-line angle at the entity's s; lane: heading minus the
//!   lane's driving direction (pitfall 15), pitch and roll as for road; trajectory: heading
//!   minus the heading of the followed trajectory at its point closest to the entity (false
//!   while the entity follows none).
//! * RelativeAngleCondition: the triggering entity's angle minus the reference entity's (the
//!   frame's own angle cancels out of the difference, so every coordinate system gives the
//!   same value).
//!
//! An entity off the roads has no road or lane angle: the condition is false.

use opendrive::{angle_difference, Pose, Real, RoadNetwork};
use scenario::{AngleType, CoordinateSystem};

use super::ConditionErrorKind;
use crate::position::EntityView;

/// The angle of `pose` selected by `angle_type`.
fn pick(pose: &Pose, angle_type: AngleType) -> Real {
    match angle_type {
        AngleType::Pitch => pose.p,
        AngleType::Roll => pose.r,
        _ => pose.h,
    }
}

/// The entity's own angle in `cs`; `None` when it needs a road the entity is not on.
pub(crate) fn own_angle(
    network: &RoadNetwork,
    e: &EntityView<'_>,
    angle_type: AngleType,
    cs: Option<CoordinateSystem>,
) -> Result<Option<Real>, ConditionErrorKind> {
    let own = pick(&e.pose, angle_type);
    match cs {
        None | Some(CoordinateSystem::World) | Some(CoordinateSystem::Entity) => Ok(Some(own)),
        Some(CoordinateSystem::Road) | Some(CoordinateSystem::Lane) => {
            let Some(rp) = e.road_position else {
                return Ok(None);
            };
            let Ok(mut road) = network.road_pose(&rp.road_id, rp.s, rp.t) else {
                return Ok(None);
            };
            if cs == Some(CoordinateSystem::Lane) && angle_type == AngleType::Heading {
                road.h = crate::position::lane_driving_heading(
                    network,
                    &rp.road_id,
                    rp.lane_id,
                    rp.s,
                    road.h,
                );
            }
            Ok(Some(angle_difference(own, pick(&road, angle_type))))
        }
        Some(CoordinateSystem::Trajectory) => Ok(e.trajectory.map(|path| {
            let c = path.closest(e.pose.x, e.pose.y);
            match angle_type {
                AngleType::Heading => angle_difference(own, c.point.heading),
                // A trajectory is a plane curve: its pitch and roll are 0.
                _ => own,
            }
        })),
        _ => Err(ConditionErrorKind::Unsupported {
            expected: "coordinateSystem world, entity, road, lane or trajectory",
            found: "another coordinate system",
        }),
    }
}

/// True when `measured` equals `angle` within `tolerance`, modulo 2π.
pub(crate) fn within(measured: Real, angle: Real, tolerance: Real) -> bool {
    angle_difference(measured, angle).abs() <= tolerance
}

/// RelativeAngleCondition's measured value.
pub(crate) fn relative_angle(
    e: &EntityView<'_>,
    reference: &EntityView<'_>,
    angle_type: AngleType,
) -> Real {
    angle_difference(pick(&e.pose, angle_type), pick(&reference.pose, angle_type))
}
