//! LateralDistanceAction (OpenSCENARIO 1.3 §7.7.2.2, XSD `LateralDistanceAction`): keep a
//! lateral distance to a reference entity ("Missing value is interpreted as 0"), between
//! reference points or, with `freespace`, bounding boxes, measured in `coordinateSystem`
//! (absent: entity, the actor's frame; module `gauge`). In the entity frame the heading the
//! sideways motion gives the actor turns its axes too, so with the reference ahead or behind
//! the measured distance moves with it (by the longitudinal offset × sin of the heading); the
//! road and lane frames measure across the road, as the corpus scenarios do.
//!
//! * `displacement`: leftToReferencedEntity puts the actor left of the reference,
//!   rightToReferencedEntity right of it, `any` (the default) keeps the side it is on at the
//!   start (left when level).
//! * The actor moves sideways on its lane (its lateral position t; the default controller keeps
//!   driving along the lane) with a lateral speed v the action controls. Without
//!   DynamicConstraints ("unlimited dynamics") it is put at the distance at once. With
//!   maxAcceleration (or maxDeceleration alone) the lateral acceleration follows the critically
//!   damped law of module `law` with that limit as tension, clamped to maxAcceleration, or to
//!   maxDeceleration while it slows the sideways motion down when that is given (a lateral
//!   acceleration has no separate brake: without maxDeceleration, maxAcceleration bounds both
//!   ways, as in esmini); with only maxSpeed, v is the speed that closes the error. In every
//!   case |v| ≤ maxSpeed. The spring damps the actor's own lateral speed; the reference's
//!   lateral motion enters through the error it predicts (below).
//!   Integration is forward Euler: over [t, t + dt] the actor moves at the v of the step's
//!   start, then v takes the step's acceleration (so the first step of the action only sets v
//!   going, as in esmini's runs). The error the new v works on is the one expected when it
//!   acts: the error measured at the step's start, less this step's own motion, plus the
//!   reference's lateral motion (at its present lateral speed) over this step and the next.
//! * An actor off every lane needs no lane: in a frame that can measure there (entity, world)
//!   it moves along its own y axis (left of its heading) and keeps its heading; the road and
//!   lane frames refuse it at the start, having no distance to measure (issue 16 class 8).
//! * The heading turns with the sideways motion: h = road heading + atan(v / speed), the
//!   motion being handed to the default controller as a one-step lateral blend of the lane.
//! * oscsim's `at_start` (no XML form; DSL 2.1 §8.8.3 `keep_space_gap(…, lateral)` after a
//!   run-time start): the distance is the clearance measured as the action starts, on the
//!   side `displacement` keeps the reference on (not below 0).
//! * `continuous="false"`: the action ends when the lateral error measured at a step's start is
//!   at most 0.01 m (esmini's threshold; the standard gives none); the actor keeps the lateral
//!   position reached.

use opendrive::Direction;
use scenario::{LateralAction, LateralDisplacement, SourcePos};

use super::gauge::{Axis, Gauge};
use super::law::{spring, Limits};
use crate::actions::Part;
use crate::error::Error;
use crate::position::lane_at;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::lane_track::Blend;

/// Lateral error (m) at which a non-continuous action has reached its distance.
pub(crate) const REACHED: f64 = 0.01;

/// Steps until a lateral speed set now has acted: the measurement is the step's start, and the
/// speed moves the actor over the next step (forward Euler), so the error it must remove is
/// the one predicted two steps ahead.
const HORIZON_STEPS: f64 = 2.0;

/// Travel below which the heading is not turned by the sideways motion (m per step).
const MIN_TRAVEL: f64 = 1e-6;

/// A running LateralDistanceAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct LateralState {
    reference: EntityId,
    distance: f64,
    gauge: Gauge,
    /// +1: the reference stays left of the actor; −1: right of it.
    toward: f64,
    continuous: bool,
    /// `None`: unlimited dynamics.
    limits: Option<Limits>,
    /// Lateral speed, m/s to the left of the actor's travel.
    speed: f64,
}

/// Starts a LateralDistanceAction on `actor` and takes its first step (no motion yet).
pub(crate) fn start_lateral(
    world: &mut World,
    actor: EntityId,
    action: &LateralAction,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let LateralAction::LateralDistance {
        entity_ref: name,
        continuous,
        distance,
        freespace,
        displacement,
        coordinate_system,
        dynamic_constraints,
        at_start,
    } = action
    else {
        return Err(Error::unsupported("this LateralAction", pos));
    };
    let reference = entity_ref(world, name, pos)?;
    let e = world.entity(actor);
    let (gauge, now) = Gauge::at_start(
        world,
        (actor, reference),
        Axis::Lateral,
        *coordinate_system,
        *freespace,
        pos,
    )?;
    let toward = match displacement {
        Some(LateralDisplacement::LeftToReferencedEntity) => -1.0,
        Some(LateralDisplacement::RightToReferencedEntity) => 1.0,
        _ if now <= 0.0 => -1.0,
        _ => 1.0,
    };
    // The sideways motion in progress (a lane change, say) carries on into the action.
    let side = travel_sign(e.track.as_ref().map(|t| t.direction));
    let distance =
        match (distance, at_start) {
            (Some(_), true) => return Err(Error::at(
                "a LateralDistanceAction keeping either a given distance or the one at its start",
                "both",
                pos,
            )),
            // oscsim's `at_start`: the clearance on the side the reference is kept on, not below 0.
            (None, true) => gauge
                .clearance(world, actor, reference, toward)
                .unwrap_or(0.0)
                .max(0.0),
            (d, false) => d.unwrap_or(0.0).abs(),
        };
    let mut state = LateralState {
        reference,
        distance,
        gauge,
        toward,
        continuous: *continuous,
        limits: dynamic_constraints.as_ref().map(Limits::from_constraints),
        speed: side * e.lateral_slope * e.speed.abs(),
    };
    Ok(match step_lateral(world, actor, &mut state, 0.0) {
        ActionStatus::Running => Part::LateralDistance(state),
        done => Part::Done(done),
    })
}

/// One step of a LateralDistanceAction over `dt` s (0 at the start: no motion).
pub(crate) fn step_lateral(
    world: &mut World,
    actor: EntityId,
    s: &mut LateralState,
    dt: f64,
) -> ActionStatus {
    // A reference that left the scenario (DeleteEntityAction) has no place to keep a distance
    // to: the action stops where the actor is (as the longitudinal one does).
    if !world.entity(s.reference).placed {
        world.keep_lateral_position(actor);
        return ActionStatus::Stopped;
    }
    let Some(clearance) = s.gauge.clearance(world, actor, s.reference, s.toward) else {
        return ActionStatus::Running;
    };
    let error = clearance - s.distance;
    if !s.continuous && error.abs() <= REACHED {
        world.keep_lateral_position(actor);
        return ActionStatus::Ended;
    }
    if dt <= 0.0 {
        return ActionStatus::Running;
    }
    // Positive: the actor must move to the left of its travel.
    let left = s.toward * error;
    let reference = world.entity(s.reference);
    let side = travel_sign(world.entity(actor).track.as_ref().map(|t| t.direction));
    // The reference's lateral speed across its lane, to the left of the actor's travel.
    let v_ref = side * reference.lateral_slope * reference.speed.abs();
    let shift = match s.limits {
        None => {
            // Rigid: at the distance from where the reference is at the step's end.
            s.speed = 0.0;
            left + v_ref * dt
        }
        Some(limits) => {
            let shift = s.speed * dt;
            // The error when the speed set now acts: after this step's own motion, with the
            // reference moving on over this step and the next.
            let ahead = left - shift + HORIZON_STEPS * v_ref * dt;
            let tension = if limits.acceleration.is_finite() {
                limits.acceleration
            } else {
                limits.deceleration
            };
            let v = if tension.is_finite() {
                let acc = spring(ahead, s.speed, tension, dt);
                let bound = if acc * s.speed < 0.0 && limits.deceleration.is_finite() {
                    limits.deceleration
                } else {
                    limits.acceleration
                };
                s.speed + acc.clamp(-bound, bound) * dt
            } else {
                ahead / dt
            };
            s.speed = v.clamp(-limits.speed, limits.speed);
            shift
        }
    };
    move_sideways(world, actor, shift, dt, s.limits.is_some());
    ActionStatus::Running
}

/// Moves `actor` by `left` m to the left of its travel over this step: the lane and offset
/// that hold the new lateral position, reached through a one-step blend when `smooth` (the
/// default controller then turns the heading by the slope of the motion).
fn move_sideways(world: &mut World, actor: EntityId, left: f64, dt: f64, smooth: bool) {
    let (net, e) = world.entity_on_network_mut(actor);
    let travel = (e.speed * dt).abs();
    let Some(track) = &mut e.track else {
        // Off the lanes: sideways in the entity frame, along its y axis; the heading stays
        // (there is no lane to blend along, and turning it would turn the frame measured in).
        e.pose.x -= left * e.pose.h.sin();
        e.pose.y += left * e.pose.h.cos();
        return;
    };
    let Some(road) = net.road(&track.road_id) else {
        return;
    };
    let dt_road = travel_sign(Some(track.direction)) * left;
    let (from_lane, from_offset) =
        lane_at(road, track.s, track.t).unwrap_or((track.lane_id, track.offset));
    let t = track.t + dt_road;
    let (lane, offset) =
        lane_at(road, track.s, t).unwrap_or((track.lane_id, track.offset + t - track.t));
    track.lane_id = lane;
    track.offset = offset;
    track.blend = (smooth && travel > MIN_TRAVEL).then_some(Blend {
        from_lane,
        from_offset,
        weight: 1.0,
        weight_per_m: 1.0 / travel,
    });
}

/// +1 for travel towards +s, −1 towards −s (left of the travel is then −t).
fn travel_sign(direction: Option<Direction>) -> f64 {
    match direction {
        Some(Direction::Backward) => -1.0,
        _ => 1.0,
    }
}
