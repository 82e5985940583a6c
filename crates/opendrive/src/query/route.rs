//! Shortest lane-level route between two lane positions: the search of `route_search` with
//! the cost of length.
//!
//! Cost model: the length driven along s (|Δs| on each lane section, measured on the reference
//! line) plus [`LANE_CHANGE_COST`] for each change to an adjacent drivable lane of the same
//! driving direction within a lane section. A lane change takes no length of its own: it
//! happens at the point where the previous lane was entered. Only drivable lanes
//! ([`LaneType::is_drivable`](crate::LaneType::is_drivable)) are used between start and end.

use super::graph::LaneHandle;
use super::route_search::{LaneCost, LanePosition, RouteSegment};
use crate::math::Real;
use crate::network::RoadNetwork;

/// Extra cost (m) of one lane change, so that a route changes lanes only when it must or when
/// that saves more than this distance.
pub const LANE_CHANGE_COST: Real = 10.0;

/// A route: segments in driving order and the total length driven (m, sum of |Δs|).
#[derive(Debug, Clone, PartialEq)]
pub struct LaneRoute {
    /// The lane stretches, in order.
    pub segments: Vec<RouteSegment>,
    /// Total length (m), lane-change costs excluded.
    pub length: Real,
    /// Number of lane changes.
    pub lane_changes: usize,
}

/// Length plus [`LANE_CHANGE_COST`] per lane change: the cost of [`RoadNetwork::route`].
struct LengthCost;

impl LaneCost for LengthCost {
    type Cost = Real;
    fn along(&self, _: LaneHandle, _: Real, length: Real) -> Real {
        length
    }
    fn lane_change(&self, _: LaneHandle, _: Real) -> Real {
        LANE_CHANGE_COST
    }
    fn enter(&self, _: LaneHandle, _: LaneHandle) -> Real {
        0.0
    }
}

impl RoadNetwork {
    /// The shortest route from `from` to `to` (see the module doc for the cost), or `None` if
    /// either position is unknown or `to` cannot be reached in the driving direction. A goal
    /// behind the start on the start's own lane is reached round a loop of the network, if
    /// there is one.
    pub fn route(&self, from: &LanePosition, to: &LanePosition) -> Option<LaneRoute> {
        let path = self.route_by(&LengthCost, from, to)?;
        let length = path
            .segments
            .iter()
            .map(|seg| (seg.s_end - seg.s_start).abs())
            .sum();
        Some(LaneRoute {
            segments: path.segments,
            length,
            lane_changes: path.lane_changes.len(),
        })
    }
}
