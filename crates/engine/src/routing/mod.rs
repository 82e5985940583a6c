//! Route planning at runtime (OpenSCENARIO 1.3 §7.5 "Routes", XSD `Route`, `Waypoint`,
//! `RouteStrategy`; used by AssignRouteAction, AcquirePositionAction, RoutePosition and the
//! default controller): a lane-level path through a route's waypoints on the OpenDRIVE lane
//! graph, leg by leg with each waypoint's routeStrategy, as the lane stretches to drive, the
//! lane changes they need, and a [`domain::Route`](crate::domain::Route) for
//! distance_along_route and InRoutePosition.
//!
//! | module | implements |
//! | --- | --- |
//! | `error` | `RoutingError`, `RoutingErrorKind` |
//! | `cost` | the cost of driving a lane stretch, changing lanes and entering a junction per RouteStrategy, for the lane-graph search `opendrive::RoadNetwork::route_by` |
//! | `random` | the seeded, order-independent lane weights of routeStrategy `random` |
//! | `planned` | `PlannedRoute`: stretches, lane changes, waypoints' path s, look-ups by path s |
//! | `random_route` | `plan_random`: RandomRouteAction's seeded walk over the lane graph |
//! | `source` | `WaypointSource`: the seam through which a route's waypoints are resolved |
//! | `plan` | `plan_route` (Route with waypoints, closed routes) and `plan_between` (AcquirePositionAction) |

mod cost;
mod error;
mod plan;
mod planned;
mod random;
mod random_route;
mod source;

pub use cost::{RoutingOptions, DEFAULT_SPEED, UNLIMITED_ROAD_SPEED};
pub use error::{RoutingError, RoutingErrorKind};
pub use opendrive::LaneChange;
pub use plan::{plan_between, plan_route};
pub use planned::{PlannedRoute, RoutedWaypoint};
pub use random_route::{
    plan_random, HORIZON as RANDOM_ROUTE_HORIZON, MAX_DECISIONS as RANDOM_ROUTE_MAX_DECISIONS,
};
pub use source::WaypointSource;
