//! Entity conditions on the entity's place on the road network (OpenSCENARIO 1.3 §7.6.3;
//! XSD `EndOfRoadCondition`, `OffroadCondition`, `CollisionCondition`).
//!
//! * EndOfRoadCondition: the entity has reached the end of its road in its direction of
//!   travel (within [`END_OF_ROAD_TOLERANCE`] of s = length when facing +s, of s = 0 when
//!   facing −s) and the road has no successor (predecessor) there, so nothing continues; for
//!   `duration` s.
//! * OffroadCondition: the entity's reference point lies off every road surface, or on a lane
//!   of type `none` — OpenDRIVE 1.8 §11.3: "the space on the outermost edge of the road … its
//!   only purpose is for applications to register that ASAM OpenDRIVE is still present in case
//!   the (human) driver leaves the road"; for `duration` s. The lane is looked up from the
//!   pose (`RoadNetwork::locate`), not taken from the runtime's lane assignment, which may keep
//!   a lane id with a large offset (as esmini's does). esmini's `lane_change.xosc` leaves the
//!   road into such a lane and expects the condition to hold there.
//! * CollisionCondition: the entity's box touches the named entity's, or any other entity's
//!   of the given type (`ConditionContext::collided`).

use opendrive::{LaneType, Real, RoadNetwork, LENGTH_EPSILON};

use crate::position::EntityView;

/// How close to a road's end (m) counts as at its end.
pub const END_OF_ROAD_TOLERANCE: Real = 1e-3;

/// True when `e` stands at an end of its road that leads nowhere.
pub(crate) fn at_end_of_road(network: &RoadNetwork, e: &EntityView<'_>) -> bool {
    let Some(rp) = e.road_position else {
        return false;
    };
    let Some(road) = network.road(&rp.road_id) else {
        return false;
    };
    if rp.relative_heading.cos() >= 0.0 {
        road.length - rp.s <= END_OF_ROAD_TOLERANCE && road.links.successor.is_none()
    } else {
        rp.s <= END_OF_ROAD_TOLERANCE && road.links.predecessor.is_none()
    }
}

/// True when `e` is off every road surface or on a lane of type `none`.
pub(crate) fn off_road(network: &RoadNetwork, e: &EntityView<'_>) -> bool {
    let p = &e.pose;
    let Some(rp) = network.locate(p.x, p.y, Some(p.h)) else {
        return true;
    };
    if rp.distance > LENGTH_EPSILON {
        return true;
    }
    network
        .road(&rp.road_id)
        .and_then(|road| road.lane_section_at(rp.s).lane(rp.lane_id))
        .is_some_and(|lane| lane.lane_type == LaneType::None)
}
