//! Readers for positions (OpenSCENARIO 1.3, "Positions", XSD `Position`, `Orientation`,
//! `InRoutePosition`). The 1.0 GeoPosition attributes `latitude`/`longitude` (rad) and
//! `height` are read into the 1.3 `latitudeDeg`/`longitudeDeg`/`altitude`, with a warning.

use crate::error::{ErrorKind, Result};
use crate::model::{InRoutePosition, Orientation, Position, PositionKind};
use crate::reader::context::{Ctx, Node};
use crate::reader::routing::{read_route_ref, read_trajectory_ref};

const POSITIONS: &str = "WorldPosition, RelativeWorldPosition, RelativeObjectPosition, RoadPosition, \
RelativeRoadPosition, LanePosition, RelativeLanePosition, RoutePosition, GeoPosition, TrajectoryPosition";

/// Reads a required child `name` (e.g. `Position`, `TargetPosition`) of `parent`.
pub(crate) fn read_position_child<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    name: &str,
) -> Result<Position> {
    let n = ctx.child(parent, name)?;
    read_position(ctx, n)
}

/// Reads XSD `Position`.
pub(crate) fn read_position<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Position> {
    ctx.check_depth(n)?;
    let c = ctx.choice(n, POSITIONS)?;
    let pos = ctx.pos(c);
    let orientation = read_orientation_child(ctx, c)?;
    let kind = match c.tag_name().name() {
        "WorldPosition" => PositionKind::World {
            x: ctx.req(c, "x")?,
            y: ctx.req(c, "y")?,
            z: ctx.opt(c, "z")?,
            h: ctx.opt(c, "h")?,
            p: ctx.opt(c, "p")?,
            r: ctx.opt(c, "r")?,
        },
        "RelativeWorldPosition" => PositionKind::RelativeWorld {
            entity_ref: ctx.entity(c, "entityRef")?,
            dx: ctx.req(c, "dx")?,
            dy: ctx.req(c, "dy")?,
            dz: ctx.opt(c, "dz")?,
            orientation,
        },
        "RelativeObjectPosition" => PositionKind::RelativeObject {
            entity_ref: ctx.entity(c, "entityRef")?,
            dx: ctx.req(c, "dx")?,
            dy: ctx.req(c, "dy")?,
            dz: ctx.opt(c, "dz")?,
            orientation,
        },
        "RoadPosition" => PositionKind::Road {
            road_id: ctx.req(c, "roadId")?,
            s: ctx.req(c, "s")?,
            t: ctx.req(c, "t")?,
            orientation,
        },
        "RelativeRoadPosition" => PositionKind::RelativeRoad {
            entity_ref: ctx.entity(c, "entityRef")?,
            ds: ctx.req(c, "ds")?,
            dt: ctx.req(c, "dt")?,
            orientation,
        },
        "LanePosition" => PositionKind::Lane {
            road_id: ctx.req(c, "roadId")?,
            lane_id: ctx.req(c, "laneId")?,
            s: ctx.req(c, "s")?,
            offset: ctx.opt(c, "offset")?,
            orientation,
        },
        "RelativeLanePosition" => {
            let ds_lane = ctx.opt(c, "dsLane")?;
            if ds_lane.is_some() {
                ctx.since(c, 1);
            }
            PositionKind::RelativeLane {
                entity_ref: ctx.entity(c, "entityRef")?,
                d_lane: ctx.req(c, "dLane")?,
                ds: ctx.opt(c, "ds")?,
                ds_lane,
                offset: ctx.opt(c, "offset")?,
                orientation,
            }
        }
        "RoutePosition" => {
            let route_ref = ctx.child(c, "RouteRef")?;
            let route = read_route_ref(ctx, route_ref, read_position)?;
            let in_route = ctx.child(c, "InRoutePosition")?;
            let in_route = read_in_route_position(ctx, in_route)?;
            PositionKind::Route {
                route: Box::new(route),
                orientation,
                in_route,
            }
        }
        "GeoPosition" => read_geo_position(ctx, c, orientation)?,
        "TrajectoryPosition" => {
            ctx.since(c, 1);
            let trajectory_ref = ctx.child(c, "TrajectoryRef")?;
            let trajectory = read_trajectory_ref(ctx, trajectory_ref, read_position)?;
            PositionKind::Trajectory {
                trajectory: Box::new(trajectory),
                s: ctx.req(c, "s")?,
                t: ctx.opt(c, "t")?,
                orientation,
            }
        }
        _ => return Err(ctx.unexpected(n, c, POSITIONS)),
    };
    Ok(Position { kind, pos })
}

/// Reads XSD `GeoPosition`, mapping the 1.0 radian attributes onto degrees.
fn read_geo_position<'a>(
    ctx: &mut Ctx<'a>,
    c: Node<'a>,
    orientation: Option<Orientation>,
) -> Result<PositionKind> {
    let old_lat: Option<f64> = ctx.opt(c, "latitude")?;
    let old_lon: Option<f64> = ctx.opt(c, "longitude")?;
    let old_height: Option<f64> = ctx.opt(c, "height")?;
    if old_lat.is_some() || old_lon.is_some() || old_height.is_some() {
        ctx.warn(c, "GeoPosition@latitude/longitude/height are deprecated (rad), read as latitudeDeg/longitudeDeg/altitude".into());
    }
    let latitude_deg = match ctx.opt(c, "latitudeDeg")? {
        Some(v) => v,
        None => old_lat.map(f64::to_degrees).ok_or_else(|| {
            ctx.err(
                c,
                ErrorKind::MissingAttribute {
                    element: "GeoPosition".into(),
                    attribute: "latitudeDeg",
                },
            )
        })?,
    };
    let longitude_deg = match ctx.opt(c, "longitudeDeg")? {
        Some(v) => v,
        None => old_lon.map(f64::to_degrees).ok_or_else(|| {
            ctx.err(
                c,
                ErrorKind::MissingAttribute {
                    element: "GeoPosition".into(),
                    attribute: "longitudeDeg",
                },
            )
        })?,
    };
    Ok(PositionKind::Geo {
        latitude_deg,
        longitude_deg,
        altitude: ctx.opt(c, "altitude")?.or(old_height),
        vertical_road_selection: ctx.opt(c, "verticalRoadSelection")?,
        orientation,
    })
}

/// Reads the optional `Orientation` child of `n`.
pub(crate) fn read_orientation_child<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
) -> Result<Option<Orientation>> {
    let Some(o) = ctx.opt_child(n, "Orientation") else {
        return Ok(None);
    };
    Ok(Some(Orientation {
        h: ctx.opt(o, "h")?.unwrap_or(0.0),
        p: ctx.opt(o, "p")?.unwrap_or(0.0),
        r: ctx.opt(o, "r")?.unwrap_or(0.0),
        reference: ctx.opt(o, "type")?,
    }))
}

/// Reads XSD `InRoutePosition`.
fn read_in_route_position<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<InRoutePosition> {
    const EXPECTED: &str = "FromCurrentEntity, FromRoadCoordinates, FromLaneCoordinates";
    let c = ctx.choice(n, EXPECTED)?;
    Ok(match c.tag_name().name() {
        "FromCurrentEntity" => InRoutePosition::FromCurrentEntity {
            entity_ref: ctx.entity(c, "entityRef")?,
        },
        "FromRoadCoordinates" => InRoutePosition::FromRoadCoordinates {
            path_s: ctx.req(c, "pathS")?,
            t: ctx.req(c, "t")?,
        },
        "FromLaneCoordinates" => InRoutePosition::FromLaneCoordinates {
            path_s: ctx.req(c, "pathS")?,
            lane_id: ctx.req(c, "laneId")?,
            lane_offset: ctx.opt(c, "laneOffset")?,
        },
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}
