//! Positions on a route (OpenSCENARIO 1.3 §7.5 "Routes"; XSD `RoutePosition`,
//! `InRoutePosition`: `FromCurrentEntity`, `FromRoadCoordinates`, `FromLaneCoordinates`).
//!
//! The route's path is built from its waypoints: each waypoint's position is resolved, and
//! consecutive waypoints are joined by the road network's shortest lane route
//! (`RoadNetwork::route`, which runs each lane in its driving direction); a closed route also
//! joins the last waypoint to the first. `pathS` is the distance along that path measured on
//! the roads' reference lines (the s-axis of the domain model's routes), from the first
//! waypoint.
//!
//! * FromRoadCoordinates: the road point (s, t) at pathS; t as on that road (left of its
//!   reference line).
//! * FromLaneCoordinates: the centre of lane `laneId` of the road at pathS, plus
//!   `laneOffset` along the road's t-axis.
//! * FromCurrentEntity: where the entity is, if it is on one of the path's stretches.
//!
//! Orientation: relative headings count from the route's direction of travel at the point
//! (the road's s-tangent, turned by π where the route runs towards −s).

use std::f64::consts::PI;

use opendrive::{Direction, LanePosition, Pose, Real, RoadNetwork, S_TOLERANCE};
use scenario::{InRoutePosition, Orientation, Route, SourcePos};

use super::error::road_error;
use super::lane::parse_lane_id;
use super::orientation::on_surface;
use super::world::{entity, finite};
use super::{resolve, EntityQuery, PositionError, PositionErrorKind, ResolvedPosition};

/// One stretch of a route's path: road `road_id` from `s_start` to `s_end`.
#[derive(Debug, Clone, PartialEq)]
struct Stretch {
    road_id: String,
    s_start: Real,
    s_end: Real,
    direction: Direction,
}

/// The path of a route: its stretches in travel order.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RoutePath {
    stretches: Vec<Stretch>,
    length: Real,
}

impl RoutePath {
    /// Builds the path through `route`'s waypoints; errors carry the waypoint's position.
    pub(crate) fn build<Q: EntityQuery + ?Sized>(
        route: &Route,
        ctx: &Q,
        pos: &SourcePos,
    ) -> Result<Self, PositionError> {
        let network = ctx.road_network();
        if route.waypoints.len() < 2 {
            return Err(PositionError::new(
                PositionErrorKind::TooFewWaypoints {
                    route: route.name.clone(),
                    found: route.waypoints.len(),
                },
                pos,
            ));
        }
        let mut points = Vec::with_capacity(route.waypoints.len());
        for wp in &route.waypoints {
            let resolved = resolve(&wp.position, ctx)?;
            let rp = resolved.road_position.ok_or_else(|| {
                PositionError::new(
                    PositionErrorKind::NoRoute {
                        route: route.name.clone(),
                        from: points.len(),
                        to: points.len(),
                    },
                    &wp.position.pos,
                )
            })?;
            points.push(LanePosition {
                road_id: rp.road_id,
                lane_id: rp.lane_id,
                s: rp.s,
                offset: rp.offset,
            });
        }
        let mut pairs: Vec<(usize, usize)> = (1..points.len()).map(|i| (i - 1, i)).collect();
        if route.closed {
            pairs.push((points.len() - 1, 0));
        }
        let mut stretches = Vec::new();
        for (a, b) in pairs {
            let lane_route = network.route(&points[a], &points[b]).ok_or_else(|| {
                PositionError::new(
                    PositionErrorKind::NoRoute {
                        route: route.name.clone(),
                        from: a,
                        to: b,
                    },
                    &route.waypoints[b].position.pos,
                )
            })?;
            for seg in lane_route.segments {
                if (seg.s_end - seg.s_start).abs() > 0.0 {
                    stretches.push(Stretch {
                        road_id: seg.road_id,
                        s_start: seg.s_start,
                        s_end: seg.s_end,
                        direction: seg.direction,
                    });
                }
            }
        }
        let length = stretches.iter().map(|s| (s.s_end - s.s_start).abs()).sum();
        Ok(Self { stretches, length })
    }

    /// Total length of the path (m).
    pub(crate) fn length(&self) -> Real {
        self.length
    }

    /// Road, s and direction at `path_s` (m from the start), `None` beyond the path.
    fn at(&self, path_s: Real) -> Option<(&str, Real, Direction)> {
        if !(-S_TOLERANCE..=self.length + S_TOLERANCE).contains(&path_s) {
            return None;
        }
        let mut start = 0.0;
        for (i, st) in self.stretches.iter().enumerate() {
            let len = (st.s_end - st.s_start).abs();
            if path_s <= start + len || i + 1 == self.stretches.len() {
                let along = (path_s - start).clamp(0.0, len);
                let s = match st.direction {
                    Direction::Forward => st.s_start + along,
                    Direction::Backward => st.s_start - along,
                };
                return Some((&st.road_id, s, st.direction));
            }
            start += len;
        }
        None
    }

    /// pathS of the road point (road_id, s), if it lies on one of the path's stretches.
    pub(crate) fn path_s_of(&self, road_id: &str, s: Real) -> Option<(Real, Direction)> {
        let mut start = 0.0;
        for st in &self.stretches {
            let (lo, hi) = (st.s_start.min(st.s_end), st.s_start.max(st.s_end));
            if st.road_id == road_id && s >= lo - S_TOLERANCE && s <= hi + S_TOLERANCE {
                return Some((start + (s - st.s_start).abs(), st.direction));
            }
            start += (st.s_end - st.s_start).abs();
        }
        None
    }
}

/// Heading of travel on a road whose s-tangent heads `road_h`.
fn travel_heading(road_h: Real, direction: Direction) -> Real {
    match direction {
        Direction::Forward => road_h,
        Direction::Backward => opendrive::normalize_angle(road_h + PI),
    }
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
    let path = RoutePath::build(route, ctx, pos)?;
    let outside = |path_s: Real| {
        PositionError::new(
            PositionErrorKind::OutsideRoute {
                route: route.name.clone(),
                path_s,
                length: path.length(),
            },
            pos,
        )
    };
    match in_route {
        InRoutePosition::FromRoadCoordinates { path_s, t } => {
            finite(&[("pathS", *path_s), ("t", *t)], pos)?;
            let (road_id, s, dir) = path.at(*path_s).ok_or_else(|| outside(*path_s))?;
            let surface = network
                .road_pose(road_id, s, *t)
                .map_err(|e| road_error(e, pos))?;
            Ok(placed(network, road_id, surface, orientation, dir))
        }
        InRoutePosition::FromLaneCoordinates {
            path_s,
            lane_id,
            lane_offset,
        } => {
            let offset = lane_offset.unwrap_or(0.0);
            finite(&[("pathS", *path_s), ("laneOffset", offset)], pos)?;
            let lane_id = parse_lane_id(lane_id, pos)?;
            let (road_id, s, dir) = path.at(*path_s).ok_or_else(|| outside(*path_s))?;
            let surface = network
                .lane_pose(road_id, lane_id, s, offset)
                .map_err(|e| road_error(e, pos))?;
            Ok(placed(network, road_id, surface, orientation, dir))
        }
        InRoutePosition::FromCurrentEntity { entity_ref } => {
            let e = entity(ctx, entity_ref, pos)?;
            let off_route = || {
                PositionError::new(
                    PositionErrorKind::EntityOffRoute {
                        entity: entity_ref.clone(),
                        route: route.name.clone(),
                    },
                    pos,
                )
            };
            let rp = e.road_position.ok_or_else(off_route)?;
            let (_, dir) = path.path_s_of(&rp.road_id, rp.s).ok_or_else(off_route)?;
            let road_h = network
                .road_pose(&rp.road_id, rp.s, 0.0)
                .map_err(|err| road_error(err, pos))?
                .h;
            let surface = Pose {
                h: road_h,
                ..e.pose
            };
            Ok(placed(network, &rp.road_id, surface, orientation, dir))
        }
        _ => Err(PositionError::new(
            PositionErrorKind::Unsupported {
                expected: "FromCurrentEntity, FromRoadCoordinates or FromLaneCoordinates",
                found: "another InRoutePosition form",
            },
            pos,
        )),
    }
}

/// The pose at `surface` (a road or lane pose) oriented for travel in `dir`.
fn placed(
    network: &RoadNetwork,
    road_id: &str,
    surface: Pose,
    orientation: Option<&Orientation>,
    dir: Direction,
) -> ResolvedPosition {
    let a = on_surface(orientation, &surface, travel_heading(surface.h, dir));
    let pose = Pose {
        h: a.h,
        p: a.p,
        r: a.r,
        ..surface
    };
    ResolvedPosition::on_road(network, road_id, pose)
}
