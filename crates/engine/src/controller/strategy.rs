//! Motion actions on a domain a user controller holds are handed to it (the rule and the
//! models' readings are in the module doc of `controller`).

use scenario::{
    LateralAction, LongitudinalAction, ModelAcceleration, PrivateAction, RoutingAction, SpeedOf,
};

use super::assign::Origin;
use super::command::{FreeAcceleration, Strategy};
use super::properties::{ControllerKind, ModelSettings};
use super::table::ControllerTable;
use crate::error::Error;
use crate::output::EventRecord;
use crate::store::targets::{entity_ref, target_lane, target_speed};
use crate::store::World;
use crate::world::EntityId;

/// The motion domains `action` would take (longitudinal, lateral), and its element name.
fn domains(action: &PrivateAction) -> Option<(bool, bool, &'static str)> {
    Some(match action {
        PrivateAction::Longitudinal(l) => (
            true,
            false,
            match l {
                LongitudinalAction::Speed { .. } => "SpeedAction",
                LongitudinalAction::SpeedProfile { .. } => "SpeedProfileAction",
                LongitudinalAction::Acceleration { .. } => "AccelerationAction",
                LongitudinalAction::RelativeAcceleration { .. } => "RelativeAccelerationAction",
                LongitudinalAction::ModelAcceleration { .. } => "AccelerationAction",
                LongitudinalAction::Travel(_) => "TravelAction",
                _ => "LongitudinalDistanceAction",
            },
        ),
        PrivateAction::Lateral(l) => (
            false,
            true,
            match l {
                LateralAction::LaneChange { .. }
                | LateralAction::LaneChangeAt(_)
                | LateralAction::FollowLanes(_)
                | LateralAction::MandatoryLane { .. } => "LaneChangeAction",
                LateralAction::LaneOffset { .. } | LateralAction::OffsetInWidth(_) => {
                    "LaneOffsetAction"
                }
                _ => "LateralDistanceAction",
            },
        ),
        PrivateAction::Synchronize(_) => (true, false, "SynchronizeAction"),
        PrivateAction::Routing(r) => match &**r {
            RoutingAction::FollowTrajectory { time_reference, .. } => {
                (time_reference.is_some(), true, "FollowTrajectoryAction")
            }
            RoutingAction::FollowTrajectoryAtSpeed(_) => (true, true, "FollowTrajectoryAction"),
            _ => return None,
        },
        _ => return None,
    })
}

/// The strategy a model can take from `action`, if any.
fn strategy(
    world: &World,
    action: &PrivateAction,
    origin: &Origin<'_>,
) -> Result<Option<Strategy>, Error> {
    Ok(match action {
        PrivateAction::Longitudinal(LongitudinalAction::Speed { target, .. }) => {
            Some(Strategy::Speed(target_speed(world, target, origin.pos)?))
        }
        PrivateAction::Longitudinal(LongitudinalAction::SpeedProfile {
            entity_ref,
            entries,
            ..
        }) => {
            let base = match entity_ref {
                Some(name) => {
                    let id = world.id(name).ok_or_else(|| {
                        Error::at(
                            "a declared entity",
                            format!("entityRef '{name}'"),
                            origin.pos,
                        )
                    })?;
                    world.entity(id).speed
                }
                None => 0.0,
            };
            entries.last().map(|e| Strategy::Speed(base + e.speed))
        }
        PrivateAction::Longitudinal(LongitudinalAction::ModelAcceleration { target }) => {
            Some(match target {
                Some(ModelAcceleration::Toward { speed, rate, of }) => {
                    // Relative to x: x's speed now plus `speed`, fixed (projected), or read
                    // by the model at every step.
                    let (speed, of) = match of {
                        None => (*speed, None),
                        Some(SpeedOf {
                            entity_ref: name,
                            projected,
                        }) => {
                            let x = entity_ref(world, name, origin.pos)?;
                            match projected {
                                true => (world.entity(x).speed + speed, None),
                                false => (*speed, Some(x)),
                            }
                        }
                    };
                    Strategy::FreeAccelerationToward {
                        speed,
                        rate: free_acceleration(world, rate, origin)?,
                        of,
                    }
                }
                Some(t) => Strategy::FreeAcceleration(Some(free_acceleration(world, t, origin)?)),
                None => Strategy::FreeAcceleration(None),
            })
        }
        PrivateAction::Lateral(LateralAction::LaneChange { target, .. }) => {
            Some(Strategy::Lane(target_lane(world, target, origin.pos)?))
        }
        PrivateAction::Lateral(LateralAction::LaneChangeAt(at)) => {
            Some(Strategy::Lane(target_lane(world, &at.target, origin.pos)?))
        }
        PrivateAction::Lateral(LateralAction::MandatoryLane { target }) => {
            Some(Strategy::MandatoryLane(match target {
                Some(t) => Some(target_lane(world, t, origin.pos)?),
                None => None,
            }))
        }
        _ => None,
    })
}

/// The free-road acceleration `target` asks for as the model takes it: a reference's
/// acceleration read once is its value now (measured by its last move), plus the value.
fn free_acceleration(
    world: &World,
    target: &ModelAcceleration,
    origin: &Origin<'_>,
) -> Result<FreeAcceleration, Error> {
    Ok(match target {
        ModelAcceleration::Absolute(a) => FreeAcceleration::Fixed(*a),
        ModelAcceleration::Relative {
            entity_ref,
            value,
            continuous,
        } => {
            let reference = world.id(entity_ref).ok_or_else(|| {
                Error::at(
                    "a declared entity",
                    format!("entityRef '{entity_ref}'"),
                    origin.pos,
                )
            })?;
            let x = world.entity(reference);
            match continuous {
                true => FreeAcceleration::Follow {
                    reference,
                    value: *value,
                },
                false => FreeAcceleration::Fixed(
                    x.travel_component(x.acceleration.translational) + value,
                ),
            }
        }
        // A rate toward a speed as the rate of another (the DSL runtime writes none), and
        // `ModelAcceleration` is non-exhaustive: a target this engine does not know.
        _ => return Err(Error::unsupported("this ModelAcceleration", origin.pos)),
    })
}

/// Whether `lane` is a drivable lane of `actor`'s road where it is, driven the way the actor
/// travels (a lane a model can change into).
fn drivable_same_way(world: &World, actor: EntityId, lane: i32) -> bool {
    let Some(track) = &world.entity(actor).track else {
        return false;
    };
    let net = &world.network;
    let (Some(own), Some(to)) = (
        net.lane_handle_on(track.road, track.lane_id, track.s),
        net.lane_handle_on(track.road, lane, track.s),
    ) else {
        return false;
    };
    let drivable = net
        .road_at(track.road)
        .lane_section_at(track.s)
        .lane(lane)
        .is_some_and(|l| l.lane_type.is_drivable());
    drivable && net.driving_direction(own) == net.driving_direction(to)
}

/// When `action` is a motion action on a domain a user controller of `actor` holds, hands it
/// to that controller, logs what the controller made of it and returns `true`: the action
/// then completes at once. `init`: the action belongs to the Init (a SpeedAction also sets
/// the speed).
pub(crate) fn hand_over(
    world: &mut World,
    controllers: &mut ControllerTable,
    actor: EntityId,
    action: &PrivateAction,
    init: bool,
    origin: &Origin<'_>,
    events: &mut Vec<EventRecord>,
) -> Result<bool, Error> {
    let Some((lon, lat, kind)) = domains(action) else {
        return Ok(false);
    };
    let Some(ctrl) = controllers.of(actor.index()) else {
        return Ok(false);
    };
    // A mandatory lane where no user controller holds the lateral domain goes to the `idm`
    // holding the longitudinal one: it decides when each change starts (module `mobil`, "A
    // mandatory lane"), the default controller keeping the lateral domain carries it out.
    let mandatory_to_idm = || {
        let slot = ctrl.holder(true)?;
        let idm = matches!(
            ctrl.assigned[slot].kind,
            ControllerKind::Model {
                settings: ModelSettings::Idm { .. },
                ..
            }
        );
        (idm && matches!(
            action,
            PrivateAction::Lateral(LateralAction::MandatoryLane { .. })
        ))
        .then_some(slot)
    };
    let holder = (lon.then(|| ctrl.holder(true)).flatten())
        .or_else(|| lat.then(|| ctrl.holder(false)).flatten())
        .or_else(mandatory_to_idm);
    let Some(slot) = holder else {
        return Ok(false);
    };
    let s = strategy(world, action, origin)?;
    if let (true, Some(Strategy::Speed(v))) = (init, s) {
        let e = world.entity_mut(actor);
        e.speed = v.clamp(-e.max_speed(), e.max_speed());
    }
    let entity = world.entity(actor).name.clone();
    // A lane no model could change into: none of the road's there, not drivable, or driven the
    // other way (lane ids count across the centre line): the entity keeps its lane.
    let no_lane = match s {
        Some(Strategy::Lane(lane) | Strategy::MandatoryLane(Some(lane))) => {
            !drivable_same_way(world, actor, lane)
        }
        _ => false,
    };
    let taken = match (s, controllers.instance_mut(actor.index(), slot)) {
        (Some(Strategy::Lane(lane) | Strategy::MandatoryLane(Some(lane))), Some(_)) if no_lane => Some(format!(
            "ignored: no drivable lane {lane} driven the same way beside the entity, it keeps its lane"
        )),
        (Some(s), Some(instance)) => instance.strategy(s),
        _ => None,
    };
    // A mandatory lane taken: the controller may lose it on a road its links do not reach,
    // which it notes (controller/mobil.rs "Across roads").
    if let (Some(Strategy::MandatoryLane(Some(_))), Some(_), false) = (s, &taken, no_lane) {
        controllers.note_from(actor.index(), slot, origin.element);
    }
    let Some(a) = controllers
        .of(actor.index())
        .and_then(|c| c.assigned.get(slot))
    else {
        return Ok(true);
    };
    let note = match taken {
        Some(what) if no_lane => format!("{kind} {what}"),
        Some(what) => format!("{kind} handed to the controller: {what}"),
        None => format!("{kind} ignored: its domain is held by the controller"),
    };
    events.push(EventRecord::Controller {
        time: origin.time,
        element: origin.element.to_owned(),
        entity,
        controller: a.name.clone(),
        model: a.model_name(),
        active: a.active,
        note,
    });
    Ok(true)
}
