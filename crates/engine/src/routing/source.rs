//! Where a route's waypoints come from (OpenSCENARIO 1.3 §7.5, XSD `Waypoint`: each is a
//! `Position`, any of the forms of §7.4): the seam through which [`plan_route`](super::plan_route)
//! has them resolved. The engine's position resolver
//! ([`position::resolve`](crate::position::resolve)) is the source for every
//! [`EntityQuery`](crate::position::EntityQuery), so this module never calls it: a
//! RoutePosition is resolved by planning its route, whose waypoints are positions.

use opendrive::{RoadNetwork, RoadPosition};
use scenario::Position;

use super::error::RoutingError;

/// Resolves the waypoints of a route on its road network. Errors of the route itself are
/// [`RoutingError`]s; the source's own `Error` holds them too, so that a waypoint's error
/// and a route's error come back as one type.
pub trait WaypointSource {
    /// The error of resolving a waypoint, and of the planning as a whole.
    type Error: From<RoutingError>;

    /// The road network the route is planned on.
    fn network(&self) -> &RoadNetwork;

    /// Where `position` lies on the road network now; `None` when it is off every road.
    fn road_position(&self, position: &Position) -> Result<Option<RoadPosition>, Self::Error>;
}
