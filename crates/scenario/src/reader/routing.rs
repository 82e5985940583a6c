//! Readers for routes and trajectories (OpenSCENARIO 1.3, "Routes" and "Trajectories", XSD `Route`, `RouteRef`,
//! `Trajectory`, `TrajectoryRef`, `Shape`). The deprecated `Clothoid@curvatureDot` is read as
//! `curvaturePrime`.
//!
//! The schema recurses here (a `RoutePosition` holds a `Route` whose `Waypoint`s hold
//! `Position`s; a `TrajectoryPosition`'s `Shape` is built from `Position`s), so the readers
//! below take the `Position` reader as a parameter, `ReadPosition`, which the callers pass
//! in (`positions::read_position`): `positions` uses `routing`, never the other way round.

use crate::error::{ErrorKind, Result};
use crate::model::{
    Clothoid, ClothoidSpline, ClothoidSplineSegment, ControlPoint, Nurbs, Position, Route, Shape,
    Trajectory, Vertex, Waypoint,
};
use crate::reader::catalog::read_catalog_reference;
use crate::reader::context::{Ctx, Node};

/// The reader of an XSD `Position` element that routes and shapes hold (waypoints,
/// vertices, control points, clothoid starts): `positions::read_position`, passed in.
pub(crate) type ReadPosition = for<'a> fn(&mut Ctx<'a>, Node<'a>) -> Result<Position>;

/// Reads the required child `name` of `parent` with `read_position`.
fn read_position_child<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    name: &str,
    read_position: ReadPosition,
) -> Result<Position> {
    let n = ctx.child(parent, name)?;
    read_position(ctx, n)
}

/// Reads XSD `Route` (inline or as a catalog entry).
pub(crate) fn read_route<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    read_position: ReadPosition,
) -> Result<Route> {
    ctx.scoped(n, |ctx| {
        let mut waypoints = Vec::new();
        for w in ctx.children(n, "Waypoint") {
            waypoints.push(Waypoint {
                route_strategy: ctx.req(w, "routeStrategy")?,
                position: read_position_child(ctx, w, "Position", read_position)?,
            });
        }
        Ok(Route {
            name: ctx.req(n, "name")?,
            closed: ctx.req(n, "closed")?,
            waypoints,
            catalog: None,
        })
    })
}

/// Reads a choice of `Route` or `CatalogReference` (XSD `RouteRef`, `AssignRouteAction`).
pub(crate) fn read_route_ref<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    read_position: ReadPosition,
) -> Result<Route> {
    let c = ctx.choice(n, "Route, CatalogReference")?;
    match c.tag_name().name() {
        "Route" => read_route(ctx, c, read_position),
        "CatalogReference" => {
            let (mut route, origin) = read_catalog_reference(ctx, c, |ctx, e| {
                expect_entry(ctx, e, "Route", |ctx, e| read_route(ctx, e, read_position))
            })?;
            route.catalog = Some(origin);
            Ok(route)
        }
        _ => Err(ctx.unexpected(n, c, "Route, CatalogReference")),
    }
}

/// Reads XSD `Trajectory`.
pub(crate) fn read_trajectory<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    read_position: ReadPosition,
) -> Result<Trajectory> {
    ctx.scoped(n, |ctx| {
        let shape = ctx.child(n, "Shape")?;
        Ok(Trajectory {
            name: ctx.req(n, "name")?,
            closed: ctx.req(n, "closed")?,
            shape: read_shape(ctx, shape, read_position)?,
            catalog: None,
        })
    })
}

/// Reads a choice of `Trajectory` or `CatalogReference` (XSD `TrajectoryRef`; also the
/// deprecated direct children of FollowTrajectoryAction).
pub(crate) fn read_trajectory_ref<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    read_position: ReadPosition,
) -> Result<Trajectory> {
    let c = ctx.choice(n, "Trajectory, CatalogReference")?;
    read_trajectory_or_reference(ctx, n, c, read_position)
}

/// Reads `c`, a `Trajectory` or a `CatalogReference` child of `parent`.
pub(crate) fn read_trajectory_or_reference<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    c: Node<'a>,
    read_position: ReadPosition,
) -> Result<Trajectory> {
    match c.tag_name().name() {
        "Trajectory" => read_trajectory(ctx, c, read_position),
        "CatalogReference" => {
            let (mut t, origin) = read_catalog_reference(ctx, c, |ctx, e| {
                expect_entry(ctx, e, "Trajectory", |ctx, e| {
                    read_trajectory(ctx, e, read_position)
                })
            })?;
            t.catalog = Some(origin);
            Ok(t)
        }
        _ => Err(ctx.unexpected(parent, c, "Trajectory, CatalogReference")),
    }
}

/// Checks that catalog entry `e` is a `kind` element before reading it with `read`.
pub(crate) fn expect_entry<'a, T>(
    ctx: &mut Ctx<'a>,
    e: Node<'a>,
    kind: &str,
    read: impl FnOnce(&mut Ctx<'a>, Node<'a>) -> Result<T>,
) -> Result<T> {
    if e.tag_name().name() != kind {
        return Err(ctx.err(
            e,
            ErrorKind::UnexpectedElement {
                parent: "Catalog".into(),
                found: e.tag_name().name().into(),
                expected: format!("a {kind} entry"),
            },
        ));
    }
    read(ctx, e)
}

/// Reads XSD `Shape`.
fn read_shape<'a>(ctx: &mut Ctx<'a>, n: Node<'a>, read_position: ReadPosition) -> Result<Shape> {
    const EXPECTED: &str = "Polyline, Clothoid, ClothoidSpline, Nurbs";
    let c = ctx.choice(n, EXPECTED)?;
    Ok(match c.tag_name().name() {
        "Polyline" => {
            let mut vertices = Vec::new();
            for v in ctx.children(c, "Vertex") {
                vertices.push(Vertex {
                    time: ctx.opt(v, "time")?,
                    position: read_position_child(ctx, v, "Position", read_position)?,
                });
            }
            Shape::Polyline(vertices)
        }
        "Clothoid" => {
            let prime: Option<f64> = ctx.opt(c, "curvaturePrime")?;
            let dot: Option<f64> = ctx.opt(c, "curvatureDot")?;
            if dot.is_some() {
                ctx.warn(
                    c,
                    "Clothoid@curvatureDot is deprecated, read as curvaturePrime".into(),
                );
            }
            Shape::Clothoid(Clothoid {
                curvature: ctx.req(c, "curvature")?,
                curvature_prime: prime.or(dot).unwrap_or(0.0),
                length: ctx.req(c, "length")?,
                start_time: ctx.opt(c, "startTime")?,
                stop_time: ctx.opt(c, "stopTime")?,
                position: read_position_child(ctx, c, "Position", read_position)?,
            })
        }
        "ClothoidSpline" => {
            ctx.since(c, 3);
            let mut segments = Vec::new();
            for s in ctx.children(c, "ClothoidSplineSegment") {
                let position_start = match ctx.opt_child(s, "PositionStart") {
                    Some(p) => Some(read_position(ctx, p)?),
                    None => None,
                };
                segments.push(ClothoidSplineSegment {
                    curvature_start: ctx.req(s, "curvatureStart")?,
                    curvature_end: ctx.req(s, "curvatureEnd")?,
                    length: ctx.req(s, "length")?,
                    h_offset: ctx.opt(s, "hOffset")?,
                    time_start: ctx.opt(s, "timeStart")?,
                    position_start,
                });
            }
            Shape::ClothoidSpline(ClothoidSpline {
                time_end: ctx.opt(c, "timeEnd")?,
                segments,
            })
        }
        "Nurbs" => {
            let mut control_points = Vec::new();
            for p in ctx.children(c, "ControlPoint") {
                control_points.push(ControlPoint {
                    time: ctx.opt(p, "time")?,
                    weight: ctx.opt(p, "weight")?,
                    position: read_position_child(ctx, p, "Position", read_position)?,
                });
            }
            let mut knots = Vec::new();
            for k in ctx.children(c, "Knot") {
                knots.push(ctx.req(k, "value")?);
            }
            Shape::Nurbs(Nurbs {
                order: ctx.req(c, "order")?,
                control_points,
                knots,
            })
        }
        _ => return Err(ctx.unexpected(n, c, EXPECTED)),
    })
}
