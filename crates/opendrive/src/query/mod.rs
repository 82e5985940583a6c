//! Questions asked of a loaded network (OpenDRIVE 1.8 §8 coordinate systems, §11 lanes, §12
//! junctions): poses, lane extents, world → road look-up, the lane graph and routes.

mod constant_lanes;
mod frame;
mod graph;
mod lane_span;
mod locate;
mod pieces_by_distance;
mod plan_frame;
mod point_grid;
mod pose;
mod route;
mod route_search;
mod signal_lanes;
mod spatial;

pub use constant_lanes::CONSTANT_MARGIN;
pub use graph::{Direction, LaneHandle};
pub use lane_span::LaneSpan;
pub use locate::{RoadPoint, RoadPosition};
pub use route::{LanePosition, LaneRoute, RouteSegment, LANE_CHANGE_COST};
pub use route_search::{LaneChange, LaneCost, LanePath, PathCost};
pub(crate) use spatial::SpatialIndex;
