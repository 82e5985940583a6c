//! TeleportAction (OpenSCENARIO 1.3 §7.7.2.4, XSD `TeleportAction`): put the actor at a
//! position at once. Takes no control domain.
//!
//! Positions (§7.4) resolved here: World, RelativeWorld, RelativeObject, Road, RelativeRoad,
//! Lane, RelativeLane. Route and Trajectory positions are answered by the position resolver
//! (module `position`) once it lands; until then they, and Geo without a geo reference, are a
//! clear "not supported" error naming the position. Orientation: absolute for World positions,
//! relative to the road (Road, RelativeRoad) or to the lane's direction of travel (Lane,
//! RelativeLane) when the `Orientation` element gives no `type` (semantics-pitfalls #15), and
//! relative to the reference entity for the relative object/world forms.

use opendrive::{normalize_angle, Pose, Real};
use scenario::{Orientation, Position, PositionKind, ReferenceContext};

use super::speed::entity_ref;
use crate::runtime::entity::EntityId;
use crate::runtime::error::RuntimeError;
use crate::runtime::lanes::lane_shift;
use crate::runtime::world::{Heading, World};

/// Applies an orientation to a base heading: (absolute h, or base + h for relative).
fn heading(o: Option<&Orientation>, base: Real, default_relative: bool) -> Option<Real> {
    let o = o?;
    let relative = match o.reference {
        Some(ReferenceContext::Relative) => true,
        Some(ReferenceContext::Absolute) => false,
        _ => default_relative,
    };
    Some(if relative {
        normalize_angle(base + o.h)
    } else {
        normalize_angle(o.h)
    })
}

/// Teleports `actor` to `position`.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    position: &Position,
) -> Result<(), RuntimeError> {
    let pos = &position.pos;
    let road_err = |e: opendrive::Error| {
        RuntimeError::at("a position on the road network", e.to_string(), pos)
    };
    match &position.kind {
        PositionKind::World { x, y, z, h, p, r } => {
            let pose = Pose {
                x: *x,
                y: *y,
                z: z.unwrap_or(0.0),
                h: h.unwrap_or(0.0),
                p: p.unwrap_or(0.0),
                r: r.unwrap_or(0.0),
            };
            world.place(actor, pose);
            if z.is_none() {
                lift_to_road(world, actor);
            }
        }
        PositionKind::RelativeWorld {
            entity_ref: name,
            dx,
            dy,
            dz,
            orientation,
        } => {
            let base = world.entity(entity_ref(world, name, pos)?).pose;
            let pose = Pose {
                x: base.x + dx,
                y: base.y + dy,
                z: base.z + dz.unwrap_or(0.0),
                h: heading(orientation.as_ref(), base.h, true).unwrap_or(base.h),
                ..base
            };
            world.place(actor, pose);
        }
        PositionKind::RelativeObject {
            entity_ref: name,
            dx,
            dy,
            dz,
            orientation,
        } => {
            let base = world.entity(entity_ref(world, name, pos)?).pose;
            let (c, s) = (base.h.cos(), base.h.sin());
            let pose = Pose {
                x: base.x + c * dx - s * dy,
                y: base.y + s * dx + c * dy,
                z: base.z + dz.unwrap_or(0.0),
                h: heading(orientation.as_ref(), base.h, true).unwrap_or(base.h),
                ..base
            };
            world.place(actor, pose);
        }
        PositionKind::Road {
            road_id,
            s,
            t,
            orientation,
        } => {
            road_place(world, actor, road_id, *s, *t, orientation.as_ref(), pos)?;
        }
        PositionKind::RelativeRoad {
            entity_ref: name,
            ds,
            dt,
            orientation,
        } => {
            let r = world.entity(entity_ref(world, name, pos)?);
            let Some(rp) = r.road_position.clone() else {
                return Err(RuntimeError::at(
                    "a reference entity on a road",
                    format!("'{name}' off the road"),
                    pos,
                ));
            };
            road_place(
                world,
                actor,
                &rp.road_id,
                rp.s + ds,
                rp.t + dt,
                orientation.as_ref(),
                pos,
            )?;
        }
        PositionKind::Lane {
            road_id,
            lane_id,
            s,
            offset,
            orientation,
        } => {
            let lane = parse_lane(lane_id, pos)?;
            let heading = lane_heading(orientation.as_ref());
            world
                .place_on_lane(actor, road_id, lane, *s, offset.unwrap_or(0.0), heading)
                .map_err(road_err)?;
        }
        PositionKind::RelativeLane {
            entity_ref: name,
            d_lane,
            ds,
            ds_lane,
            offset,
            orientation,
        } => {
            let r = world.entity(entity_ref(world, name, pos)?);
            let (Some(rp), Some(track)) = (r.road_position.clone(), r.track.clone()) else {
                return Err(RuntimeError::at(
                    "a reference entity on a lane",
                    format!("'{name}' off the road"),
                    pos,
                ));
            };
            let lane = lane_shift(rp.lane_id, *d_lane, track.direction);
            let along = if track.direction == opendrive::Direction::Forward {
                1.0
            } else {
                -1.0
            };
            let s = rp.s + ds.unwrap_or(0.0) + ds_lane.unwrap_or(0.0) * along;
            let heading = lane_heading(orientation.as_ref());
            world
                .place_on_lane(actor, &rp.road_id, lane, s, offset.unwrap_or(0.0), heading)
                .map_err(road_err)?;
        }
        PositionKind::Geo { .. } => {
            return Err(RuntimeError::unsupported(
                "GeoPosition (the road network has no geo reference in use)",
                pos,
            ))
        }
        PositionKind::Route { .. } => return Err(RuntimeError::unsupported("RoutePosition", pos)),
        PositionKind::Trajectory { .. } => {
            return Err(RuntimeError::unsupported("TrajectoryPosition", pos))
        }
        _ => return Err(RuntimeError::unsupported("this Position", pos)),
    }
    Ok(())
}

/// The heading of a lane position's orientation (relative to the lane unless absolute).
fn lane_heading(o: Option<&Orientation>) -> Heading {
    match o {
        Some(o) if o.reference == Some(ReferenceContext::Absolute) => Heading::Absolute(o.h),
        Some(o) => Heading::Relative(o.h),
        None => Heading::Relative(0.0),
    }
}

fn parse_lane(lane_id: &str, pos: &scenario::SourcePos) -> Result<i32, RuntimeError> {
    lane_id.trim().parse().map_err(|_| {
        RuntimeError::at(
            "an OpenDRIVE lane id (integer)",
            format!("laneId '{lane_id}'"),
            pos,
        )
    })
}

fn road_place(
    world: &mut World,
    actor: EntityId,
    road_id: &str,
    s: Real,
    t: Real,
    orientation: Option<&Orientation>,
    pos: &scenario::SourcePos,
) -> Result<(), RuntimeError> {
    let mut pose = world
        .network
        .road_pose(road_id, s, t)
        .map_err(|e| RuntimeError::at("a position on the road network", e.to_string(), pos))?;
    match heading(orientation, pose.h, true) {
        Some(h) => pose.h = h,
        None => {
            if let Some((lane, offset)) = world.lane_and_offset(road_id, s, t) {
                // No orientation: along the lane's direction of travel.
                return world
                    .place_on_lane(actor, road_id, lane, s, offset, Heading::Relative(0.0))
                    .map_err(|e| {
                        RuntimeError::at("a position on the road network", e.to_string(), pos)
                    });
            }
        }
    }
    world.place(actor, pose);
    Ok(())
}

/// A world position without z sits on the road surface when it lies on a road.
fn lift_to_road(world: &mut World, actor: EntityId) {
    let e = world.entity(actor);
    if let Some(rp) = &e.road_position {
        if let Ok(p) = world.network.road_pose(&rp.road_id, rp.s, rp.t) {
            let e = world.entity_mut(actor);
            e.pose.z = p.z;
        }
    }
}
