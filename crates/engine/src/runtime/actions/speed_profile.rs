//! SpeedProfileAction (OpenSCENARIO 1.3 §7.7.2.1, XSD `SpeedProfileAction`, 1.2+): a sequence of
//! speed targets, each reached in its entry's `time`, or, without one, at the acceleration
//! limit (DynamicConstraints, else the vehicle's performance, else 5 m/s²).
//!
//! oscsim changes speed linearly within each entry for both following modes; `follow` in the
//! standard allows a smoother, jerk-limited approach (esmini uses one), which differs only in
//! the corners of the profile.

use scenario::{LongitudinalAction, SourcePos};

use super::speed::entity_ref;
use super::Part;
use crate::runtime::entity::EntityId;
use crate::runtime::error::RuntimeError;
use crate::runtime::world::World;
use crate::storyboard::ActionStatus;

/// Acceleration (m/s²) used when neither the action nor the vehicle gives one.
const DEFAULT_ACCELERATION: f64 = 5.0;

/// A running SpeedProfileAction on one actor: linear segments (end time, end speed).
#[derive(Debug, Clone)]
pub(crate) struct ProfileState {
    /// (start time, start speed, end time, end speed) per segment.
    segments: Vec<(f64, f64, f64, f64)>,
}

/// Starts the action: plans the segments from the current speed.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &LongitudinalAction,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, RuntimeError> {
    let LongitudinalAction::SpeedProfile {
        entity_ref: reference,
        dynamic_constraints,
        entries,
        ..
    } = action
    else {
        return Err(RuntimeError::unsupported("this LongitudinalAction", pos));
    };
    let base = match reference {
        Some(name) => world.entity(entity_ref(world, name, pos)?).speed,
        None => 0.0,
    };
    let e = world.entity(actor);
    let perf = e.performance;
    let accel = dynamic_constraints
        .and_then(|c| c.max_acceleration)
        .or(perf.map(|p| p.max_acceleration))
        .unwrap_or(DEFAULT_ACCELERATION);
    let decel = dynamic_constraints
        .and_then(|c| c.max_deceleration)
        .or(perf.map(|p| p.max_deceleration))
        .unwrap_or(DEFAULT_ACCELERATION);
    let (mut t, mut v) = (now, e.speed);
    let mut segments = Vec::with_capacity(entries.len());
    for entry in entries {
        let target = base + entry.speed;
        let limit = if target >= v { accel } else { decel };
        let duration = match entry.time {
            Some(d) if d > 0.0 => d,
            _ if limit > 0.0 => (target - v).abs() / limit,
            _ => 0.0,
        };
        segments.push((t, v, t + duration, target));
        t += duration;
        v = target;
    }
    let mut state = ProfileState { segments };
    Ok(
        match step(world, actor, &mut state, now - f64::EPSILON, 0.0) {
            ActionStatus::Running => Part::Profile(state),
            done => Part::Done(done),
        },
    )
}

/// Sets the speed at the step's end, `now + dt`.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut ProfileState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let t = now + dt;
    let Some(&(_, _, _, last)) = s.segments.last() else {
        return ActionStatus::Ended;
    };
    let mut speed = last;
    let mut running = false;
    for &(t0, v0, t1, v1) in &s.segments {
        if t < t1 {
            speed = if t1 > t0 {
                v0 + (v1 - v0) * ((t - t0) / (t1 - t0)).clamp(0.0, 1.0)
            } else {
                v1
            };
            running = true;
            break;
        }
    }
    world.entity_mut(actor).speed = speed;
    if running {
        ActionStatus::Running
    } else {
        ActionStatus::Ended
    }
}
