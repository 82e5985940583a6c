//! LongitudinalDistanceAction and LateralDistanceAction (OpenSCENARIO 1.3 §7.7.2.1–7.7.2.2,
//! XSD `LongitudinalDistanceAction`, `LateralDistanceAction`): keep a distance (or, longitudinally,
//! a time gap × own speed) to a reference entity, between reference points or bounding boxes
//! (`freespace`).
//!
//! Distances are measured along the road (s difference, when both are on the same road; else
//! along the actor's heading). Without DynamicConstraints the actor is put at the distance at
//! once and takes the reference's speed (longitudinal) — the standard leaves the approach to the
//! implementation. With them, a critically damped spring drives the gap error to zero within
//! the acceleration, deceleration, rate and speed limits; its stiffness grows with the limit it
//! works against (0.4/m × limit), the tuning esmini uses, so that the corpus runs compare. A non-continuous action ends
//! when the gap is within 0.1 m and the relative speed within 0.1 m/s.

use opendrive::Direction;
use scenario::{
    LateralAction, LateralDisplacement, LongitudinalAction, LongitudinalDisplacement, SourcePos,
};

use super::speed::entity_ref;
use super::Part;
use crate::runtime::controller::place_on_track;
use crate::runtime::entity::EntityId;
use crate::runtime::error::RuntimeError;
use crate::runtime::lanes::lane_at;
use crate::runtime::world::World;
use crate::storyboard::ActionStatus;

/// Gap error (m) and speed difference (m/s) at which a non-continuous action has arrived.
const ARRIVED: f64 = 0.1;
/// Stiffness per m/s² of acceleration limit (1/m) of the constrained gap controller: the
/// spring constant is this times the limit in the direction of the correction.
const STIFFNESS_PER_LIMIT: f64 = 0.4;

/// A running LongitudinalDistanceAction.
#[derive(Debug, Clone)]
pub(crate) struct LongitudinalState {
    reference: EntityId,
    distance: Option<f64>,
    time_gap: Option<f64>,
    freespace: bool,
    /// +1: the actor trails the reference; −1: it leads.
    side: f64,
    continuous: bool,
    limits: Option<scenario::DynamicConstraints>,
    /// Acceleration of the last step (m/s²), for the jerk limits.
    acceleration: f64,
}

/// A running LateralDistanceAction.
#[derive(Debug, Clone)]
pub(crate) struct LateralState {
    reference: EntityId,
    distance: f64,
    freespace: bool,
    /// +1: the actor stays left of the reference; −1: right.
    side: f64,
    continuous: bool,
    max_speed: Option<f64>,
}

/// Signed distance (m) from the actor to the reference along the actor's direction of travel.
fn longitudinal_gap(world: &World, actor: EntityId, reference: EntityId) -> f64 {
    let (a, r) = (world.entity(actor), world.entity(reference));
    if let (Some(ta), Some(tr)) = (&a.track, &r.track) {
        if ta.road_id == tr.road_id {
            let sign = if ta.direction == Direction::Forward {
                1.0
            } else {
                -1.0
            };
            return (tr.s - ta.s) * sign;
        }
    }
    let (dx, dy) = (r.pose.x - a.pose.x, r.pose.y - a.pose.y);
    dx * a.pose.h.cos() + dy * a.pose.h.sin()
}

/// Starts a LongitudinalDistanceAction.
pub(crate) fn start_longitudinal(
    world: &mut World,
    actor: EntityId,
    action: &LongitudinalAction,
    pos: &SourcePos,
) -> Result<Part, RuntimeError> {
    let LongitudinalAction::LongitudinalDistance {
        entity_ref: name,
        continuous,
        distance,
        time_gap,
        freespace,
        displacement,
        dynamic_constraints,
        ..
    } = action
    else {
        return Err(RuntimeError::unsupported("this LongitudinalAction", pos));
    };
    let reference = entity_ref(world, name, pos)?;
    if distance.is_none() && time_gap.is_none() {
        return Err(RuntimeError::at("a distance or a timeGap", "neither", pos));
    }
    let side = match displacement {
        Some(LongitudinalDisplacement::LeadingReferencedEntity) => -1.0,
        Some(LongitudinalDisplacement::Any) if longitudinal_gap(world, actor, reference) < 0.0 => {
            -1.0
        }
        _ => 1.0,
    };
    let mut state = LongitudinalState {
        reference,
        distance: *distance,
        time_gap: *time_gap,
        freespace: *freespace,
        side,
        continuous: *continuous,
        limits: *dynamic_constraints,
        acceleration: 0.0,
    };
    Ok(match step_longitudinal(world, actor, &mut state, 0.0) {
        ActionStatus::Running => Part::LongitudinalDistance(state),
        done => Part::Done(done),
    })
}

/// One step of a LongitudinalDistanceAction (`dt` = 0 at the start: no integration).
pub(crate) fn step_longitudinal(
    world: &mut World,
    actor: EntityId,
    s: &mut LongitudinalState,
    dt: f64,
) -> ActionStatus {
    let (a, r) = (world.entity(actor), world.entity(s.reference));
    let mut wanted = s
        .distance
        .unwrap_or_else(|| s.time_gap.unwrap_or(0.0) * a.speed.abs());
    if s.freespace {
        let front = a.bounding_box.center().x + a.bounding_box.length() / 2.0;
        let rear = r.bounding_box.length() / 2.0 - r.bounding_box.center().x;
        let (lead, trail) = if s.side > 0.0 {
            (rear, front)
        } else {
            (front, rear)
        };
        wanted += lead + trail;
    }
    let gap = longitudinal_gap(world, actor, s.reference) * s.side;
    let (v, v_ref) = (a.speed, r.speed);
    let error = gap - wanted;
    match s.limits {
        None => {
            // Ideal following: put the actor at the distance, at the reference's speed.
            let e = world.entity_mut(actor);
            e.speed = v_ref;
            if let Some(mut track) = e.track.take() {
                let sign = if track.direction == Direction::Forward {
                    1.0
                } else {
                    -1.0
                };
                track.s = (track.s + error * s.side * sign).max(0.0);
                let net = &world.network;
                let e = &mut world.entities[actor.index()];
                place_on_track(net, e, &mut track);
                e.track = Some(track);
            }
        }
        Some(limits) if dt > 0.0 => {
            let perf = a.performance;
            let max_acc = limits
                .max_acceleration
                .or(perf.map(|p| p.max_acceleration))
                .unwrap_or(f64::INFINITY);
            let max_dec = limits
                .max_deceleration
                .or(perf.map(|p| p.max_deceleration))
                .unwrap_or(f64::INFINITY);
            let max_speed = limits.max_speed.unwrap_or(a.max_speed());
            // A critically damped spring on the gap error whose stiffness scales with the
            // limit it works against (k = 0.4/m × limit, damping 2√k), clamped to the limits,
            // with the change of acceleration bounded by the rate limits when given.
            let toward = if error * s.side < 0.0 {
                max_acc
            } else {
                max_dec
            };
            let k = STIFFNESS_PER_LIMIT * toward.min(1e6);
            let acc = (k * error) * s.side - 2.0 * k.sqrt() * (v - v_ref);
            let mut acc = acc.clamp(-max_dec, max_acc);
            if acc < st_acc(s) {
                if let Some(rate) = limits.max_deceleration_rate {
                    acc = acc.max(st_acc(s) - rate * dt);
                }
            } else if let Some(rate) = limits.max_acceleration_rate {
                acc = acc.min(st_acc(s) + rate * dt);
            }
            s.acceleration = acc;
            world.entity_mut(actor).speed = (v + acc * dt).clamp(0.0, max_speed);
        }
        Some(_) => {}
    }
    let arrived = error.abs() <= ARRIVED && (v - v_ref).abs() <= ARRIVED || s.limits.is_none();
    if arrived && !s.continuous {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}

/// The acceleration of the previous step.
fn st_acc(s: &LongitudinalState) -> f64 {
    s.acceleration
}

/// Starts a LateralDistanceAction.
pub(crate) fn start_lateral(
    world: &mut World,
    actor: EntityId,
    action: &LateralAction,
    pos: &SourcePos,
) -> Result<Part, RuntimeError> {
    let LateralAction::LateralDistance {
        entity_ref: name,
        continuous,
        distance,
        freespace,
        displacement,
        dynamic_constraints,
        ..
    } = action
    else {
        return Err(RuntimeError::unsupported("this LateralAction", pos));
    };
    let reference = entity_ref(world, name, pos)?;
    let (a, r) = (world.entity(actor), world.entity(reference));
    let (Some(ta), Some(tr)) = (&a.track, &r.track) else {
        return Err(RuntimeError::at(
            "actor and reference on lanes",
            "an entity off the road",
            pos,
        ));
    };
    let side = match displacement {
        Some(LateralDisplacement::LeftToReferencedEntity) => 1.0,
        Some(LateralDisplacement::RightToReferencedEntity) => -1.0,
        _ if ta.t >= tr.t => 1.0,
        _ => -1.0,
    };
    let mut state = LateralState {
        reference,
        distance: distance.unwrap_or(0.0),
        freespace: *freespace,
        side,
        continuous: *continuous,
        max_speed: dynamic_constraints.and_then(|c| c.max_speed),
    };
    Ok(match step_lateral(world, actor, &mut state, 0.0) {
        ActionStatus::Running => Part::LateralDistance(state),
        done => Part::Done(done),
    })
}

/// One step of a LateralDistanceAction: moves t towards the reference's t ± distance.
pub(crate) fn step_lateral(
    world: &mut World,
    actor: EntityId,
    s: &mut LateralState,
    dt: f64,
) -> ActionStatus {
    let (a, r) = (world.entity(actor), world.entity(s.reference));
    let (Some(ta), Some(tr)) = (&a.track, &r.track) else {
        return ActionStatus::Ended;
    };
    let mut d = s.distance;
    if s.freespace {
        d += (a.bounding_box.width() + r.bounding_box.width()) / 2.0;
    }
    // t grows to the left of +s; "left of the reference" flips for travel towards −s.
    let sign = if ta.direction == Direction::Forward {
        1.0
    } else {
        -1.0
    };
    let target = tr.t + s.side * sign * d;
    let error = target - ta.t;
    let step = match (s.max_speed, dt > 0.0) {
        (Some(v), true) => error.clamp(-v * dt, v * dt),
        _ => error,
    };
    let net = &world.network;
    let e = &mut world.entities[actor.index()];
    if let Some(mut track) = e.track.take() {
        let t = track.t + step;
        if let Some((lane, offset)) = net
            .road(&track.road_id)
            .and_then(|road| lane_at(road, track.s, t))
        {
            track.lane_id = lane;
            track.offset = offset;
            track.blend = None;
        }
        place_on_track(net, e, &mut track);
        e.track = Some(track);
    }
    if (error - step).abs() <= ARRIVED && !s.continuous {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}
