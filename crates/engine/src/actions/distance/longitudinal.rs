//! LongitudinalDistanceAction (OpenSCENARIO 1.3 §7.7.2.1, XSD `LongitudinalDistanceAction`):
//! "activates a controller for the longitudinal behavior of an entity in a way that a given
//! distance or time gap to the reference entity is maintained".
//!
//! * What is kept: `distance` (m), or `timeGap` (s) × the reference's speed. The standard does
//!   not say whose speed turns a time gap into a distance; oscsim takes the reference's, as
//!   esmini does: the wanted distance then does not depend on the speed being controlled, once
//!   the gap is kept both speeds are equal, and with leadingReferencedEntity it is the speed
//!   of the follower, as in a time headway.
//! * Measured (module `gauge`) in `coordinateSystem` (absent: entity, the actor's frame), between
//!   reference points or, with `freespace`, bounding boxes.
//! * `displacement`: trailingReferencedEntity (the default) keeps the reference ahead,
//!   leadingReferencedEntity keeps it behind, `any` keeps the side it is on at the start.
//! * Without DynamicConstraints ("unlimited dynamics") the actor is put at the distance along its
//!   lane each step and takes the reference's speed. With them, the actor's speed follows the
//!   critically damped law of module `law` (tension: maxAcceleration when the actor must drop
//!   back, maxDeceleration when it must close up — esmini's pairing), the acceleration clamped
//!   to [−maxDeceleration, maxAcceleration] and to what still lets the jerk limits bring it
//!   back to 0 before the speed leaves [0, maxSpeed] (`law::speed_room`), then limited in its
//!   change by maxAccelerationRate / maxDecelerationRate; the speed stays in [0, maxSpeed]
//!   (a distance controller does not reverse) without a jump in the acceleration.
//! * oscsim's `at_least` (no XML form; DSL 2.1 §8.9 `position(ahead_of/behind: x)` without a
//!   distance or time after a run-time start, the DSL runtime's default gap): with `timeGap`,
//!   the distance kept is the larger of timeGap × the reference's speed and `at_least`, read
//!   at every step.
//! * oscsim's `at_start` (no XML form; DSL 2.1 §8.8.3 `keep_space_gap` / `keep_time_headway`
//!   after a run-time start): the distance, or the time gap (the distance over the
//!   reference's speed), is the one measured as the action starts, on the side `displacement`
//!   keeps the reference on (not below 0); a standing reference has no time gap (an error).
//! * `continuous="false"`: "the action ends when the target distance is reached", oscsim: when
//!   the distance error measured at a step's start is at most 0.1 m (esmini's threshold; the
//!   standard gives none); that step's control still applies, and the storyboard logs the end
//!   with the next step, as esmini does (its log shows the end at the frame of that step).

use opendrive::Direction;
use scenario::{GapAtStart, LongitudinalAction, LongitudinalDisplacement, SourcePos};

use super::gauge::{Axis, Gauge};
use super::law::{limit_jerk, speed_room, spring, Limits};
use crate::actions::Part;
use crate::controller::place_on_track;
use crate::error::Error;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;

/// Distance error (m) at which a non-continuous action has reached its distance.
pub(crate) const REACHED: f64 = 0.1;

/// What the action keeps.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Wanted {
    /// A distance, m.
    Distance(f64),
    /// A time gap, s, at the reference's speed.
    TimeGap(f64),
    /// A time gap, s, at the reference's speed, and at least a distance, m (oscsim's
    /// `at_least`): the larger of the two at every step.
    TimeGapAtLeast(f64, f64),
}

/// A running LongitudinalDistanceAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct LongitudinalState {
    reference: EntityId,
    wanted: Wanted,
    gauge: Gauge,
    /// +1: the reference stays ahead (the actor trails); −1: behind (the actor leads).
    toward: f64,
    continuous: bool,
    /// `None`: unlimited dynamics.
    limits: Option<Limits>,
    /// The acceleration the last step asked for (m/s²), for the jerk limits.
    acceleration: f64,
}

/// Starts a LongitudinalDistanceAction on `actor` and takes its first step (no motion yet).
pub(crate) fn start_longitudinal(
    world: &mut World,
    actor: EntityId,
    action: &LongitudinalAction,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let LongitudinalAction::LongitudinalDistance {
        entity_ref: name,
        continuous,
        distance,
        time_gap,
        freespace,
        displacement,
        coordinate_system,
        dynamic_constraints,
        at_start,
        at_least,
    } = action
    else {
        return Err(Error::unsupported("this LongitudinalAction", pos));
    };
    let reference = entity_ref(world, name, pos)?;
    let given =
        match (distance, time_gap, at_start) {
            (Some(d), None, None) => Some(Wanted::Distance(d.abs())),
            (None, Some(g), None) => Some(match at_least {
                Some(d) => Wanted::TimeGapAtLeast(g.abs(), d.abs()),
                None => Wanted::TimeGap(g.abs()),
            }),
            (None, None, Some(_)) => None,
            (Some(_), Some(_), _) => {
                return Err(Error::at(
                    "a LongitudinalDistanceAction with either distance or timeGap",
                    "both",
                    pos,
                ))
            }
            (None, None, None) => {
                return Err(Error::at(
                    "a LongitudinalDistanceAction with a distance or a timeGap",
                    "neither",
                    pos,
                ))
            }
            (_, _, Some(_)) => return Err(Error::at(
                "a LongitudinalDistanceAction keeping either a given value or the one at its start",
                "both",
                pos,
            )),
        };
    let (gauge, now) = Gauge::at_start(
        world,
        (actor, reference),
        Axis::Longitudinal,
        *coordinate_system,
        *freespace,
        pos,
    )?;
    let toward = match displacement {
        Some(LongitudinalDisplacement::LeadingReferencedEntity) => -1.0,
        Some(LongitudinalDisplacement::Any) if now < 0.0 => -1.0,
        _ => 1.0,
    };
    let wanted = match (given, at_start) {
        (Some(w), _) => w,
        (None, kind) => measured(world, (actor, reference), (&gauge, toward), *kind, pos)?,
    };
    let limits = dynamic_constraints
        .as_ref()
        .map(|c| Limits::longitudinal(c, world.entity(actor)));
    let mut state = LongitudinalState {
        reference,
        wanted,
        gauge,
        toward,
        continuous: *continuous,
        limits,
        acceleration: 0.0,
    };
    Ok(match step_longitudinal(world, actor, &mut state, 0.0) {
        ActionStatus::Running => Part::LongitudinalDistance(state),
        done => Part::Done(done),
    })
}

/// The value of `kind` (`None`: a distance) between `actor` and `reference` as the action
/// starts (oscsim's `at_start`): the clearance on the side the reference is kept on (not below
/// 0, boxes that overlap keep none), or that over the reference's speed, which must not be 0
/// (a standing reference has no time gap).
fn measured(
    world: &World,
    (actor, reference): (EntityId, EntityId),
    (gauge, toward): (&Gauge, f64),
    kind: Option<GapAtStart>,
    pos: &SourcePos,
) -> Result<Wanted, Error> {
    let clearance = gauge
        .clearance(world, actor, reference, toward)
        .unwrap_or(0.0)
        .max(0.0);
    if kind != Some(GapAtStart::TimeGap) {
        return Ok(Wanted::Distance(clearance));
    }
    let r = world.entity(reference);
    if r.speed.abs() <= crate::tolerance::SPEED {
        return Err(Error::at(
            "a moving reference for the time gap kept from the start",
            format!("'{}' standing", r.name),
            pos,
        ));
    }
    Ok(Wanted::TimeGap(clearance / r.speed.abs()))
}

/// One step of a LongitudinalDistanceAction over `dt` s (0 at the start: no integration).
pub(crate) fn step_longitudinal(
    world: &mut World,
    actor: EntityId,
    s: &mut LongitudinalState,
    dt: f64,
) -> ActionStatus {
    // A reference that left the scenario (DeleteEntityAction) has no place to keep a distance
    // to: the action stops and the actor keeps its speed (as SpeedAction does, speed.rs).
    if !world.entity(s.reference).placed {
        return ActionStatus::Stopped;
    }
    let Some(clearance) = s.gauge.clearance(world, actor, s.reference, s.toward) else {
        // No measurement now (e.g. off the roads in a road frame): hold the speed.
        return ActionStatus::Running;
    };
    let (v, v_ref) = (world.entity(actor).speed, world.entity(s.reference).speed);
    let wanted = match s.wanted {
        Wanted::Distance(d) => d,
        Wanted::TimeGap(g) => g * v_ref.abs(),
        Wanted::TimeGapAtLeast(g, d) => (g * v_ref.abs()).max(d),
    };
    let error = clearance - wanted;
    // Positive: the actor must move forward to remove the error.
    let forward = s.toward * error;
    match s.limits {
        None => {
            shift_along_lane(world, actor, forward);
            world.entity_mut(actor).speed = v_ref;
            if !s.continuous {
                return ActionStatus::Ended;
            }
        }
        Some(limits) if dt > 0.0 => {
            let tension = if forward < 0.0 {
                limits.acceleration
            } else {
                limits.deceleration
            };
            let (lowest, highest) = speed_room(v, &limits, dt);
            let acc = spring(forward, v - v_ref, tension, dt)
                .clamp(-limits.deceleration, limits.acceleration)
                .clamp(lowest.min(0.0), highest.max(0.0));
            let acc = limit_jerk(acc, s.acceleration, &limits, dt);
            s.acceleration = acc;
            world.entity_mut(actor).speed = (v + acc * dt).clamp(0.0, limits.speed);
        }
        Some(_) => {}
    }
    if !s.continuous && error.abs() <= REACHED {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}

/// Moves `actor` by `forward` m along its lane (negative: back), within its road.
fn shift_along_lane(world: &mut World, actor: EntityId, forward: f64) {
    let (net, e) = world.entity_on_network_mut(actor);
    let Some(track) = e.track.as_mut() else {
        e.pose.x += forward * e.pose.h.cos();
        e.pose.y += forward * e.pose.h.sin();
        e.road_position = net.locate(e.pose.x, e.pose.y, Some(e.pose.h));
        return;
    };
    let sign = if track.direction == Direction::Forward {
        1.0
    } else {
        -1.0
    };
    let length = net.road(&track.road_id).map_or(f64::INFINITY, |r| r.length);
    track.s = (track.s + forward * sign).clamp(0.0, length);
    place_on_track(net, e);
}
