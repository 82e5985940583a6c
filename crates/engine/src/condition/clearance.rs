//! RelativeClearanceCondition (OpenSCENARIO 1.3 §7.6.3, 1.2+): true when no other entity
//! occupies the given lanes within the given longitudinal range around the triggering entity.
//!
//! oscsim's reading:
//! * Lanes are counted relative to the triggering entity's lane, positive to the left of its
//!   direction of travel, the centre lane 0 skipped (lane −1 next to lane 1 is one lane away).
//!   `relativeLaneRange` entries (from, to) are inclusive; an absent bound is open; no entry
//!   means every lane. Only entities on the triggering entity's road are compared.
//! * `oppositeLanes` false ignores entities on lanes driven the other way.
//! * The longitudinal range is [−distanceBackward, distanceForward] (absent: 0) along the
//!   road in the triggering entity's direction of travel, between reference points, or
//!   between boxes with `freeSpace` (overlapping boxes are at 0).
//! * `EntityRef` entries restrict the check to those entities; none means all.

use opendrive::{Direction, Real, RoadNetwork};
use scenario::{CoordinateSystem, DistanceMeasure, RelativeDistanceType};

use super::measure::{distance, Target};
use super::ConditionErrorKind;
use crate::position::{EntityQuery, EntityView};

/// The attributes of a RelativeClearanceCondition.
pub(crate) struct Clearance<'c> {
    pub opposite_lanes: bool,
    pub distance_forward: Option<Real>,
    pub distance_backward: Option<Real>,
    pub free_space: bool,
    pub relative_lane_ranges: &'c [(Option<i32>, Option<i32>)],
    pub entity_refs: &'c [String],
}

/// Lane ids as consecutive integers across the road (…, −2 → −1, −1 → 0, 1 → 1, 2 → 2).
fn lane_index(id: i32) -> i32 {
    if id < 0 {
        id + 1
    } else {
        id
    }
}

fn direction(network: &RoadNetwork, road: &str, lane: i32, s: Real) -> Option<Direction> {
    network
        .lane_handle(road, lane, s)
        .map(|h| network.driving_direction(h))
}

/// True when the clearance holds for `e`.
pub(crate) fn clear<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    e: &EntityView<'_>,
    c: &Clearance<'_>,
) -> Result<bool, ConditionErrorKind> {
    let network = ctx.road_network();
    let Some(own) = e.road_position else {
        return Ok(false);
    };
    let travel = if own.relative_heading.cos() >= 0.0 {
        1
    } else {
        -1
    };
    let own_dir = direction(network, &own.road_id, own.lane_id, own.s);
    let measure = DistanceMeasure {
        freespace: c.free_space,
        coordinate_system: Some(CoordinateSystem::Road),
        relative_distance_type: Some(RelativeDistanceType::Longitudinal),
        routing_algorithm: None,
    };
    let (forward, backward) = (
        c.distance_forward.unwrap_or(0.0),
        c.distance_backward.unwrap_or(0.0),
    );
    for other in ctx.entities() {
        if other.name == e.name
            || (!c.entity_refs.is_empty() && !c.entity_refs.iter().any(|r| r == other.name))
        {
            continue;
        }
        let Some(rp) = other.road_position else {
            continue;
        };
        if rp.road_id != own.road_id {
            continue;
        }
        if !c.opposite_lanes && direction(network, &rp.road_id, rp.lane_id, rp.s) != own_dir {
            continue;
        }
        let lanes = travel * (lane_index(rp.lane_id) - lane_index(own.lane_id));
        let in_lanes = c.relative_lane_ranges.is_empty()
            || c.relative_lane_ranges.iter().any(|&(from, to)| {
                from.map_or(true, |f| f <= lanes) && to.map_or(true, |t| lanes <= t)
            });
        if !in_lanes {
            continue;
        }
        let Some(d) = distance(network, e, &Target::Entity(other), &measure)? else {
            continue;
        };
        if d >= -backward && d <= forward {
            return Ok(false);
        }
    }
    Ok(true)
}
