//! oscsim's RelativeAccelerationAction (`scenario::LongitudinalAction::RelativeAcceleration`,
//! an action with no XML form): in each step the actor's longitudinal acceleration is its
//! reference's plus a constant, ASAM OpenSCENARIO DSL 2.1 §8.9 `acceleration(…, faster_than /
//! slower_than / same_as: x)` ("relative to" x) followed as x's acceleration changes, which no
//! OpenSCENARIO 1.x action does (a RelativeTargetSpeed follows x's speed, not its
//! acceleration).
//!
//! `continuous`: the speed is the integral from the start: after τ s, v = v₀ + (v_x − v_x₀) +
//! value·τ, with v₀ and v_x₀ the actor's and the reference's speeds at the start and v_x the
//! reference's speed at the step's end. Written through the speeds (not a sum of per-step
//! accelerations) it carries no drift. Not `continuous`: the reference's acceleration as the
//! action starts, over its first step (a_x₀ = (v_x − v_x₀)/dt, the acceleration the reference
//! starts the phase with, as a planned linear change has it from its first instant), plus the
//! value, held: v = v₀ + (a_x₀ + value)·τ. Stage 2 advances these parts after every other running action (see
//! `ActionTable::step_all`), so v_x is the speed the reference's own action set for the same
//! step's end; a reference moved by a controller (stage 3) is read one step late. A vehicle's
//! Performance bounds the change per step as for the AccelerationAction; the action ends at
//! 0 m/s while pushing below it, or at the maximum speed while pushing above, and otherwise
//! runs until a later longitudinal action replaces it or its Act ends.
//!
//! With `transition` (DSL 2.1 §8.9.1.1.4 `acceleration(…, shape: s)` relative to x, the
//! shape's `change_acceleration` dynamics, after a run-time start) the acceleration goes from
//! a₀, the actor's at the start, to the target a_t = a_x + value under the transition's shape
//! f over its span T (a rate: T = |a_t − a₀|·f′max/j with the target read over the first
//! step, as the plan reads x's acceleration at a phase start): a(τ) = a₀ + (a_t − a₀)·f(τ/T).
//! a_t is the reference's acceleration over each step plus the value when `continuous` (x's
//! acceleration followed), else its value over the first step, fixed (projected). The speed
//! gains ∫a over each step exactly where a_t is constant over it: a₀·dt + (a_t − a₀)·T·(F(τ₁/T)
//! − F(τ₀/T)), F the shape's integral, summed from the start (so after T it follows a_t, or
//! holds it). With `ends_at_target` the action ends in the step that completes the
//! transition; otherwise it goes on so.
//!
//! With `to_speed` the acceleration is the rate of a speed change (DSL 2.1 §8.9
//! `acceleration(…)` beside `change_speed`): in each step the speed moves toward the target
//! by |a|·dt (a the acceleration above: held, or the reference's over the step plus the
//! value), not past it; the action ends in the step that reaches the target, and fails in the
//! step that ends `within` s after its start without it (an error record, and the run stops,
//! as a failed state check: [`ErrorKind::CheckFailed`]). A target relative to an entity
//! (`SpeedChange::of`) is that entity's speed plus the change's: read once at the start when
//! projected, else in every step, and then the action follows it once reached (at the same
//! rate, so it does not end by itself), failing only where it is not there `within` s after
//! its start.

use scenario::{SpeedChange, TransitionDynamics};

use super::Part;
use crate::error::{Error, ErrorKind};
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::shapes::{shape_integral, shape_value, span, Span};

/// A transition of the acceleration to the reference's plus the value (module doc).
#[derive(Debug, Clone)]
pub(crate) struct Transition {
    dynamics: TransitionDynamics,
    /// The actor's acceleration at the start (m/s²).
    from: f64,
    /// The span, known from the first step (a rate's depends on the target read then).
    span: Option<Span>,
    /// The speed the transition has given the actor by the last step's end (m/s).
    speed: f64,
    ends_at_target: bool,
    /// When a transition that ends at its target completed (the step's end) and the
    /// acceleration it reached there, for an AccelerationAction that keeps it to start from.
    reached: Option<(f64, f64)>,
}

/// A running RelativeAccelerationAction on one actor.
#[derive(Debug, Clone)]
pub(crate) struct RelativeAccelerationState {
    reference: EntityId,
    value: f64,
    /// Follow the reference in every step; else hold `held`.
    continuous: bool,
    /// Not continuous: the acceleration held, the reference's over the first step plus the
    /// value (known from the first step on).
    held: Option<f64>,
    /// The actor's and the reference's speeds at the start (m/s).
    start_speed: f64,
    reference_start_speed: f64,
    start_time: f64,
    /// The speed change the acceleration is the rate of, if any (a target relative to an
    /// entity read at the start when projected: then fixed).
    to_speed: Option<SpeedChange>,
    /// The entity whose speed the change aims at, read in every step (`SpeedChange::of`, not
    /// projected): the target is its speed plus `to_speed`'s, followed once reached.
    target_of: Option<EntityId>,
    /// The reference's speed at the last step's end (m/s): its acceleration over a step.
    reference_last_speed: f64,
    /// Why the speed change failed, for the action table to report.
    pub(crate) failure: Option<Error>,
    /// A transition to the target acceleration (`None`: at once).
    transition: Option<Transition>,
}

impl RelativeAccelerationState {
    /// When a transition that ends at its target completed (a step's end) and the acceleration
    /// it reached (an AccelerationAction keeping it, started then, starts from it: the
    /// entity's own acceleration is that step's mean).
    pub(crate) fn reached(&self) -> Option<(f64, f64)> {
        self.transition.as_ref()?.reached
    }

    /// True when a transition that ends at its target completes by `t` (the storyboard sees it
    /// end in the step whose motion completes it, as an AccelerationAction's); its span is
    /// known from its first step on.
    pub(crate) fn completes_by(&self, t: f64) -> bool {
        self.transition.as_ref().is_some_and(|tr| {
            tr.ends_at_target
                && match tr.span {
                    Some(Span::Time(d)) => t - self.start_time >= d - crate::tolerance::TIME,
                    Some(_) => true,
                    None => false,
                }
        })
    }
}

/// Starts the action on `actor` at `now`, relative to the entity named `entity_ref`.
pub(crate) fn start(
    world: &World,
    actor: EntityId,
    entity_ref: &str,
    (value, continuous, to_speed): (f64, bool, Option<&SpeedChange>),
    (transition, ends_at_target): (Option<&TransitionDynamics>, bool),
    (now, pos): (f64, &scenario::SourcePos),
) -> Result<Part, Error> {
    let reference = world.id(entity_ref).ok_or_else(|| {
        Error::at(
            "a declared entity",
            format!("entityRef '{entity_ref}'"),
            pos,
        )
    })?;
    let mut to_speed = to_speed.cloned();
    let mut target_of = None;
    if let Some(change) = to_speed.as_mut() {
        if let Some(of) = change.of.take() {
            let id = world.id(&of.entity_ref).ok_or_else(|| {
                Error::at(
                    "a declared entity",
                    format!("entityRef '{}'", of.entity_ref),
                    pos,
                )
            })?;
            // Projected: the entity's speed now, fixed; else read in every step.
            match of.projected {
                true => change.speed += world.entity(id).speed,
                false => target_of = Some(id),
            }
        }
    }
    let e = world.entity(actor);
    let transition = transition.map(|dynamics| Transition {
        dynamics: *dynamics,
        from: e.travel_component(e.acceleration.translational),
        span: None,
        speed: e.speed,
        ends_at_target,
        reached: None,
    });
    Ok(Part::RelativeAcceleration(RelativeAccelerationState {
        reference,
        value,
        continuous,
        held: None,
        transition,
        start_speed: world.entity(actor).speed,
        reference_start_speed: world.entity(reference).speed,
        start_time: now,
        to_speed,
        target_of,
        reference_last_speed: world.entity(reference).speed,
        failure: None,
    }))
}

/// The actor's speed `tau` s after the start when its reference then has `reference_speed`:
/// v₀ + (v_x − v_x₀) + value·τ.
fn followed_speed(s: &RelativeAccelerationState, reference_speed: f64, tau: f64) -> f64 {
    s.start_speed + (reference_speed - s.reference_start_speed) + s.value * tau
}

/// Sets the speed for the step from `now` to `now + dt`.
pub(crate) fn step(
    world: &mut World,
    actor: EntityId,
    s: &mut RelativeAccelerationState,
    now: f64,
    dt: f64,
) -> ActionStatus {
    let tau = now + dt - s.start_time;
    let reference_speed = world.entity(s.reference).speed;
    if !s.continuous && s.held.is_none() {
        s.held = Some((reference_speed - s.reference_start_speed) / tau + s.value);
    }
    let last = std::mem::replace(&mut s.reference_last_speed, reference_speed);
    let target = s.held.unwrap_or((reference_speed - last) / dt + s.value);
    if let Some(tr) = &mut s.transition {
        return transition_step(world, actor, tr, target, (tau, dt, now + dt));
    }
    if s.to_speed.is_some() {
        let a = s.held.unwrap_or((reference_speed - last) / dt + s.value);
        return toward(world, actor, s, (a, tau), (now, dt));
    }
    let (wanted, pushing) = match s.held {
        Some(a) => (s.start_speed + a * tau, a),
        None => {
            let wanted = followed_speed(s, reference_speed, tau);
            (wanted, wanted - world.entity(actor).speed)
        }
    };
    super::acceleration::set_speed(world, actor, wanted, pushing, dt)
}

/// One step of a transition `tr` to the acceleration `target` (over this step), `tau` s after
/// the start at the step's end (module doc).
fn transition_step(
    world: &mut World,
    actor: EntityId,
    tr: &mut Transition,
    target: f64,
    (tau, dt, tau_end): (f64, f64, f64),
) -> ActionStatus {
    let span = *tr
        .span
        .get_or_insert_with(|| span(&tr.dynamics, target - tr.from));
    let shape = tr.dynamics.dynamics_shape;
    // ∫₀^τ f(q/T) dq, and f(τ/T): done at once without a time span.
    let time = match span {
        Span::Time(t) => Some(t),
        _ => None,
    };
    let integral = |u: f64| time.map_or(u, |t| t * shape_integral(shape, u / t));
    let done = time.map_or(1.0, |t| shape_value(shape, tau / t).0);
    tr.speed += tr.from * dt + (target - tr.from) * (integral(tau) - integral(tau - dt));
    let pushing = tr.from + (target - tr.from) * done;
    let status = super::acceleration::set_speed(world, actor, tr.speed, pushing, dt);
    let over = match span {
        Span::Time(t) => tau >= t - crate::tolerance::TIME,
        _ => true,
    };
    if tr.ends_at_target && over {
        tr.reached = Some((tau_end, target));
        ActionStatus::Ended
    } else {
        status
    }
}

/// One step of the speed change toward `s.to_speed` at the rate |a|, `tau` s after the start
/// at the step's end.
fn toward(
    world: &mut World,
    actor: EntityId,
    s: &mut RelativeAccelerationState,
    (a, tau): (f64, f64),
    (now, dt): (f64, f64),
) -> ActionStatus {
    let Some(change) = &s.to_speed else {
        return ActionStatus::Ended;
    };
    let e = world.entity(actor);
    let (v, name) = (e.speed, e.name.clone());
    // A target relative to an entity: its speed now plus the change's.
    let target = change.speed + s.target_of.map_or(0.0, |o| world.entity(o).speed);
    let gap = target - v;
    let fail = |expected: String, found: String| {
        Some(Error::new(ErrorKind::CheckFailed {
            what: change.what.clone(),
            expected,
            found,
            time: now + dt,
        }))
    };
    // A rate beyond the vehicle's Performance would be cut by it: an error, never a slower
    // change.
    let limit = e.performance.map(|p| {
        if gap > 0.0 {
            p.max_acceleration.abs()
        } else {
            p.max_deceleration.abs()
        }
    });
    if let Some(limit) = limit.filter(|l| a.abs() > l + crate::tolerance::VALUE) {
        s.failure = fail(
            format!("a rate within '{name}''s {limit:.3} m/s²"),
            format!("{:.3} m/s²", a.abs()),
        );
        return ActionStatus::Stopped;
    }
    let wanted = if gap.abs() <= a.abs() * dt {
        target
    } else {
        v + gap.signum() * a.abs() * dt
    };
    let status = super::acceleration::set_speed(world, actor, wanted, gap.signum() * a.abs(), dt);
    let reached = world.entity(actor).speed;
    let there = (reached - target).abs() <= crate::tolerance::SPEED;
    // A fixed target ends the change; an entity's speed is followed on.
    if there && s.target_of.is_none() {
        return ActionStatus::Ended;
    }
    if !there && tau >= change.within - crate::tolerance::TIME {
        s.failure = fail(
            format!(
                "'{name}' at {target:.3} m/s within {:.3} s of its start",
                change.within
            ),
            format!("{reached:.3} m/s"),
        );
        return ActionStatus::Stopped;
    }
    status
}

#[cfg(test)]
mod tests {
    use super::{followed_speed, RelativeAccelerationState};
    use crate::world::entity::EntityId;

    /// A state started at t = 1 s with the actor at 12 m/s and the reference at 10 m/s.
    fn started(value: f64) -> RelativeAccelerationState {
        RelativeAccelerationState {
            reference: EntityId(0),
            value,
            continuous: true,
            held: None,
            start_speed: 12.0,
            reference_start_speed: 10.0,
            start_time: 1.0,
            to_speed: None,
            target_of: None,
            reference_last_speed: 10.0,
            failure: None,
            transition: None,
        }
    }

    /// same_as (value 0): the reference brakes from 10 to 6 m/s (−2 m/s² over 2 s, then −1
    /// m/s² for 1 s to 5 m/s): the actor loses the same 4 m/s and then 1 m/s, 12 → 8 → 7 m/s,
    /// whatever the reference's acceleration was step by step.
    #[test]
    fn same_as_loses_what_the_reference_loses() {
        let s = started(0.0);
        assert!((followed_speed(&s, 6.0, 2.0) - 8.0).abs() < 1e-12);
        assert!((followed_speed(&s, 5.0, 3.0) - 7.0).abs() < 1e-12);
    }

    /// faster_than by 0.5 m/s²: after 2 s the reference went 10 → 14 m/s (+2 m/s²), the
    /// actor 12 → 12 + 4 + 0.5·2 = 17 m/s (+2.5 m/s²).
    #[test]
    fn faster_than_adds_its_value_per_second() {
        let s = started(0.5);
        assert!((followed_speed(&s, 14.0, 2.0) - 17.0).abs() < 1e-12);
    }
}
