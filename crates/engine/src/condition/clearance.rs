//! RelativeClearanceCondition (OpenSCENARIO 1.3 §7.6.3, 1.2+): "evaluates to true, if the
//! specified area exists and is free, otherwise evaluates to false".
//!
//! oscsim's reading:
//! * The area exists when every lane a bounded `relativeLaneRange` names exists on the
//!   triggering entity's road at its s (a range reaching past the road's edge does not).
//! * Lanes are counted relative to the triggering entity's lane, positive to the left of its
//!   direction of travel, the centre lane 0 skipped (lane −1 next to lane 1 is one lane away).
//!   `relativeLaneRange` entries (from, to) are inclusive; an absent bound is open; no entry
//!   means every lane.
//! * Where the other entity is, its lane is counted from the lane the triggering entity's lane
//!   becomes there, followed through lane sections and onto connecting roads along the lane
//!   links (`position::lane_walk`, the 1.3 continuation rule), not by lane id: on a 2+1 road
//!   a lane that appears on the left renumbers the lanes to its right, and lane −2 after the
//!   section boundary may be the same lane as −1 before it. Where the triggering entity's lane
//!   ends before the other entity's place (the passing lane of a 2+1 road), the nearest lane
//!   beside it that does continue is followed (one driven the same way first, then the left
//!   one) and the count shifted by the lanes between them at the triggering entity. An entity whose place no followed lane reaches (another branch
//!   of a junction) is not in the area. (issue 16 class 7)
//! * `oppositeLanes` false ignores entities on lanes driven the other way ("otherwise only
//!   lanes in the same direction are considered"), and a bounded `relativeLaneRange` whose
//!   lanes at the triggering entity are all driven the other way specifies an area that does
//!   not exist, so the condition is false (issue 34 class 4: range 1..1 beside a lane whose
//!   left neighbour is the opposite carriageway). A range mixing both directions keeps its
//!   lanes driven the triggering entity's way.
//! * The longitudinal range is [−distanceBackward, distanceForward] (absent: 0, as the XSD
//!   says) along the road in the direction the triggering entity faces, between reference
//!   points, or between boxes with `freeSpace` (overlapping boxes are at 0), along the centre
//!   line of the entity's lane as the standard says (lane coordinates of `measure`).
//! * Without `freeSpace` another entity occupies the lane of its reference point; with it,
//!   every lane a corner of its box stands on ("the whole bounding box is considered").
//! * `EntityRef` entries restrict the check to those entities; none means all.

use opendrive::{Direction, Real, RoadNetwork};
use scenario::{CoordinateSystem, DistanceMeasure, RelativeDistanceType};

use super::measure::distance;
use super::target::Target;
use super::ConditionErrorKind;
use crate::position::{add_lanes, lane_walk, EntityQuery, EntityView};

/// The attributes of a RelativeClearanceCondition.
pub(crate) struct Clearance<'c> {
    pub opposite_lanes: bool,
    pub distance_forward: Option<Real>,
    pub distance_backward: Option<Real>,
    pub free_space: bool,
    pub relative_lane_ranges: &'c [(Option<i32>, Option<i32>)],
    /// With EntityRefs: only these entities count (as they stand now, in the store's
    /// order); else every entity in the scene.
    pub only: Option<&'c [EntityView<'c>]>,
}

/// Lane ids as consecutive integers across the road (…, −2 → −1, −1 → 0, 1 → 1, 2 → 2).
fn lane_index(id: i32) -> i32 {
    if id < 0 {
        id + 1
    } else {
        id
    }
}

/// The lanes of road `road_id` that the corners of `e`'s box stand on.
fn box_lanes<'n>(
    network: &'n RoadNetwork,
    e: &EntityView<'_>,
    road_id: &'n str,
) -> impl Iterator<Item = i32> + 'n {
    let corners = e.bounding_box.footprint(&e.pose).corners();
    corners.into_iter().filter_map(move |[x, y]| {
        network
            .locate_on_road(road_id, x, y)
            .filter(|p| p.distance <= opendrive::LENGTH_EPSILON)
            .map(|p| p.lane_id)
    })
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
    // The area must exist: every lane a bounded range names, on the entity's road at its s;
    // with oppositeLanes false, a range whose lanes are all driven the other way names no lane
    // that is considered, so its part of the area does not exist either.
    for &(from, to) in c.relative_lane_ranges {
        let (Some(from), Some(to)) = (from, to) else {
            continue;
        };
        let mut considered = false;
        for k in from.min(to)..=from.max(to) {
            let lane = add_lanes(own.lane_id, travel * k);
            if network.lane_boundaries(&own.road_id, lane, own.s).is_err() {
                return Ok(false);
            }
            considered |=
                c.opposite_lanes || direction(network, &own.road_id, lane, own.s) == own_dir;
        }
        if !considered {
            return Ok(false);
        }
    }
    let measure = DistanceMeasure {
        freespace: c.free_space,
        coordinate_system: Some(CoordinateSystem::Lane),
        relative_distance_type: Some(RelativeDistanceType::Longitudinal),
        routing_algorithm: None,
    };
    let (forward, backward) = (
        c.distance_forward.unwrap_or(0.0),
        c.distance_backward.unwrap_or(0.0),
    );
    let others: Box<dyn Iterator<Item = EntityView<'_>> + '_> = match c.only {
        Some(only) => Box::new(only.iter().copied()),
        None => ctx.entities(),
    };
    for other in others {
        if other.name == e.name {
            continue;
        }
        let Some(rp) = other.road_position else {
            continue;
        };
        if !c.opposite_lanes && direction(network, &rp.road_id, rp.lane_id, rp.s) != own_dir {
            continue;
        }
        let Some(count) = LaneCount::to(network, e, own, &other, travel)? else {
            continue;
        };
        let in_range = |lane: i32| {
            let k = count.relative(lane);
            c.relative_lane_ranges.is_empty()
                || c.relative_lane_ranges
                    .iter()
                    .any(|&(from, to)| from.is_none_or(|f| f <= k) && to.is_none_or(|t| k <= t))
        };
        let in_lanes = in_range(rp.lane_id)
            || (c.free_space && box_lanes(network, &other, &rp.road_id).any(in_range));
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

/// How lanes at another entity's place are counted from the triggering entity's lane: the
/// lane `reference` there is `shift` lanes left of the triggering entity's, and lane ids there
/// grow to the left of the triggering entity's travel when `sign` is +1.
struct LaneCount {
    reference: i32,
    shift: i32,
    sign: i32,
}

/// Lanes beside the triggering entity's own (lanes to its left) tried when its lane ends before
/// the other's place.
const NEIGHBOURS: [i32; 7] = [0, 1, -1, 2, -2, 3, -3];

impl LaneCount {
    /// The count at `other`'s place, or `None` when no followed lane reaches its road there.
    fn to(
        network: &RoadNetwork,
        e: &EntityView<'_>,
        own: &opendrive::RoadPosition,
        other: &EntityView<'_>,
        travel: i32,
    ) -> Result<Option<LaneCount>, ConditionErrorKind> {
        let Some(rp) = other.road_position else {
            return Ok(None);
        };
        if rp.road_id == own.road_id
            && network
                .road(&own.road_id)
                .is_some_and(|r| r.lane_section_index(rp.s) == r.lane_section_index(own.s))
        {
            return Ok(Some(LaneCount {
                reference: own.lane_id,
                shift: 0,
                sign: travel,
            }));
        }
        // Reference-line distance to the other's reference point, ahead of the travel.
        let along = DistanceMeasure {
            freespace: false,
            coordinate_system: Some(CoordinateSystem::Road),
            relative_distance_type: Some(RelativeDistanceType::Longitudinal),
            routing_algorithm: None,
        };
        let Some(d) = distance(network, e, &Target::Entity(*other), &along)? else {
            return Ok(None);
        };
        let ds = Real::from(travel) * d;
        // The own lane first, then nearer lanes before farther ones, lanes driven the own
        // lane's way before opposite ones, left before right.
        let own_dir = direction(network, &own.road_id, own.lane_id, own.s);
        let mut candidates: Vec<(i32, i32)> = NEIGHBOURS
            .iter()
            .map(|&j| (j, add_lanes(own.lane_id, travel * j)))
            .filter(|&(_, lane)| network.lane_boundaries(&own.road_id, lane, own.s).is_ok())
            .collect();
        candidates.sort_by_key(|&(j, lane)| {
            let opposite = direction(network, &own.road_id, lane, own.s) != own_dir;
            (j.abs(), opposite, j < 0)
        });
        for (j, lane) in candidates {
            let Some(end) = lane_walk(network, &own.road_id, lane, own.s, ds) else {
                continue;
            };
            if end.road_id != rp.road_id {
                continue;
            }
            return Ok(Some(LaneCount {
                reference: end.lane_id,
                shift: j,
                sign: if end.flipped { -travel } else { travel },
            }));
        }
        Ok(None)
    }

    /// Lane `lane` at the other's place, counted from the triggering entity's lane.
    fn relative(&self, lane: i32) -> i32 {
        self.shift + self.sign * (lane_index(lane) - lane_index(self.reference))
    }
}
