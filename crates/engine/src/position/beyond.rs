//! Road-based positions whose s lies outside their road (issue 16 class 2). One rule for every
//! position type that names an s: RoadPosition and LanePosition (OpenSCENARIO 1.3 §6.3.3,
//! §6.3.4), RelativeRoadPosition and RelativeLanePosition with `ds` (module `lane_walk`) or
//! `dsLane`.
//!
//! The standard defines the continuation for the relative forms only: "the ds-coordinate is
//! calculated assuming that the reference line of the road of the reference entity continues
//! seamlessly on the connecting road … [and] that the lane, where the reference entity is
//! located, continues seamlessly on the connecting road" (1.3 XSD RelativeRoadPosition,
//! RelativeLanePosition). An absolute s past a road's end (s > length) or before its start
//! (s < 0) asks the same question of the road graph, and gets the same answer here: the
//! excess is walked from the road's end along the lane's links (LanePosition: its lane;
//! RoadPosition: the lane at t at the road's end, drivable lanes first) onto the connecting
//! road, and t or the lane offset keeps its side (negated where the road reached runs against
//! the first). Where nothing connects there, the position is an error naming its file, line
//! and column; positions that depend on no entity are checked at load (`check`), so such a
//! file does not load rather than stop at the moment the position is needed.
//!
//! RelativeLanePosition with `dsLane` (a distance along the lane's centre line) continues the
//! same way, measured along the centre lines of the lanes passed (`lane::along_lane`). Not
//! carried: TrajectoryPosition and the route-based forms, whose trajectory or route has no
//! continuation (an s past their end is an error at its place).

use opendrive::{Real, RoadNetwork, S_TOLERANCE};

use super::lane_at::lane_at;
use super::lane_walk::{walk, WalkEnd};

/// Where (road, lane, s) lies when s is outside the road: the end of the walk from the road's
/// end by the excess. `None` when s is on the road (within [`S_TOLERANCE`]), the road or lane
/// is unknown, or nothing connects at that end (the caller's own error then names the s).
pub(crate) fn carried(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: Option<i32>,
    s: Real,
    t: Real,
) -> Option<WalkEnd> {
    let road = network.road(road_id)?;
    if !s.is_finite() || (-S_TOLERANCE..=road.length + S_TOLERANCE).contains(&s) {
        return None;
    }
    let end = s.clamp(0.0, road.length);
    let lane = match lane_id {
        Some(lane) => lane,
        None => lane_at(road, end, t)?.0,
    };
    walk(network, road_id, lane, end, s - end)
}
