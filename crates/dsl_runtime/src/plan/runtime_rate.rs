//! Speed changes at a rate relative to another actor in a phase that starts on a run-time
//! condition (ASAM OpenSCENARIO DSL 2.1 §8.9 `speed(same_as/faster_than/slower_than: x, at:
//! end)`, `acceleration(…)` as the rate of a speed change; §8.9.1.1.3 `track`): how long the
//! change takes depends on the speeds (or on another actor's acceleration) at and after the
//! start, which only the engine has, so the engine runs the change and checks it.
//!
//! | the change | done by |
//! | --- | --- |
//! | to x's speed at the rate of `acceleration(a)` over a phase of duration T | the engine's SpeedAction at rate a to x's speed (actual: read each step, followed after the change, checked at the end; projected: x's at the start), beside its check at the start that \|v_x ± δ − v₀\|/a ≤ T |
//! | toward v or x's speed at the rate of `acceleration(a, faster_than/slower_than/same_as: y)` (with a duration or beside `distance(d)`) | the engine's RelativeAccelerationAction toward it at y's acceleration ± a as it reads it (`rate_at_run_time`); x's speed followed once reached; checked at the phase end |

use scenario::{
    DynamicsDimension, DynamicsShape, LongitudinalAction, PrivateAction, RateWithin, SpeedOf,
    StateCheck, TransitionDynamics,
};

use super::motion::check_accel;
use super::planner::Planner;
use super::runtime::speed_at_rate_check;
use super::types::{Planned, SPEED_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Arg, Modifier};

impl Planner<'_> {
    /// The speed `m` asks of `target` relative to `x` (± `delta`) at the end of a phase of
    /// `len` s that starts on a run-time condition, at the rate of `acceleration(a)` `q`
    /// beside it, as the actions `check_name` and `name`: the change takes \|v_x ± δ − v₀\|/a
    /// from both speeds at the start, which only the engine has, so the engine's SpeedAction
    /// at the rate a to x's speed (± δ) and its check at that start that the change ends
    /// within the phase from those speeds (`speed_at_rate_check`, an error record and a failed
    /// run otherwise: the phase's end would cut it short). With `track: actual` the target is
    /// x's speed read at each step and followed after the change (the engine's linear change
    /// over the length fixed at the start, blended to x's speed as it moves), checked at the
    /// phase end (`relative_speed_over_distance`); `track: projected` x's speed as the action
    /// starts, fixed. At the rate of an acceleration relative to another actor y, the
    /// engine's change at y's acceleration (`relative_rate_to_relative_speed`), with no check
    /// at the start (its length depends on y's acceleration over it).
    pub(super) fn start_relative_speed_at_rate(
        &self,
        (m, q): (&Modifier, &Modifier),
        target: &str,
        (x, len): ((String, f64), f64),
        (check_name, name): (String, String),
        after: &mut Vec<Planned>,
    ) -> Result<Vec<Planned>, Error> {
        if relative_to(q).is_some() {
            // No check at the start: the change's length depends on y's acceleration over it.
            let change =
                self.relative_rate_to_relative_speed((m, q), target, x, len, &name, after)?;
            return Ok(vec![change]);
        }
        let a = self.acceleration_value(q, (None, len))?.abs();
        check_accel(q, a)?;
        let end_name = format!("{name}.end");
        let to = self.relative_speed_over_distance(m, target, x, (end_name, after));
        let dynamics = TransitionDynamics {
            dynamics_shape: DynamicsShape::Linear,
            dynamics_dimension: DynamicsDimension::Rate,
            value: a,
            following_mode: None,
        };
        Ok(vec![
            speed_at_rate_check(
                target,
                (&q.name, &q.site),
                (to.clone(), a, RateWithin::Time(len)),
                check_name,
            ),
            Planned::with_phase(
                target,
                name,
                PrivateAction::Longitudinal(LongitudinalAction::Speed {
                    dynamics,
                    target: to,
                }),
                &m.site,
            ),
        ])
    }

    /// The engine's change toward `v1` m/s (added to a relative target's speed) within
    /// `within` s at the rate of `q`, an `acceleration(a, faster_than/slower_than/same_as: y)`,
    /// in a phase that starts on a run-time condition (`relative_rate_at_run_time`); with `track:
    /// projected` y's acceleration over the phase's first step, held.
    pub(super) fn rate_at_run_time(
        &self,
        q: &Modifier,
        v1: f64,
        within: f64,
    ) -> Result<PrivateAction, Error> {
        match self.relative_rate_at_run_time(Some(q), None, (v1, within))? {
            Some(action) => Ok(action),
            None => self
                .acceleration_value(q, (None, within))
                .and(Err(q.site.err(
                K::Modifier,
                "expected an acceleration relative to another actor in acceleration(…), found none",
            ))),
        }
    }

    /// The speed `m` asks of `target` relative to `x` (± `delta`) at the end of a phase that
    /// starts on a run-time condition, at the rate of `q`, an `acceleration(a,
    /// faster_than/slower_than/same_as: y)`, as the action `name`: the engine's
    /// RelativeAccelerationAction toward x's speed ± δ (oscsim's `to_speed` with a target
    /// relative to x, `SpeedOf`, no XML form), its rate \|a_y ± a\| as the engine reads y's
    /// acceleration (at: start over the phase's first step, held; at: all and end in every
    /// step, `relative_rate_at_run_time`); with `track: actual` x's speed read in every step
    /// and followed once reached, the engine's check at the phase end (in `after`) that the
    /// actor is at x's speed then ± δ; `track: projected` x's speed as the action starts,
    /// fixed. Not there `within` s after the start (the phase's length; a distance ends the
    /// phase instead with `f64::INFINITY`) is an error record and a failed run.
    pub(super) fn relative_rate_to_relative_speed(
        &self,
        (m, q): (&Modifier, &Modifier),
        target: &str,
        (x, delta): (String, f64),
        within: f64,
        name: &str,
        after: &mut Vec<Planned>,
    ) -> Result<Planned, Error> {
        let mut action = self.rate_at_run_time(q, delta, within)?;
        if let PrivateAction::Longitudinal(LongitudinalAction::RelativeAcceleration {
            to_speed: Some(change),
            ..
        }) = &mut action
        {
            change.of = Some(SpeedOf {
                entity_ref: x.clone(),
                projected: m.projected,
            });
        }
        if !m.projected {
            let check = StateCheck {
                speed: Some((Some(x), delta, SPEED_TOLERANCE)),
                ..StateCheck::default()
            };
            after.push(self.end_check(m, target, format!("{name}.end"), check));
        }
        Ok(Planned::with_phase(
            target,
            name.to_string(),
            action,
            &m.site,
        ))
    }
}

/// The actor `q` (an `acceleration(…)`) is relative to, if any (`faster_than`, `slower_than`,
/// `same_as`).
pub(super) fn relative_to(q: &Modifier) -> Option<&Arg> {
    ["faster_than", "slower_than", "same_as"]
        .into_iter()
        .find_map(|key| q.arg(key))
}
