//! SpeedAction (OpenSCENARIO 1.3 §7.7.2.1 "LongitudinalAction", XSD `SpeedAction`): drive the
//! actor's speed to an absolute target, or to a reference entity's speed plus a delta or times
//! a factor, under a transition shape (see `shapes`). With `continuous="true"` a relative
//! target keeps being followed after the transition, so the action never ends by itself.
//! oscsim's `RelativeAtStart` target (no XML form) reads the reference's speed once, at the
//! start, and is fixed from then on.
//!
//! A `distance` dimension is turned into the time in which the change covers that distance,
//! T = 2·d / |v₀ + v₁| (see `distance_to_time`, also for a change of direction), so that a
//! change starting from rest still progresses (a change linear in distance would never leave
//! v = 0); the shape then runs over T.
//!
//! A vehicle's Performance bounds the change: a transition whose peak rate would exceed
//! maxAcceleration (maxDeceleration) is stretched in time to meet it, keeping its shape, as
//! esmini does; the change per step is also clamped to the limits, and the speed to ±maxSpeed.
//! A TransitionDynamics with followingMode `position` ignores these Performance limits.

use scenario::{
    DynamicsDimension, DynamicsShape, FollowingMode, Performance, SourcePos, SpeedTarget,
    SpeedTargetValueType, TransitionDynamics,
};

use super::Part;
use crate::error::Error;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::shapes::{peak_slope, progress, shape_value, span, Span};

/// A running SpeedAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct SpeedState {
    /// The vehicle's Performance when it bounds the change (see `bounded_by_performance`).
    performance: Option<Performance>,
    dynamics: TransitionDynamics,
    target: Target,
    start_speed: f64,
    start_time: f64,
    span: Span,
    /// A performance limit bounded the last step's change.
    limited: bool,
}

/// The target speed: fixed, or read from a reference entity every step.
#[derive(Debug, Clone)]
enum Target {
    Fixed(f64),
    Relative {
        entity: EntityId,
        value: f64,
        kind: SpeedTargetValueType,
        continuous: bool,
    },
}

impl Target {
    fn speed(&self, world: &World) -> f64 {
        match self {
            Target::Fixed(v) => *v,
            Target::Relative {
                entity,
                value,
                kind,
                ..
            } => {
                let v = world.entity(*entity).speed;
                match kind {
                    SpeedTargetValueType::Delta => v + value,
                    _ => v * value,
                }
            }
        }
    }

    fn continuous(&self) -> bool {
        matches!(
            self,
            Target::Relative {
                continuous: true,
                ..
            }
        )
    }
}

/// Starts the action: a step change takes effect at once.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    dynamics: &TransitionDynamics,
    target: &SpeedTarget,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let target = target_of(world, target, pos)?;
    let v0 = world.entity(actor).speed;
    let v1 = target.speed(world);
    // A relative target can overflow (a factor of 1e10 on 1e300 m/s): refused, as a
    // non-finite value in the file is.
    if !v1.is_finite() {
        return Err(Error::at("a finite target speed", format!("{v1} m/s"), pos));
    }
    let mut span = span(dynamics, v1 - v0);
    if let (DynamicsDimension::Distance, Span::Distance(d)) = (dynamics.dynamics_dimension, span) {
        span = distance_to_time(d, v0, v1);
    }
    // The vehicle's acceleration limit stretches the transition so that the shape's peak rate,
    // max f′·|Δv|/T, stays within it (the shape is kept, only slower).
    let performance = bounded_by_performance(dynamics)
        .then_some(world.entity(actor).performance)
        .flatten();
    if let (Span::Time(t), Some(perf)) = (span, performance) {
        span = Span::Time(t.max(least_time(&perf, dynamics.dynamics_shape, v0, v1)));
    }
    let mut state = SpeedState {
        performance,
        dynamics: *dynamics,
        target,
        start_speed: v0,
        start_time: now,
        span,
        limited: false,
    };
    if span == Span::Instant {
        world.entity_mut(actor).speed = v1;
        if !state.target.continuous() {
            return Ok(Part::Done(ActionStatus::Ended));
        }
        state.start_speed = v1;
    }
    Ok(Part::Speed(state))
}

/// The speed `target` asks of an actor now (m/s), read as a SpeedAction starting now reads it.
pub(crate) fn target_speed(
    world: &World,
    target: &SpeedTarget,
    pos: &SourcePos,
) -> Result<f64, Error> {
    Ok(target_of(world, target, pos)?.speed(world))
}

/// The running form of `target`.
fn target_of(world: &World, target: &SpeedTarget, pos: &SourcePos) -> Result<Target, Error> {
    Ok(match target {
        SpeedTarget::Absolute(v) => Target::Fixed(*v),
        SpeedTarget::Relative {
            entity_ref: name,
            value,
            speed_target_value_type,
            continuous,
        } => Target::Relative {
            entity: entity_ref(world, name, pos)?,
            value: *value,
            kind: *speed_target_value_type,
            continuous: *continuous,
        },
        SpeedTarget::RelativeAtStart {
            entity_ref: name,
            value,
        } => Target::Fixed(world.entity(entity_ref(world, name, pos)?).speed + value),
        _ => return Err(Error::unsupported("this SpeedActionTarget", pos)),
    })
}

/// The least time `perf` lets a transition of `shape` from `v0` to `v1` take (s): its peak
/// rate, max f′·|Δv|/T, within maxAcceleration (maxDeceleration when slowing); 0 without a
/// limit.
pub(crate) fn least_time(perf: &Performance, shape: DynamicsShape, v0: f64, v1: f64) -> f64 {
    let limit = if v1 >= v0 {
        perf.max_acceleration
    } else {
        perf.max_deceleration
    }
    .abs();
    if limit > 0.0 {
        peak_slope(shape) * (v1 - v0).abs() / limit
    } else {
        0.0
    }
}

/// True unless the transition's followingMode is `position`, which follows the shape "exactly by
/// ignoring the dynamic constraints of the entity" (OpenSCENARIO 1.3 `FollowingMode`); `follow`
/// observes them, and without a followingMode (as before 1.2) oscsim observes them too, as
/// esmini does.
fn bounded_by_performance(dynamics: &TransitionDynamics) -> bool {
    dynamics.following_mode != Some(FollowingMode::Position)
}

/// The duration of a change from `v0` to `v1` that travels the path length `d`, for the speed
/// shape run over time: T = 2·d / |v0 + v1| when the direction is kept (every shape covers
/// (v0 + v1)·T/2, since f(p) + f(1 − p) = 1). When the speed changes sign the path runs out to
/// the stop and back, |v0|·T₀/2 + |v1|·T₁/2 with T₀/T₁ = |v0|/|v1| for the linear shape, so
/// T = 2·d·(|v0| + |v1|) / (v0² + v1²).
fn distance_to_time(d: f64, v0: f64, v1: f64) -> Span {
    let time = if v0 * v1 < 0.0 {
        2.0 * d * (v0.abs() + v1.abs()) / (v0 * v0 + v1 * v1)
    } else {
        let mean = 0.5 * (v0 + v1).abs();
        if mean > crate::tolerance::SPEED {
            d / mean
        } else {
            0.0
        }
    };
    if time.is_finite() && time > 0.0 {
        Span::Time(time)
    } else {
        Span::Instant
    }
}

/// `v` limited to [`lo`, `hi`]; unlike `f64::clamp` it never panics (a NaN limit from a
/// malformed Performance leaves that side open).
fn within(v: f64, lo: f64, hi: f64) -> f64 {
    v.max(lo).min(hi)
}

impl SpeedState {
    /// True when a fixed-time transition without a continuous target reaches its end by `t`
    /// and no performance limit holds it back.
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        !self.target.continuous()
            && !self.limited
            && matches!(self.span, Span::Time(d) if t - self.start_time >= d - crate::tolerance::TIME)
    }
}

/// Sets the speed for the step from `now` to `now + dt`: the shape at the step's end.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut SpeedState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    // A reference entity that left the scenario (DeleteEntityAction) has no speed to follow,
    // and a continuous relative target may overflow later: either stops the action, the actor
    // keeping the speed it has (the step stage has no error channel; the stop shows in the
    // log). At the start both are errors (`entity_ref`, `start`).
    if let Target::Relative { entity, .. } = &s.target {
        if !world.entity(*entity).placed {
            return ActionStatus::Stopped;
        }
    }
    let v1 = s.target.speed(world);
    if !v1.is_finite() {
        return ActionStatus::Stopped;
    }
    let p = progress(s.span, now + dt - s.start_time, 0.0);
    let (f, _) = shape_value(s.dynamics.dynamics_shape, p);
    let v = if p >= 1.0 {
        v1
    } else {
        s.start_speed + (v1 - s.start_speed) * f
    };
    let e = world.entity_mut(actor);
    // The vehicle's performance bounds the change per step (semantics-pitfalls #9); a step
    // shape (Span::Instant) is an ideal jump and is not limited.
    let bounded = match (s.span, s.performance) {
        (Span::Instant, _) | (_, None) => v,
        (_, Some(perf)) => within(
            v,
            e.speed - perf.max_deceleration.abs() * dt,
            e.speed + perf.max_acceleration.abs() * dt,
        ),
    };
    s.limited = (bounded - v).abs() > crate::tolerance::SPEED;
    let max_speed = s.performance.map_or(f64::INFINITY, |p| p.max_speed.abs());
    e.speed = within(bounded, -max_speed, max_speed);
    let reached = (e.speed - within(v1, -max_speed, max_speed)).abs() <= crate::tolerance::SPEED;
    if p >= 1.0 && reached && !s.target.continuous() {
        ActionStatus::Ended
    } else {
        ActionStatus::Running
    }
}
