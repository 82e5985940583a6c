//! A speed relative to another actor at the end of a phase that `distance(d)` ends (ASAM
//! OpenSCENARIO DSL 2.1 §8.9 `speed(same_as/faster_than/slower_than: x, at: end)`,
//! `change_speed`, `distance`; §8.9.1.1.1 `at: end`: "this constraint holds at the end of the
//! phase"; §8.9.1.1.3 `track`: "The default is actual, meaning that the vehicle reacts to the
//! behavior of the referenced vehicle").
//!
//! The phase has no duration: it ends when the actor has covered d, and the speed change runs
//! at a rate (`acceleration(a)` beside it, else `change_speed`'s default) inside it
//! (`runtime_end::speed_over_distance`). Relative to x the speed to reach is x's (± the value):
//!
//! | start | `track: actual` (default) | `track: projected` |
//! | --- | --- | --- |
//! | one the plan knows | x's planned speed where the phase ends, which depends on the change: the plan solves v₁ = v_x(t_e(v₁)) ± δ (`relative_end_speed`), then plans the change to v₁ at its rate as for a speed of its own | x's planned speed at the phase start |
//! | after a run-time condition | the engine's SpeedAction at the rate to x's speed read each step, kept after the change (continuous: the actor goes on reacting to x until d ends the phase); the engine checks at the start that the change to x's speed then covers \|v₁² − v₀²\|/(2a) ≤ d, and at the end that the actor's speed is x's then | oscsim's RelativeAtStart target (x's speed as the action starts, fixed); the check at the start only |

use scenario::{SpeedTarget, SpeedTargetValueType, StateCheck};

use super::planner::Planner;
use super::types::{Planned, SPEED_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::Modifier;

/// How closely x's speed where the phase ends must repeat the speed the change aims at before
/// the plan takes it (m/s): well below the engine's `SPEED_TOLERANCE` checks.
const SETTLED: f64 = 1e-9;

/// The most rounds of the plan's search for that speed; a search that has not settled by then
/// is an error (x's speed changes too fast for the change's rate to catch).
const ROUNDS: usize = 200;

impl Planner<'_> {
    /// At a start `t` the plan knows, the speed `m` (relative to `x` by `delta`) asks of
    /// `target` where `distance(d)` ends its phase, the change running at the rate `a`: with
    /// `track: projected` x's planned speed at `t`; with `track: actual` x's planned speed at
    /// the phase's end t_e, which itself depends on the change (it takes \|v₁ − v₀\|/a and
    /// covers \|v₁² − v₀²\|/(2a), the rest of d at v₁): the plan repeats v₁ ← v_x(t_e(v₁)) + δ
    /// from x's speed at `t` until it settles (x's speed holding over the phase: at once).
    pub(super) fn relative_end_speed(
        &self,
        m: &Modifier,
        (target, t): (&str, f64),
        (x, delta): (String, f64),
        (a, d): (f64, f64),
    ) -> Result<f64, Error> {
        let of_x = |at: f64| self.track(&x).at(at).1 + delta;
        let mut v1 = of_x(t);
        if m.projected {
            return Ok(v1);
        }
        let v0 = self.track(target).at(t).1;
        let mut before = v1;
        for _ in 0..ROUNDS {
            // A change that does not fit in d, or a standing actor, is the caller's error
            // (`speed_change_over`), with this v₁.
            let Some(te) = ends_after(v0, v1, a, d) else {
                return Ok(v1);
            };
            let next = of_x(t + te);
            if (next - v1).abs() <= SETTLED {
                return Ok(next);
            }
            (before, v1) = (v1, next);
        }
        Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a speed of `{x}` where distance({d} m) ends the phase that a change to it at {a} m/s² from {v0:.2} m/s ends the phase with, found none settling in {ROUNDS} rounds (the last two: {before:.2} and {v1:.2} m/s; `{x}`'s speed jumps where the phase would end)"),
        ))
    }

    /// After a run-time start, the engine's target of the change `m` (relative to `x` by
    /// `delta`) of `target`: with `track: actual` x's speed read at each step, followed after
    /// the change (continuous), beside the engine's check at the phase end (in `after`) that
    /// the actor's speed is x's then (± delta), as the action `end_name`; with `track: projected` x's speed as the action
    /// starts, fixed (oscsim's RelativeAtStart target, no XML form).
    pub(super) fn relative_speed_over_distance(
        &self,
        m: &Modifier,
        target: &str,
        (x, delta): (String, f64),
        (end_name, after): (String, &mut Vec<Planned>),
    ) -> SpeedTarget {
        if m.projected {
            return SpeedTarget::RelativeAtStart {
                entity_ref: x,
                value: delta,
            };
        }
        let check = StateCheck {
            speed: Some((Some(x.clone()), delta, SPEED_TOLERANCE)),
            ..StateCheck::default()
        };
        after.push(self.end_check(m, target, end_name, check));
        SpeedTarget::Relative {
            entity_ref: x,
            value: delta,
            speed_target_value_type: SpeedTargetValueType::Delta,
            continuous: true,
        }
    }
}

/// The time (s) a change from `v0` to `v1` at the rate `a` and then the rest of `d` at `v1`
/// take; `None` when the change alone covers more than d, or the actor stands with some of d
/// left.
fn ends_after(v0: f64, v1: f64, a: f64, d: f64) -> Option<f64> {
    let covers = (v1 * v1 - v0 * v0).abs() / (2.0 * a);
    let rest = d - covers;
    if rest < 0.0 || (rest > 0.0 && v1 <= 0.0) {
        return None;
    }
    let after = if rest > 0.0 { rest / v1 } else { 0.0 };
    Some((v1 - v0).abs() / a + after)
}
