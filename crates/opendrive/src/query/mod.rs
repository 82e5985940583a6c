//! Questions asked of a loaded network (OpenDRIVE 1.8 §8 coordinate systems, §11 lanes, §12
//! junctions): poses, lane extents, world → road look-up, the lane graph and routes, on a
//! [`RoadNetwork`](crate::RoadNetwork); what one road answers alone is module `road`.

mod graph;
mod locate;
mod pose;
mod route;
mod route_search;
mod signal_lanes;

pub use graph::{Direction, LaneHandle};
pub use locate::{RoadPoint, RoadPosition};
pub use route::{LaneRoute, LANE_CHANGE_COST};
pub use route_search::{LaneChange, LaneCost, LanePath, LanePosition, PathCost, RouteSegment};
