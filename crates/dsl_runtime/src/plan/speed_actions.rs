//! The actions that control an actor's speed or acceleration (ASAM OpenSCENARIO DSL 2.1
//! §8.8.2.6 `assign_speed`, §8.8.2.7 `assign_acceleration`, §8.8.2.10 `remain_stationary`,
//! §8.8.2.12 `change_speed`, §8.8.2.13 `keep_speed`, §8.8.2.14 `change_acceleration`,
//! §8.8.2.15 `keep_acceleration`), as the standard's tables say when each starts and ends:
//!
//! | action | lowered to | ends |
//! | --- | --- | --- |
//! | `change_speed(target, rate_profile, rate_peak)` | SpeedAction to `target`: `smooth` sinusoidal, else linear; over the action's `duration` (or the phase's length), at `rate_peak` (m/s², the peak for `smooth`), `asap` at the vehicle's maximum 10 m/s², else at [`DEFAULT_ACCELERATION`] | when the target speed is reached |
//! | `assign_speed(target)` | SpeedAction, step | at once (the speed is reached) |
//! | `keep_speed()` | SpeedAction, step, to its own speed (it ends whatever controlled the speed) | with its phase |
//! | `remain_stationary()` | `keep_position()` (standing from its start) and, after its first phase, a step to 0 m/s | with its phase |
//! | `assign_acceleration(target)` | AccelerationAction, step | at once; the acceleration holds |
//! | `change_acceleration(target, rate_profile, rate_peak)` | AccelerationAction: `smooth` sinusoidal, `asap` a step, else linear; over the `duration` (or the phase's length), at `rate_peak` (m/s³), else at [`DEFAULT_JERK`] (at a rate after a run-time condition: an AccelerationAction ending at its target from the acceleration the engine finds, then a step AccelerationAction holding it) | when the target acceleration is reached; it holds |
//! | `keep_acceleration()` | AccelerationAction keeping the acceleration it starts with | with its phase; it holds |
//!
//! An acceleration an action sets holds after the action ends, until another action or modifier
//! controls the actor's speed (the engine's new longitudinal action replaces the running one) or
//! the scenario ends: its AccelerationAction runs in an Act of its own (`PhasePlan::persist`).
//! The speed a vehicle reaches under it is bounded by 0 m/s and its maximum, where it stops.

use std::f64::consts::FRAC_PI_2;

use scenario::{
    ConditionGroup, DynamicsDimension, DynamicsShape, LongitudinalAction, PrivateAction,
    SpeedTarget, SpeedTargetValueType, StoryboardElementState, TransitionDynamics, Trigger,
};

use super::action_args::{missing, number, positive, profile, rate, timed, Profile};
use super::motion::acceleration;
use super::planner::Planner;
use super::runtime::speed_change_check;
use super::types::{Planned, When, MAX_ACCELERATION, MAX_SPEED};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, At, Invoke, ModKind, Phase};
use crate::trigger::action_state;

/// Acceleration of a speed change that gives neither a rate nor a duration (m/s²): the largest
/// average acceleration ISO 15622 allows an adaptive cruise control, a comfortable change.
pub(crate) const DEFAULT_ACCELERATION: f64 = 2.0;

/// Jerk of an acceleration change that gives neither a rate nor a duration (m/s³): the largest
/// average rate of change of deceleration ISO 15622 allows an adaptive cruise control.
pub(crate) const DEFAULT_JERK: f64 = 2.5;

/// How one invocation's longitudinal action is planned: its actor, its phase's start and length
/// when the plan knows them, and where its actions go.
pub(super) struct Slot<'o> {
    /// The entity.
    pub target: &'o str,
    /// The phase's start.
    pub t0: Option<f64>,
    /// The phase's length, when known before the action is planned (a duration).
    pub len: Option<f64>,
    /// Whether this is the actor's first phase.
    pub first: bool,
    /// The phase's actions.
    pub out: &'o mut Vec<Planned>,
    /// Actions that go on after the phase.
    pub persist: &'o mut Vec<Planned>,
    /// For a member of the vehicle group the invocation is on, at a start the plan knows: its
    /// offset from the group's member 0 along and across the road at that start (m), taken
    /// before any member's action changes the plan.
    pub formation: Option<(f64, f64)>,
    /// For a member of the vehicle group the invocation is on, at a start the plan knows: the
    /// group's speed then (member 0's, m/s).
    pub group_speed: Option<f64>,
}

impl Planner<'_> {
    /// Plans `inv`'s speed or acceleration action for one actor; returns when the action ends
    /// on its own (`None`: with its phase).
    pub(super) fn plan_speed_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            len,
            first,
            out,
            persist,
            ..
        } = slot;
        check_speed_modifiers(inv, first)?;
        let v0 = t0.map_or(self.last_v[target], |t| self.track(target).at(t).1);
        let planned = |name: String, action| Planned::with_phase(target, name, action, &p.site);
        match inv.kind {
            Action::ChangeSpeed => {
                let v1 = speed_target(inv, p)?;
                let profile = profile(inv)?;
                let peak = positive(inv, "rate_peak")?;
                let own = positive(inv, "duration")?;
                let dv = v1 - v0;
                let shape = if profile == Profile::Smooth {
                    DynamicsShape::Sinusoidal
                } else {
                    DynamicsShape::Linear
                };
                let slope = if profile == Profile::Smooth {
                    FRAC_PI_2
                } else {
                    1.0
                };
                if profile == Profile::Asap && own.is_some() {
                    return Err(p.site.err(
                        K::Argument,
                        "expected rate_profile: asap (as soon as possible) or a duration in change_speed(…), found both",
                    ));
                }
                // The change's shape and how long it lasts.
                let (dynamics, span) = match (profile, peak, own.or(len)) {
                    (Profile::Asap, None, _) => rate(shape, MAX_ACCELERATION, dv, slope),
                    (_, Some(a), _) => rate(shape, a, dv, slope),
                    (_, None, Some(d)) => (timed(shape, d), d),
                    (_, None, None) => rate(shape, DEFAULT_ACCELERATION, dv, slope),
                };
                let peak_acc = if span > 0.0 {
                    dv.abs() * slope / span
                } else {
                    0.0
                };
                let timed_at_run_time =
                    t0.is_none() && dynamics.dynamics_dimension == DynamicsDimension::Time;
                if timed_at_run_time {
                    // The rate depends on the speed the actor has then: the engine's check.
                    out.push(speed_change_check(
                        target,
                        (&inv.action, &p.site),
                        (SpeedTarget::Absolute(v1), shape, span),
                        name("check"),
                    ));
                } else if peak_acc > MAX_ACCELERATION + 1e-9 {
                    return Err(p.site.err(
                        K::Unsatisfiable,
                        format!("expected change_speed(…) within the vehicle's ±{MAX_ACCELERATION} m/s², found it needs {peak_acc:.2} m/s² to change from {v0:.2} m/s to {v1:.2} m/s"),
                    ));
                }
                if let (Some(d), Some(_)) = (own, peak) {
                    if span > d + 1e-9 {
                        return Err(p.site.err(
                            K::Unsatisfiable,
                            format!("expected the change from {v0:.2} m/s to {v1:.2} m/s within the action's {d} s, found it needs {span:.2} s at its rate_peak"),
                        ));
                    }
                }
                let n = name("change_speed");
                out.push(planned(
                    n.clone(),
                    PrivateAction::Longitudinal(LongitudinalAction::Speed {
                        dynamics,
                        target: SpeedTarget::Absolute(v1),
                    }),
                ));
                if let Some(t) = t0 {
                    let tr = self.track_mut(target);
                    if shape == DynamicsShape::Sinusoidal {
                        tr.sine(t, t + span, v1);
                    } else {
                        tr.ramp(t, t + span, v1);
                    }
                }
                self.last_v.insert(target.to_string(), v1);
                Ok(Some(self.ends(t0, span, &n, p)))
            }
            Action::AssignSpeed => {
                let v1 = speed_target(inv, p)?;
                let n = name("assign_speed");
                out.push(planned(n.clone(), step_speed(SpeedTarget::Absolute(v1))));
                if let Some(t) = t0 {
                    self.track_mut(target).ramp(t, t, v1);
                }
                self.last_v.insert(target.to_string(), v1);
                Ok(Some(self.ends(t0, 0.0, &n, p)))
            }
            Action::KeepSpeed => {
                out.push(planned(
                    name("keep_speed"),
                    step_speed(SpeedTarget::Relative {
                        entity_ref: target.to_string(),
                        value: 0.0,
                        speed_target_value_type: SpeedTargetValueType::Delta,
                        continuous: false,
                    }),
                ));
                if let Some(t) = t0 {
                    self.track_mut(target).ramp(t, t, v0);
                }
                Ok(None)
            }
            Action::RemainStationary => {
                // Standing from its start (its implied keep_position(): placed at 0 m/s in its
                // first phase, checked standing in a later one); the step ends anything that
                // still controls the speed.
                if !first {
                    out.push(planned(
                        name("remain_stationary"),
                        step_speed(SpeedTarget::Absolute(0.0)),
                    ));
                }
                Ok(None)
            }
            Action::AssignAcceleration => {
                let a = number(inv, "target")?.ok_or_else(|| missing(p, inv, "target"))?;
                check_acceleration(p, a)?;
                let n = name("assign_acceleration");
                persist.push(planned(
                    n,
                    acceleration(Some(a), timed(DynamicsShape::Step, 0.0)),
                ));
                self.hold_acceleration(target, t0, v0, a, 0.0, 0.0)?;
                Ok(Some(self.ends(t0, 0.0, "", p)))
            }
            Action::ChangeAcceleration => {
                let a1 = number(inv, "target")?.ok_or_else(|| missing(p, inv, "target"))?;
                check_acceleration(p, a1)?;
                let profile = profile(inv)?;
                let peak = positive(inv, "rate_peak")?;
                let own = positive(inv, "duration")?;
                let a0 = t0.map(|t| self.track(target).acceleration(t));
                let shape = match profile {
                    Profile::Smooth => DynamicsShape::Sinusoidal,
                    Profile::Asap => DynamicsShape::Step,
                    _ => DynamicsShape::Linear,
                };
                let slope = if profile == Profile::Smooth {
                    FRAC_PI_2
                } else {
                    1.0
                };
                let (dynamics, span) = match (profile, peak, own.or(len)) {
                    (Profile::Asap, _, _) => (timed(DynamicsShape::Step, 0.0), Some(0.0)),
                    (_, None, Some(d)) => (timed(shape, d), Some(d)),
                    (_, j, _) => {
                        let j = j.unwrap_or(DEFAULT_JERK);
                        let (d, _) = rate(shape, j, 0.0, slope);
                        (d, a0.map(|a0| (a1 - a0).abs() * slope / j))
                    }
                };
                // At a rate the span needs the acceleration at the start, which after a
                // run-time condition is the engine's; over a duration it does not (the engine
                // changes from the acceleration it finds, and the plan records no track then).
                let Some(span) = span else {
                    return self.change_acceleration_at_run_time(
                        p,
                        (target, v0, a1),
                        dynamics,
                        name,
                        persist,
                    );
                };
                let a0 = a0.unwrap_or(0.0);
                persist.push(planned(
                    name("change_acceleration"),
                    acceleration(Some(a1), dynamics),
                ));
                self.hold_acceleration(target, t0, v0, a1, span, a0)?;
                Ok(Some(self.ends(t0, span, "", p)))
            }
            Action::KeepAcceleration => {
                let a = t0.map(|t| self.track(target).acceleration(t));
                persist.push(planned(
                    name("keep_acceleration"),
                    acceleration(a, timed(DynamicsShape::Step, 0.0)),
                ));
                if let Some(a) = a {
                    self.hold_acceleration(target, t0, v0, a, 0.0, a)?;
                }
                Ok(None)
            }
            _ => Ok(None),
        }
    }

    /// `change_acceleration` to `a1` at a rate (`dynamics`) in a phase of `target` (speed `v0`
    /// as the plan last knows it) that starts on a run-time condition: the change lasts
    /// |a1 − a0|·f′max/j from the acceleration a0 the engine finds then. The engine's
    /// AccelerationAction ending at its target (`ends_at_target`) ramps it and ends the phase
    /// when it ends (its Event complete); the held acceleration is a step AccelerationAction to
    /// `a1` that starts when the ramp ends by reaching it (the Action's endTransition: a ramp
    /// another longitudinal action replaces hands nothing on). Both go on after the phase
    /// (`persist`), as at a known start.
    fn change_acceleration_at_run_time(
        &mut self,
        p: &Phase,
        (target, v0, a1): (&str, f64, f64),
        dynamics: TransitionDynamics,
        name: &mut dyn FnMut(&str) -> String,
        persist: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        let ramp = name("change_acceleration");
        persist.push(Planned::with_phase(
            target,
            ramp.clone(),
            PrivateAction::Longitudinal(LongitudinalAction::Acceleration {
                target: Some(a1),
                dynamics,
                ends_at_target: true,
            }),
            &p.site,
        ));
        let mut hold = Planned::with_phase(
            target,
            name("hold_acceleration"),
            acceleration(Some(a1), timed(DynamicsShape::Step, 0.0)),
            &p.site,
        );
        hold.at = Some(When::Dyn(Trigger {
            condition_groups: vec![ConditionGroup {
                conditions: vec![action_state(
                    &ramp,
                    StoryboardElementState::EndTransition,
                    p.site.pos.clone(),
                )],
            }],
        }));
        persist.push(hold);
        self.hold_acceleration(target, None, v0, a1, 0.0, 0.0)?;
        Ok(Some(self.ends(None, 0.0, &ramp, p)))
    }

    /// Plans `target`'s speed under an acceleration that changes from `a0` to `a1` over `span`
    /// s from `t0` (linearly: constant jerk) and then holds until the speed reaches 0 m/s or
    /// the maximum. Without a known start only the speed at the end is recorded.
    fn hold_acceleration(
        &mut self,
        target: &str,
        t0: Option<f64>,
        v0: f64,
        a1: f64,
        span: f64,
        a0: f64,
    ) -> Result<(), Error> {
        let bound = if a1 > 0.0 {
            MAX_SPEED
        } else if a1 < 0.0 {
            0.0
        } else {
            v0
        };
        self.last_v.insert(target.to_string(), bound);
        let Some(t) = t0 else {
            return Ok(());
        };
        let tr = self.track_mut(target);
        if span > 0.0 {
            tr.jerk(t, t + span, a0, (a1 - a0) / span);
        }
        let (_, v) = tr.at(t + span);
        let rest = if a1 != 0.0 { (bound - v) / a1 } else { 0.0 };
        if rest > 0.0 {
            tr.jerk(t + span, t + span + rest, a1, 0.0);
        } else {
            tr.ramp(t + span, t + span, v.clamp(0.0, MAX_SPEED));
        }
        if a1 == 0.0 {
            // The speed holds where the change leaves it (not where it started).
            self.last_v
                .insert(target.to_string(), v.clamp(0.0, MAX_SPEED));
        }
        Ok(())
    }
}

/// An action that controls the speed (or acceleration) takes no modifier that changes the speed
/// in its phase: those are the action's own (`speed(…)` at the start of the actor's first phase
/// places it, and stays allowed).
pub(super) fn check_speed_modifiers(inv: &Invoke, first: bool) -> Result<(), Error> {
    let controls = matches!(
        inv.kind,
        Action::ChangeSpeed
            | Action::AssignSpeed
            | Action::AssignAcceleration
            | Action::ChangeAcceleration
            | Action::KeepAcceleration
            | Action::ChangeSpaceGap
            | Action::KeepSpaceGap
            | Action::ChangeTimeHeadway
            | Action::KeepTimeHeadway
    );
    if !controls {
        return Ok(());
    }
    let conflict = inv.modifiers.iter().find(|m| match m.kind {
        ModKind::ChangeSpeed | ModKind::Acceleration | ModKind::Distance => true,
        ModKind::Position => m.at == At::End,
        ModKind::Speed => m.at == At::End || !first,
        _ => false,
    });
    match conflict {
        Some(m) => Err(m.site.err(
            K::Unsatisfiable,
            format!(
                "expected no speed modifier beside {}(…), which controls the speed, found `{}(…)`",
                inv.action, m.name
            ),
        )),
        None => Ok(()),
    }
}

/// A SpeedAction with a step shape.
pub(super) fn step_speed(target: SpeedTarget) -> PrivateAction {
    PrivateAction::Longitudinal(LongitudinalAction::Speed {
        dynamics: timed(DynamicsShape::Step, 0.0),
        target,
    })
}

/// The `target` speed of `inv`: mandatory, within 0 m/s and the vehicle's maximum.
pub(super) fn speed_target(inv: &Invoke, p: &Phase) -> Result<f64, Error> {
    let a = arg(&inv.args, "target").ok_or_else(|| missing(p, inv, "target"))?;
    let v = a.number()?;
    if !(0.0..=MAX_SPEED).contains(&v) {
        return Err(a.site.err(
            K::Unsatisfiable,
            format!("expected a target speed within 0 to {MAX_SPEED} m/s, found {v:.2} m/s"),
        ));
    }
    Ok(v)
}

/// An acceleration within the vehicle's limits.
fn check_acceleration(p: &Phase, a: f64) -> Result<(), Error> {
    if a.abs() > MAX_ACCELERATION + 1e-9 {
        return Err(p.site.err(
            K::Unsatisfiable,
            format!("expected an acceleration within the vehicle's ±{MAX_ACCELERATION} m/s², found {a:.2} m/s²"),
        ));
    }
    Ok(())
}
