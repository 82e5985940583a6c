//! The front door: [`resolve`] dispatches a `scenario::Position` (OpenSCENARIO 1.3 §7.4, XSD
//! `Position` and its ten choices) to the module of its form.
//!
//! GeoPosition (WGS 84 latitude/longitude, OpenSCENARIO 1.3 XSD `GeoPosition`) goes through the
//! road network's `geoReference` and `offset` to the network's x/y (opendrive's
//! `GeoTransform`, OpenDRIVE 1.8 §8.5), and from there it is a WorldPosition: `altitude` is
//! the height above the WGS 84 ellipsoid, which oscsim does not map (no geoid model), so z is
//! the road surface's as for a WorldPosition without z; an Orientation (absent `type` too) is
//! absolute in the network's x/y frame, and `type="relative"` is refused: a GeoPosition has no
//! reference to be relative to.

use scenario::{InRoutePosition, Orientation, Position, PositionKind, Route, Shape};

use super::lane::{lane, parse_lane_id, relative_lane, Along};
use super::road::{relative_road, road};
use super::route::route_position;
use super::trajectory::trajectory_position;
use super::world::{entity, finite_orientation, geo, relative, world};
use super::{EntityQuery, EntityView, PositionError, PositionErrorKind, ResolvedPosition};

/// Resolves `position` to a world pose and road position, reading reference entities and the
/// road network from `ctx`. Errors name the position's file, line and column.
pub fn resolve<Q: EntityQuery + ?Sized>(
    position: &Position,
    ctx: &Q,
) -> Result<ResolvedPosition, PositionError> {
    resolve_with(position, ctx, |name| entity(ctx, name, &position.pos))
}

/// What a position needs besides the road network, by its form: nothing (WorldPosition,
/// RoadPosition, LanePosition, GeoPosition, and a RoutePosition or TrajectoryPosition whose
/// route's waypoints or trajectory's points need nothing), the one entity a relative form names
/// (RelativeWorldPosition, RelativeObjectPosition, RelativeRoadPosition,
/// RelativeLanePosition), a route that needs nothing and the entity on it (RoutePosition
/// FromCurrentEntity), or a route or trajectory planned from positions that name entities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Needs<'p> {
    /// Only the road network (and, for a route, the run's routing options): the same pose
    /// whenever it is resolved.
    Nothing,
    /// The entity `entityRef` names, with the XSD element and attribute it is written in.
    Entity(&'p str, &'static str),
    /// RoutePosition `FromCurrentEntity` on `route`, whose waypoints need nothing: the route's
    /// plan is the same whenever it is planned; where the entity `entityRef` names stands on
    /// it is read when the position is resolved.
    OnRoute(&'p Route, &'p str),
    /// A route or trajectory with a waypoint or point that names an entity (or a shape drawn
    /// from the actor): planned anew whenever it is resolved.
    Plan,
}

/// What `position` needs to be resolved ([`Needs`]).
pub(crate) fn needs(position: &Position) -> Needs<'_> {
    match &position.kind {
        PositionKind::RelativeWorld { entity_ref, .. } => {
            Needs::Entity(entity_ref, "RelativeWorldPosition@entityRef")
        }
        PositionKind::RelativeObject { entity_ref, .. } => {
            Needs::Entity(entity_ref, "RelativeObjectPosition@entityRef")
        }
        PositionKind::RelativeRoad { entity_ref, .. } => {
            Needs::Entity(entity_ref, "RelativeRoadPosition@entityRef")
        }
        PositionKind::RelativeLane { entity_ref, .. } => {
            Needs::Entity(entity_ref, "RelativeLanePosition@entityRef")
        }
        PositionKind::Route {
            route, in_route, ..
        } => {
            if !route.waypoints.iter().all(|w| entity_free(&w.position)) {
                return Needs::Plan;
            }
            match in_route {
                InRoutePosition::FromCurrentEntity { entity_ref } => {
                    Needs::OnRoute(route, entity_ref)
                }
                _ => Needs::Nothing,
            }
        }
        PositionKind::Trajectory { trajectory, .. } => {
            if shape_entity_free(&trajectory.shape) {
                Needs::Nothing
            } else {
                Needs::Plan
            }
        }
        _ => Needs::Nothing,
    }
}

/// `position` resolves to the same pose whenever it is resolved ([`Needs::Nothing`]).
fn entity_free(position: &Position) -> bool {
    matches!(needs(position), Needs::Nothing)
}

/// Every point a trajectory's shape is drawn through needs no entity (OpenSCENARIO 1.3 §6.9:
/// Vertex, Clothoid, ClothoidSplineSegment's PositionStart and ControlPoint each hold a
/// Position). oscsim's shapes drawn from the actor, and a form this engine does not know, are
/// taken to need one.
fn shape_entity_free(shape: &Shape) -> bool {
    match shape {
        Shape::Polyline(vertices) => vertices.iter().all(|v| entity_free(&v.position)),
        Shape::Clothoid(c) => entity_free(&c.position),
        Shape::ClothoidSpline(spline) => spline
            .segments
            .iter()
            .filter_map(|g| g.position_start.as_ref())
            .all(entity_free),
        Shape::Nurbs(n) => n.control_points.iter().all(|c| entity_free(&c.position)),
        _ => false,
    }
}

/// [`resolve`] with the reference entity of a relative form given by `reference` (called with
/// the form's `entityRef`, at most once, where [`resolve`] looks the name up in `ctx`): a
/// caller that resolved the name before (a condition's position, condition/refs.rs) reads the
/// entity by id. Routes and trajectories still read their names from `ctx`.
pub(crate) fn resolve_with<'q, Q: EntityQuery + ?Sized>(
    position: &Position,
    ctx: &'q Q,
    reference: impl FnOnce(&str) -> Result<EntityView<'q>, PositionError>,
) -> Result<ResolvedPosition, PositionError> {
    let pos = &position.pos;
    let network = ctx.road_network();
    finite_orientation(orientation_of(&position.kind), pos)?;
    match &position.kind {
        PositionKind::World { x, y, z, h, p, r } => world(network, *x, *y, *z, [*h, *p, *r], pos),
        PositionKind::RelativeWorld {
            entity_ref,
            dx,
            dy,
            dz,
            orientation,
        }
        | PositionKind::RelativeObject {
            entity_ref,
            dx,
            dy,
            dz,
            orientation,
        } => {
            let in_object_axes = matches!(position.kind, PositionKind::RelativeObject { .. });
            relative(
                network,
                entity_ref,
                reference,
                [*dx, *dy],
                *dz,
                orientation.as_ref(),
                in_object_axes,
                pos,
            )
        }
        PositionKind::Road {
            road_id,
            s,
            t,
            orientation,
        } => road(network, road_id, [*s, *t], orientation.as_ref(), pos),
        PositionKind::RelativeRoad {
            entity_ref,
            ds,
            dt,
            orientation,
        } => relative_road(
            network,
            entity_ref,
            reference,
            [*ds, *dt],
            orientation.as_ref(),
            pos,
        ),
        PositionKind::Lane {
            road_id,
            lane_id,
            s,
            offset,
            orientation,
        } => {
            let lane_id = parse_lane_id(lane_id, pos)?;
            let offset = offset.unwrap_or(0.0);
            lane(
                network,
                road_id,
                lane_id,
                [*s, offset],
                orientation.as_ref(),
                pos,
            )
        }
        PositionKind::RelativeLane {
            entity_ref,
            d_lane,
            ds,
            ds_lane,
            offset,
            orientation,
        } => {
            // The XSD makes ds and dsLane mutually exclusive; with neither, ds = 0.
            let along = match (ds, ds_lane) {
                (_, Some(d)) => Along::Lane(*d),
                (Some(d), None) => Along::Road(*d),
                (None, None) => Along::Road(0.0),
            };
            relative_lane(
                network,
                entity_ref,
                reference,
                *d_lane,
                along,
                offset.unwrap_or(0.0),
                orientation.as_ref(),
                pos,
            )
        }
        PositionKind::Route {
            route,
            orientation,
            in_route,
        } => route_position(ctx, route, in_route, orientation.as_ref(), pos),
        PositionKind::Trajectory {
            trajectory,
            s,
            t,
            orientation,
        } => trajectory_position(
            ctx,
            trajectory,
            *s,
            t.unwrap_or(0.0),
            orientation.as_ref(),
            pos,
        ),
        PositionKind::Geo {
            latitude_deg,
            longitude_deg,
            altitude,
            orientation,
            ..
        } => geo(
            network,
            [*latitude_deg, *longitude_deg],
            *altitude,
            orientation.as_ref(),
            pos,
        ),
        _ => Err(PositionError::new(
            PositionErrorKind::Unsupported {
                expected: "one of the ten Position forms of OpenSCENARIO 1.3",
                found: "another form",
            },
            pos,
        )),
    }
}

/// The Orientation element of a position, if it has one.
pub(crate) fn orientation_of(kind: &PositionKind) -> Option<&Orientation> {
    match kind {
        PositionKind::RelativeWorld { orientation, .. }
        | PositionKind::RelativeObject { orientation, .. }
        | PositionKind::Road { orientation, .. }
        | PositionKind::RelativeRoad { orientation, .. }
        | PositionKind::Lane { orientation, .. }
        | PositionKind::RelativeLane { orientation, .. }
        | PositionKind::Route { orientation, .. }
        | PositionKind::Geo { orientation, .. }
        | PositionKind::Trajectory { orientation, .. } => orientation.as_ref(),
        _ => None,
    }
}
