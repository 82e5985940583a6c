//! oscsim's AccelerationAction (`scenario::LongitudinalAction::Acceleration`, an action with no
//! XML form): the actor's longitudinal acceleration goes from a₀, its value at the start (the
//! acceleration of the last step; replacing an AccelerationAction started in the same step,
//! which has not acted yet, that action's first acceleration), to the target a₁ under a transition shape f
//! ([`crate::world::shapes`]: over a time, at a peak jerk read as a rate, or at once), then
//! holds. ASAM OpenSCENARIO DSL 2.1 §8.8.2 `assign_acceleration`, `change_acceleration` and
//! `keep_acceleration` run through it: no OpenSCENARIO 1.x action holds an acceleration.
//!
//! The speed is the integral of that acceleration from the start, exactly: after τ s,
//! v = v₀ + a₀·τ + (a₁ − a₀)·T·F(τ/T), F the integral of f ([`shape_integral`]), and the step
//! sets the speed its end has (as SpeedAction does). A vehicle's Performance bounds the change
//! per step like SpeedAction's (semantics-pitfalls #9). The action ends when the speed reaches
//! 0 m/s while the acceleration pushes below it (a vehicle brakes to a stop, it does not
//! reverse) or the maximum speed while it pushes above; otherwise it runs until a later
//! longitudinal action replaces it (§7.5.1 control domains) or its Act ends. With
//! `ends_at_target` it ends in the step whose end completes the transition (τ ≥ T, within
//! [`crate::tolerance::TIME`]; a step shape or no change: its first step), the speed of
//! that step's end set as above, and the storyboard sees it end in that step
//! ([`AccelerationState::completes_by`], as a SpeedAction's): DSL 2.1 §8.8.2.14
//! `change_acceleration` at a rate after a run-time start, whose T = |a₁ − a₀|·f′max/j
//! depends on the a₀ the engine finds.

use scenario::TransitionDynamics;

use super::Part;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::shapes::{shape_integral, span, Span};

/// A running AccelerationAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct AccelerationState {
    dynamics: TransitionDynamics,
    /// Acceleration at the start and the target (m/s²).
    from: f64,
    to: f64,
    /// Duration of the transition.
    span: Span,
    start_speed: f64,
    start_time: f64,
    /// End when the transition is over (else hold the target).
    ends_at_target: bool,
}

impl AccelerationState {
    /// The acceleration this action gives its first step, if it started at `now` and so has
    /// not stepped yet.
    pub(crate) fn first_if_started_at(&self, now: f64) -> Option<f64> {
        (self.start_time == now).then(|| acceleration(self, 0.0))
    }

    /// True when an action that ends at its target completes its transition by `t` (the
    /// storyboard sees it end in the step whose motion completes it, as a SpeedAction's).
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        self.ends_at_target && over(self.span, t - self.start_time)
    }
}

/// Whether a transition over `span` is over `tau` s after its start.
fn over(span: Span, tau: f64) -> bool {
    match span {
        Span::Time(d) => tau >= d - crate::tolerance::TIME,
        _ => true,
    }
}

/// Starts the action on `actor` at `now`. `replaced`: the first acceleration of an
/// AccelerationAction this one replaces in the step both started in (it never acted): the
/// acceleration to start from, as an assigned acceleration ("as soon as possible", reached at
/// once) followed in the same instant by a change or a keep of it means; else the last step's.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    (target, replaced): (Option<f64>, Option<f64>),
    (dynamics, ends_at_target): (&TransitionDynamics, bool),
    now: f64,
) -> Part {
    let e = world.entity(actor);
    let from = replaced.unwrap_or_else(|| e.travel_component(e.acceleration.translational));
    let to = target.unwrap_or(from);
    Part::Acceleration(AccelerationState {
        dynamics: *dynamics,
        from,
        to,
        span: span(dynamics, to - from),
        start_speed: e.speed,
        start_time: now,
        ends_at_target,
    })
}

/// The acceleration after `tau` s.
fn acceleration(s: &AccelerationState, tau: f64) -> f64 {
    let (f, _) = crate::world::shapes::shape_value(
        s.dynamics.dynamics_shape,
        match s.span {
            Span::Time(t) => tau / t,
            _ => 1.0,
        },
    );
    s.from + (s.to - s.from) * f
}

/// Sets the speed for the step from `now` to `now + dt`.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut AccelerationState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let tau = now + dt - s.start_time;
    let gained = match s.span {
        Span::Time(t) => {
            s.from * tau + (s.to - s.from) * t * shape_integral(s.dynamics.dynamics_shape, tau / t)
        }
        _ => s.to * tau,
    };
    let status = set_speed(
        world,
        actor,
        s.start_speed + gained,
        acceleration(s, tau),
        dt,
    );
    if s.ends_at_target && over(s.span, tau) {
        ActionStatus::Ended
    } else {
        status
    }
}

/// Sets `actor`'s speed for a step of `dt` s to `wanted`, bounded by its Performance, while
/// the acceleration `pushing` drives it: at 0 m/s while pushing below it, or at the maximum
/// speed while pushing above, the action has ended.
pub(super) fn set_speed(
    world: &mut World,
    actor: EntityId,
    wanted: f64,
    pushing: f64,
    dt: f64,
) -> ActionStatus {
    let e = world.entity_mut(actor);
    let (max_speed, bounded) = match e.performance {
        Some(perf) => (
            perf.max_speed.abs(),
            wanted
                .max(e.speed - perf.max_deceleration.abs() * dt)
                .min(e.speed + perf.max_acceleration.abs() * dt),
        ),
        None => (f64::INFINITY, wanted),
    };
    if bounded <= crate::tolerance::SPEED && pushing <= 0.0 {
        e.speed = 0.0;
        return ActionStatus::Ended;
    }
    if bounded >= max_speed - crate::tolerance::SPEED && pushing >= 0.0 {
        e.speed = max_speed;
        return ActionStatus::Ended;
    }
    e.speed = bounded;
    ActionStatus::Running
}
