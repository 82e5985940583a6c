//! Positions on a route (OpenSCENARIO 1.3 §7.5 "Routes"; XSD `RoutePosition`,
//! `InRoutePosition`: `FromCurrentEntity`, `FromRoadCoordinates`, `FromLaneCoordinates`).
//!
//! The route's path is the one route planning gives ([`routing::plan_route`]: each waypoint
//! reached from the one before by its `routeStrategy`, a closed route joined back to its first
//! waypoint), so that a route is the same path to positions, to the default controller that
//! follows it and to the conditions that measure along it. `pathS` is the distance along that
//! path measured on the roads' reference lines (the s-axis of [`PlannedRoute`]), from the first
//! waypoint; routeStrategy `random` draws from the run's seed
//! ([`EntityQuery::routing_options`]).
//!
//! * FromRoadCoordinates: the road point (s, t) at pathS; t as on that road (left of its
//!   reference line).
//! * FromLaneCoordinates: the centre of lane `laneId` of the road at pathS, plus
//!   `laneOffset` along the road's t-axis.
//! * FromCurrentEntity: where the entity is, if it is on one of the path's stretches (any lane
//!   of the stretch's road: an entity between lanes or changing lanes is still on the route).
//!
//! Orientation: relative headings count from the route's direction of travel at the point
//! (the road's s-tangent at pathS, turned by π where the route runs towards −s); pitch and
//! roll are the road surface's.

use std::f64::consts::PI;

use opendrive::{Direction, Pose, Real, RoadNetwork};
use scenario::{InRoutePosition, Orientation, Position, PositionKind, Route, SourcePos};

use super::error::road_error;
use super::lane::parse_lane_id;
use super::orientation::on_surface;
use super::world::{entity, finite, finite_orientation};
use super::{EntityQuery, EntityView, PositionError, PositionErrorKind, ResolvedPosition};
use crate::routing::{self, PlannedRoute};

/// Heading of travel on a road whose s-tangent heads `road_h`.
fn travel_heading(road_h: Real, direction: Direction) -> Real {
    match direction {
        Direction::Forward => road_h,
        Direction::Backward => opendrive::normalize_angle(road_h + PI),
    }
}

/// Road, road s and direction of travel at `path_s`, or an `OutsideRoute` error.
fn at<'p>(
    planned: &'p PlannedRoute,
    path_s: Real,
    pos: &SourcePos,
) -> Result<(&'p str, Real, Direction), PositionError> {
    let (seg, s) = planned.at(path_s).ok_or_else(|| {
        PositionError::new(
            PositionErrorKind::OutsideRoute {
                route: planned.name().to_string(),
                path_s,
                length: planned.length(),
            },
            pos,
        )
    })?;
    Ok((&seg.road_id, s, seg.direction))
}

/// `RoutePosition`.
pub(crate) fn route_position<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    route: &Route,
    in_route: &InRoutePosition,
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    let network = ctx.road_network();
    // A waypoint's own position error as it is; a route that cannot be planned (too few
    // waypoints, waypoints not joined) as PositionErrorKind::Route, naming its place.
    let planned = routing::plan_route(route, ctx, &ctx.routing_options(), pos)?;
    match in_route {
        InRoutePosition::FromRoadCoordinates { path_s, t } => {
            finite(&[("pathS", *path_s), ("t", *t)], pos)?;
            let (road_id, s, dir) = at(&planned, *path_s, pos)?;
            let surface = network
                .road_pose(road_id, s, *t)
                .map_err(|e| road_error(e, pos))?;
            let travel_h = travel_heading(surface.h, dir);
            Ok(placed(network, road_id, surface, orientation, travel_h))
        }
        InRoutePosition::FromLaneCoordinates {
            path_s,
            lane_id,
            lane_offset,
        } => {
            let offset = lane_offset.unwrap_or(0.0);
            finite(&[("pathS", *path_s), ("laneOffset", offset)], pos)?;
            let lane_id = parse_lane_id(lane_id, pos)?;
            let (road_id, s, dir) = at(&planned, *path_s, pos)?;
            let surface = network
                .lane_pose(road_id, lane_id, s, offset)
                .map_err(|e| road_error(e, pos))?;
            let travel_h = travel_heading(surface.h, dir);
            Ok(placed(network, road_id, surface, orientation, travel_h))
        }
        InRoutePosition::FromCurrentEntity { entity_ref } => from_current_entity(
            network,
            &planned,
            entity(ctx, entity_ref, pos)?,
            (entity_ref, &route.name),
            orientation,
            pos,
        ),
        _ => Err(PositionError::new(
            PositionErrorKind::Unsupported {
                expected: "FromCurrentEntity, FromRoadCoordinates or FromLaneCoordinates",
                found: "another InRoutePosition form",
            },
            pos,
        )),
    }
}

/// A RoutePosition `FromCurrentEntity` (`position`) on `planned`, its route planned before
/// (condition/refs.rs: a route whose waypoints name no entity is planned once), with the
/// entity its `entityRef` names given by `reference` (called with the name, once).
pub(crate) fn on_planned_route<'q>(
    position: &Position,
    planned: &PlannedRoute,
    network: &RoadNetwork,
    reference: impl FnOnce(&str) -> Result<EntityView<'q>, PositionError>,
) -> Result<ResolvedPosition, PositionError> {
    let pos = &position.pos;
    let PositionKind::Route {
        route,
        in_route: InRoutePosition::FromCurrentEntity { entity_ref },
        orientation,
    } = &position.kind
    else {
        return Err(PositionError::new(
            PositionErrorKind::Unsupported {
                expected: "RoutePosition FromCurrentEntity",
                found: "another position form",
            },
            pos,
        ));
    };
    finite_orientation(orientation.as_ref(), pos)?;
    let e = reference(entity_ref)?;
    from_current_entity(
        network,
        planned,
        e,
        (entity_ref, &route.name),
        orientation.as_ref(),
        pos,
    )
}

/// Where entity `e` (`names`: its name and the route's) stands on `planned` (module doc,
/// FromCurrentEntity).
fn from_current_entity(
    network: &RoadNetwork,
    planned: &PlannedRoute,
    e: EntityView<'_>,
    (entity_ref, route): (&str, &str),
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    let off_route = || {
        PositionError::new(
            PositionErrorKind::EntityOffRoute {
                entity: entity_ref.to_owned(),
                route: route.to_owned(),
            },
            pos,
        )
    };
    let rp = e.road_position.ok_or_else(off_route)?;
    let path_s = planned
        .path_s_of(&rp.road_id, None, rp.s, 0.0)
        .ok_or_else(off_route)?;
    // The direction of travel is the path's at path_s (at the joint of two stretches the
    // earlier one answers, whose end meets the later one's start).
    let (road_id, s, dir) = at(planned, path_s, pos)?;
    let road_h = network
        .road_pose(road_id, s, 0.0)
        .map_err(|err| road_error(err, pos))?
        .h;
    let road = network
        .road_pose(&rp.road_id, rp.s, rp.t)
        .map_err(|err| road_error(err, pos))?;
    let surface = Pose {
        x: e.pose.x,
        y: e.pose.y,
        z: e.pose.z,
        ..road
    };
    let travel_h = travel_heading(road_h, dir);
    Ok(placed(network, &rp.road_id, surface, orientation, travel_h))
}

/// The pose at `surface` (a road or lane pose) with relative headings counted from
/// `travel_h`, the route's heading of travel there.
fn placed(
    network: &RoadNetwork,
    road_id: &str,
    surface: Pose,
    orientation: Option<&Orientation>,
    travel_h: Real,
) -> ResolvedPosition {
    let a = on_surface(orientation, &surface, travel_h);
    let pose = Pose {
        h: a.h,
        p: a.p,
        r: a.r,
        ..surface
    };
    ResolvedPosition::on_road(network, road_id, pose)
}
