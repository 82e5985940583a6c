//! OpenSCENARIO 2.0 §8.7.4.1.1 method distance_along_route(): the distance between an actor
//! and the start or end of a route, along the route's s-axis.
//!
//! The actor's reference point is projected onto each stretch's road in turn
//! (`RoadNetwork::locate_on_road`); the first stretch whose road surface holds the point, whose
//! s range holds its s and whose lane (if the stretch has one) holds it, places it on the
//! route. A route may pass a road twice; the first pass wins.

use opendrive::{Real, RoadNetwork, LENGTH_EPSILON, S_TOLERANCE};

use super::{DomainError, DomainErrorKind, Route, RouteDistanceEnum, TrafficParticipant};

impl TrafficParticipant {
    /// §8.7.4.1.1 `distance_along_route(route, from)`: with `FromStart`, the route s from the
    /// route's start point to the actor (positive when the actor is ahead of the start); with
    /// `FromEnd`, from the actor to the end point (positive when it is behind the end).
    /// Errors with `NotOnRoute` when the actor is on none of the route's stretches.
    pub fn distance_along_route(
        &self,
        network: &RoadNetwork,
        route: &Route,
        from: RouteDistanceEnum,
    ) -> Result<Real, DomainError> {
        let (x, y) = (self.pose.x, self.pose.y);
        let mut travelled = 0.0;
        for st in route.stretches() {
            let (lo, hi) = (st.s_start.min(st.s_end), st.s_start.max(st.s_end));
            let on = network.locate_on_road(&st.road_id, x, y).filter(|p| {
                p.distance <= LENGTH_EPSILON
                    && p.s >= lo - S_TOLERANCE
                    && p.s <= hi + S_TOLERANCE
                    && st.lane_id.is_none_or(|l| l == p.lane_id)
            });
            if let Some(p) = on {
                let along = travelled + (p.s - st.s_start).abs();
                return Ok(match from {
                    RouteDistanceEnum::FromStart => along,
                    RouteDistanceEnum::FromEnd => route.length() - along,
                });
            }
            travelled += (st.s_end - st.s_start).abs();
        }
        Err(DomainError::at(DomainErrorKind::NotOnRoute, x, y))
    }
}
