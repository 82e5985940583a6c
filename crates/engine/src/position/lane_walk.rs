//! Walking a distance along the reference line while staying in the entity's lane across lane
//! sections, road links and junctions: the continuation rule of OpenSCENARIO 1.3
//! RelativeRoadPosition / RelativeLanePosition — "the ds-coordinate is calculated assuming
//! that the reference line of the road of the reference entity continues seamlessly on the
//! connecting road … [and] that the lane, where the reference entity is located, continues
//! seamlessly on the connecting road".
//!
//! The walk follows the lane graph of `opendrive` (lane links of sections, roads and
//! junctions): travelling with the lane's driving direction it takes the lane's first
//! successor, against it the first predecessor (at a junction the first connection in file
//! order: the standard leaves the choice to "the routing of the reference entity", which a
//! position does not know). Distances are reference-line lengths of each road passed. When a
//! road is entered against the previous one's s direction (contact point `end` after an end,
//! or `start` after a start), the walk reports the flip, so that t and lane offsets can keep
//! their side.

use opendrive::{Direction, Real, RoadNetwork, LENGTH_EPSILON};

/// Where a walk ends: road, lane, s, and whether that road's s runs against the start road's.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WalkEnd {
    pub road_id: String,
    pub lane_id: i32,
    pub s: Real,
    pub flipped: bool,
}

/// Sections a walk may pass before it is abandoned (a guard against cyclic lane graphs).
const MAX_SECTIONS: usize = 10_000;

/// Walks `ds` m (signed: along +s of the start road when positive) from (road, lane, s),
/// staying in the lane; `None` where the lane ends with nothing connected.
pub(crate) fn walk(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s: Real,
    ds: Real,
) -> Option<WalkEnd> {
    let mut h = network.lane_handle(road_id, lane_id, s)?;
    let mut s = s;
    let mut travel = if ds >= 0.0 {
        Direction::Forward
    } else {
        Direction::Backward
    };
    let mut left = ds.abs();
    let mut flipped = false;
    for _ in 0..MAX_SECTIONS {
        let road = network.handle_road(h);
        let k = h.section as usize;
        let (start, end) = (road.lane_sections[k].s, road.lane_section_end(k));
        let room = match travel {
            Direction::Forward => end - s,
            Direction::Backward => s - start,
        };
        if left <= room + LENGTH_EPSILON {
            let s = match travel {
                Direction::Forward => (s + left).min(end),
                Direction::Backward => (s - left).max(start),
            };
            return Some(WalkEnd {
                road_id: road.id.clone(),
                lane_id: h.lane,
                s,
                flipped,
            });
        }
        left -= room.max(0.0);
        let with_traffic = travel == network.driving_direction(h);
        let next = if with_traffic {
            network.successors(h)
        } else {
            network.predecessors(h)
        };
        let h2 = *next.first()?;
        let driving = network.driving_direction(h2);
        let travel2 = if with_traffic {
            driving
        } else {
            driving.reverse()
        };
        flipped ^= travel2 != travel;
        let road2 = network.handle_road(h2);
        let k2 = h2.section as usize;
        s = match travel2 {
            Direction::Forward => road2.lane_sections[k2].s,
            Direction::Backward => road2.lane_section_end(k2),
        };
        h = h2;
        travel = travel2;
    }
    None
}
