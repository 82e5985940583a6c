//! The front door of route planning (OpenSCENARIO 1.3 §7.5 "Routes", XSD `Route`,
//! `Waypoint`; §7.4 AcquirePositionAction): waypoints resolved to lane positions by the
//! caller's [`WaypointSource`] (the engine's position resolver for every
//! [`EntityQuery`](crate::position::EntityQuery)), then one search per leg.
//!
//! Which strategy a leg uses: a Waypoint's `routeStrategy` says how that waypoint is reached
//! from the one before it, so leg i → i+1 uses waypoint i+1's strategy, and the closing leg
//! of a closed route (last → first) the first waypoint's. The first waypoint's strategy is
//! otherwise unused.

use opendrive::{LanePosition, LaneRoute, RoadNetwork, RouteSegment, LENGTH_EPSILON};
use scenario::{Route, RouteStrategy, SourcePos};

use super::cost::{enters_junction_by_id, CostModel, RoutingOptions};
use super::random::leg_key;
use super::source::WaypointSource;
use super::{LaneChange, PlannedRoute, RoutedWaypoint, RoutingError, RoutingErrorKind};
use crate::domain;

/// A point the route must pass: where, and where it was written.
#[derive(Clone)]
pub(crate) struct Stop {
    pub(crate) lane: LanePosition,
    pub(crate) pos: SourcePos,
}

/// Plans `route` (inline or from the Route catalog, as the scenario model gives it),
/// resolving its waypoints through `ctx`. `pos` names the element that uses the route
/// (AssignRouteAction, RoutePosition) for errors about the route as a whole; a waypoint's
/// error is the source's own.
pub fn plan_route<S: WaypointSource + ?Sized>(
    route: &Route,
    ctx: &S,
    options: &RoutingOptions,
    pos: &SourcePos,
) -> Result<PlannedRoute, S::Error> {
    if route.waypoints.len() < 2 {
        return Err(RoutingError::new(
            RoutingErrorKind::TooFewWaypoints {
                route: route.name.clone(),
                found: route.waypoints.len(),
            },
            pos,
        )
        .into());
    }
    let mut stops = Vec::with_capacity(route.waypoints.len());
    for (i, wp) in route.waypoints.iter().enumerate() {
        let rp = ctx.road_position(&wp.position)?.ok_or_else(|| {
            RoutingError::new(
                RoutingErrorKind::OffRoad {
                    route: route.name.clone(),
                    waypoint: i + 1,
                },
                &wp.position.pos,
            )
        })?;
        stops.push(Stop {
            lane: LanePosition {
                road_id: rp.road_id,
                lane_id: rp.lane_id,
                s: rp.s,
                offset: rp.offset,
            },
            pos: wp.position.pos.clone(),
        });
    }
    let n = stops.len();
    let mut legs: Vec<(usize, usize, RouteStrategy)> = (1..n)
        .map(|i| (i - 1, i, route.waypoints[i].route_strategy))
        .collect();
    if route.closed {
        legs.push((n - 1, 0, route.waypoints[0].route_strategy));
    }
    Ok(plan_legs(
        ctx.network(),
        &route.name,
        route.closed,
        &stops,
        &legs,
        options,
    )?)
}

/// Plans the path from `from` to `to` with `strategy` (AcquirePositionAction: the route from
/// the entity's position to the target; OpenSCENARIO 1.3 XSD `AcquirePositionAction`).
/// `pos` names the action for errors. The route is called "AcquirePositionAction".
pub fn plan_between(
    network: &RoadNetwork,
    from: &LanePosition,
    to: &LanePosition,
    strategy: RouteStrategy,
    options: &RoutingOptions,
    pos: &SourcePos,
) -> Result<PlannedRoute, RoutingError> {
    let stops = [
        Stop {
            lane: from.clone(),
            pos: pos.clone(),
        },
        Stop {
            lane: to.clone(),
            pos: pos.clone(),
        },
    ];
    plan_legs(
        network,
        "AcquirePositionAction",
        false,
        &stops,
        &[(0, 1, strategy)],
        options,
    )
}

/// "road R, lane L, s = S" for messages.
fn describe(p: &LanePosition) -> String {
    format!("road \"{}\", lane {}, s = {:.3}", p.road_id, p.lane_id, p.s)
}

/// Plans the legs `(from stop, to stop, strategy)` of route `name` through `stops`.
pub(crate) fn plan_legs(
    network: &RoadNetwork,
    name: &str,
    closed: bool,
    stops: &[Stop],
    legs: &[(usize, usize, RouteStrategy)],
    options: &RoutingOptions,
) -> Result<PlannedRoute, RoutingError> {
    let mut segments: Vec<RouteSegment> = Vec::new();
    let mut lane_changes = Vec::new();
    let mut waypoints = vec![RoutedWaypoint {
        lane: stops[0].lane.clone(),
        path_s: 0.0,
    }];
    let mut path_s = 0.0;
    for (leg, &(a, b, strategy)) in legs.iter().enumerate() {
        let model = CostModel {
            network,
            strategy,
            random_key: leg_key(options.seed, name, leg),
            default_speed: options.default_speed,
        };
        let (from, to) = (&stops[a], &stops[b]);
        let path = network
            .route_by(&model, &from.lane, &to.lane)
            .ok_or_else(|| {
                RoutingError::new(
                    RoutingErrorKind::NotConnected {
                        route: name.to_string(),
                        from: a + 1,
                        from_at: describe(&from.lane),
                        to: b + 1,
                        to_at: describe(&to.lane),
                    },
                    &to.pos,
                )
            })?;
        for c in path.lane_changes {
            lane_changes.push(LaneChange {
                path_s: path_s + c.path_s,
                ..c
            });
        }
        for seg in path.segments {
            path_s += (seg.s_end - seg.s_start).abs();
            append(&mut segments, seg);
        }
        waypoints.push(RoutedWaypoint {
            lane: to.lane.clone(),
            path_s,
        });
    }
    let junctions = segments
        .windows(2)
        .filter(|w| enters_junction_by_id(network, &w[0].road_id, &w[1].road_id))
        .count();
    let route = domain::Route::from_lane_route(&LaneRoute {
        segments: segments.clone(),
        length: path_s,
        lane_changes: lane_changes.len(),
    });
    Ok(PlannedRoute {
        name: name.to_string(),
        closed,
        waypoints,
        segments,
        lane_changes,
        junctions,
        route,
    })
}

/// Appends `seg`, merging it into the last stretch when it continues it on the same lane.
fn append(segments: &mut Vec<RouteSegment>, seg: RouteSegment) {
    if let Some(last) = segments.last_mut() {
        let continues = last.road_id == seg.road_id
            && last.lane_id == seg.lane_id
            && last.direction == seg.direction
            && (last.s_end - seg.s_start).abs() <= LENGTH_EPSILON;
        if continues {
            last.s_end = seg.s_end;
            return;
        }
        if (last.s_end - last.s_start).abs() <= LENGTH_EPSILON && last.road_id == seg.road_id {
            // A leg that ended where it started (two waypoints at one point) leaves an empty
            // stretch; the next one replaces it.
            *last = seg;
            return;
        }
    }
    segments.push(seg);
}
