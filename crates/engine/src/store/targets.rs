//! What an action's target asks for now, read from the world (OpenSCENARIO 1.3 §7.7.2.1
//! SpeedAction's `SpeedActionTarget`, §7.7.2.2 LaneChangeAction's `LaneChangeTarget`, and the
//! `entityRef` they and other actions name): used by the actions that run them (module
//! `actions`) and by a user controller that takes them over (module `controller`).

use scenario::{LaneChangeTarget, SourcePos, SpeedTarget, SpeedTargetValueType};

use super::world::World;
use crate::error::Error;
use crate::world::lanes::{lane_shift, numbered_lane};
use crate::world::EntityId;

/// Looks up entity `name` for an action at `pos`: a declared entity that is in the scenario
/// now. A deleted entity (DeleteEntityAction), or one not placed yet, has no state an action
/// could refer to (its last pose and speed are stale), so it is refused as a position's
/// `entityRef` is (position/error.rs).
pub(crate) fn entity_ref(world: &World, name: &str, pos: &SourcePos) -> Result<EntityId, Error> {
    let id = world
        .id(name)
        .ok_or_else(|| Error::at("a declared entity", format!("entityRef '{name}'"), pos))?;
    if !world.entity(id).placed {
        return Err(Error::at(
            format!("a placed entity named \"{name}\""),
            "none (deleted, or not yet placed)",
            pos,
        ));
    }
    Ok(id)
}

/// The speed (m/s) `target` asks for now, a relative one read from its entity's speed; for a
/// user controller holding the longitudinal domain (engine module `controller`).
pub(crate) fn target_speed(
    world: &World,
    target: &SpeedTarget,
    pos: &SourcePos,
) -> Result<f64, Error> {
    let v = match target {
        SpeedTarget::Absolute(v) => *v,
        SpeedTarget::Relative {
            entity_ref: name,
            value,
            speed_target_value_type,
            ..
        } => {
            let v = world.entity(entity_ref(world, name, pos)?).speed;
            match speed_target_value_type {
                SpeedTargetValueType::Delta => v + value,
                _ => v * value,
            }
        }
        // Read when the controller takes it over: the action's start.
        SpeedTarget::RelativeAtStart {
            entity_ref: name,
            value,
        } => world.entity(entity_ref(world, name, pos)?).speed + value,
        _ => return Err(Error::unsupported("this SpeedActionTarget", pos)),
    };
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::at("a finite target speed", format!("{v} m/s"), pos))
    }
}

/// The lane id a LaneChangeTarget names: absolute, counted from the reference entity's lane
/// as seen in its direction of travel, or numbered across the reference's side of its road
/// where it is (`Numbered`).
pub(crate) fn target_lane(
    world: &World,
    target: &LaneChangeTarget,
    pos: &SourcePos,
) -> Result<i32, Error> {
    Ok(match target {
        LaneChangeTarget::Absolute(id) => id
            .trim()
            .parse::<i32>()
            .map_err(|_| Error::at("an OpenDRIVE lane id (integer)", format!("'{id}'"), pos))?,
        LaneChangeTarget::Relative {
            entity_ref: name,
            value,
        } => {
            let reference = world.entity(entity_ref(world, name, pos)?);
            let (Some(rp), Some(track)) = (&reference.road_position, &reference.track) else {
                return Err(Error::at(
                    "a reference entity on a lane",
                    format!("'{name}' off the road"),
                    pos,
                ));
            };
            lane_shift(rp.lane_id, *value, track.direction)
        }
        LaneChangeTarget::Numbered {
            entity_ref: name,
            lane,
            from_left,
        } => {
            let reference = world.entity(entity_ref(world, name, pos)?);
            let Some(track) = &reference.track else {
                return Err(Error::at(
                    "a reference entity on a lane",
                    format!("'{name}' off the road"),
                    pos,
                ));
            };
            let side = if *from_left { "left" } else { "right" };
            world
                .network
                .road(&track.road_id)
                .and_then(|road| {
                    numbered_lane(
                        road,
                        track.lane_id,
                        track.s,
                        track.direction,
                        (*lane, *from_left),
                    )
                })
                .ok_or_else(|| {
                    Error::at(
                        format!(
                            "a driving lane numbered {lane} from the {side} of road {} on the side of '{name}' (lane {}) at s = {:.3} m",
                            track.road_id, track.lane_id, track.s
                        ),
                        "none",
                        pos,
                    )
                })?
        }
        _ => return Err(Error::unsupported("this LaneChangeTarget", pos)),
    })
}
