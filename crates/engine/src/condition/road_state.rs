//! Entity conditions on the entity's place on the road network (OpenSCENARIO 1.3 §7.6.3;
//! XSD `EndOfRoadCondition`, `OffroadCondition`, `CollisionCondition`).
//!
//! * EndOfRoadCondition: the entity has reached the end of its road in its direction of
//!   travel (within [`END_OF_ROAD_TOLERANCE`] of s = length when facing +s, of s = 0 when
//!   facing −s) and the road has no successor (predecessor) there, so nothing continues; for
//!   `duration` s.
//! * OffroadCondition: the entity's reference point lies off every road surface (no road
//!   position, or one at a distance > 0 from the road surface); for `duration` s.
//! * CollisionCondition: the entity's box touches the named entity's, or any other entity's
//!   of the given type (`ConditionContext::collided`).

use opendrive::{Real, RoadNetwork, LENGTH_EPSILON};

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

/// True when `e` is off every road surface.
pub(crate) fn off_road(e: &EntityView<'_>) -> bool {
    !matches!(e.road_position, Some(rp) if rp.distance <= LENGTH_EPSILON)
}
