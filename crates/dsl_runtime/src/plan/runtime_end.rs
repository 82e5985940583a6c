//! What the engine measures from the start of a phase that starts on a run-time condition, and
//! what it checks at its end (ASAM OpenSCENARIO DSL 2.1 §8.9 `distance`, `position(…, at:
//! end)`, `speed(…, at: end)`; §7.6: any operational semantics producing accepted traces is
//! valid). The plan does not know the state such a phase starts with, so:
//!
//! | in a phase that starts on a run-time condition | done by |
//! | --- | --- |
//! | `distance(d)` without a duration | a state check at the start notes the actor's odometer (a mark); the phase ends when the engine measures d travelled since (TraveledSinceMark) |
//! | `position(d / time: t / neither, ahead_of/behind: x, at: end)` without a duration (at any start; on a plan over several roads in the plan's s) | the check at the start notes the actor's side of the place the gap asks for (at x's speed); the phase ends when the engine measures the actor there or past it (GapReachedSinceMark) |
//! | `change_speed(v)`, `speed(v, at: end)` beside `distance(d)` without a duration | the engine's SpeedAction at the rate of `acceleration(a)` beside it (else `change_speed`'s default 2 m/s²) from the speed v₀ the actor has, beside its check that the change, \|v² − v₀²\|/(2a), fits within d; the phase ends at d travelled since the mark |
//! | the same at the rate of `acceleration(a, faster_than/slower_than/same_as: x)` | the engine's RelativeAccelerationAction toward v at x's acceleration ± a as it reads it, with no time of its own; the phase ends at d travelled, and the engine checks then that the actor is at v (how far the change runs depends on x's acceleration over it); toward another actor's speed, followed once reached, checked at the end likewise |
//! | `position(…, at: end)`, `distance(d)` over a duration beside `speed(v)` at: all | the speed holds; the engine checks the place (or d travelled since the start's mark) at the phase end: a constraint that holds only if the run meets it is an error record if it does not |
//! | `keep_lane()`, `lane(…)` at: all beside `lateral(d, side_of/left_of/right_of: x, at: end)` | the engine's check at the phase end: the actor in the lane it had at the start (a mark notes it) or in the lane `lane(…)` asks |
//! | `speed(same_as/faster_than/slower_than: x, at: end)` beside a TravelAction | the profile ends at x's speed at the start (± the value); the engine checks x's speed at the phase end |
//!
//! Checks at the end run in the phase's `…/end` Act, which starts when the phase's Act
//! completes (`crate::lower`).

use scenario::{
    ConditionEdge, ConditionGroup, ConditionKind, DynamicsDimension, DynamicsShape,
    EntityCondition, LongitudinalAction, Mark, PrivateAction, RateWithin, SpeedGap, SpeedTarget,
    StateCheck, TransitionDynamics, Trigger,
};

use super::motion::{check_accel, check_speed};
use super::place::{DEFAULT_TIME_GAP, GROUP_GAP};
use super::planner::Planner;
use super::runtime::{phase_start_check, speed_at_rate_check};
use super::runtime_rate::relative_to;
use super::speed_actions::DEFAULT_ACCELERATION;
use super::types::{Planned, When, SPEED_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Arg, ModKind, Modifier};

impl Planner<'_> {
    /// `distance(d)` of `target` in a phase without a duration that starts on a run-time
    /// condition: the check `name` noting the mark at the start, and the end when the engine
    /// measures `d` m travelled since.
    pub(super) fn distance_watch(
        &self,
        m: &Modifier,
        target: &str,
        d: f64,
        name: String,
    ) -> (Planned, When) {
        let end = since_mark(
            m,
            target,
            format!("{target} {d} m from the phase start"),
            EntityCondition::TraveledSinceMark {
                mark: name.clone(),
                value: d,
            },
        );
        (self.mark_check(m, target, name, None), end)
    }

    /// The speed change `m` (`change_speed(v)`, `speed(v, at: end)`) of `target` beside
    /// `distance(d)` `dm` in a phase without a duration that starts at `t0` (`None`: on a
    /// run-time condition): the SpeedAction `name` to v at the rate of `acceleration(a)` beside
    /// it, else the rate `change_speed` takes by default. After a run-time start, from the
    /// speed v₀ the actor has then, beside the engine's check `check_name` that the change
    /// covers \|v² − v₀²\|/(2a) ≤ d (named for the `acceleration(…)` when one gives the rate,
    /// else for `m`), the phase ending when `distance_watch` measures d (`None`); at a known
    /// start the plan's check and the phase's end (`speed_change_over`). A speed relative to
    /// another actor is x's where the phase ends (`relative_over_distance`: at a known start
    /// the plan's x, after a run-time one the engine's, checked in `after` at the end).
    pub(super) fn speed_over_distance(
        &mut self,
        (m, dm): (&Modifier, &Modifier),
        mods: &[Modifier],
        (target, t0): (&str, Option<f64>),
        (check_name, name): (String, String),
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<Option<When>, Error> {
        let Some(d) = dm
            .arg("distance")
            .map(Arg::number)
            .transpose()?
            .filter(|d| *d >= 0.0)
        else {
            return Err(dm.site.err(
                K::Value,
                "expected a distance of 0 m or more in distance(…), found none",
            ));
        };
        let (v1, relative) = self.speed_value(m, t0)?;
        let (rated_by, a) = match mods.iter().find(|q| q.kind == ModKind::Acceleration) {
            // At the rate of another actor's acceleration: the engine's to read.
            Some(q) if relative_to(q).is_some() && t0.is_none() => {
                let names = (name.clone(), format!("{name}.end"));
                self.relative_rate_over_distance(
                    (m, q),
                    target,
                    (v1, relative),
                    names,
                    out,
                    after,
                )?;
                return Ok(None);
            }
            Some(q) if relative_to(q).is_some() => {
                let t = t0.unwrap_or_default(); // the arm above takes a run-time start
                let a = self.relative_rate_over(q, (target, t), v1, d)?;
                check_accel(q, a)?;
                (q, a)
            }
            Some(q) => {
                let a = q
                    .arg("acceleration")
                    .map(Arg::number)
                    .transpose()?
                    .filter(|a| *a != 0.0)
                    .ok_or_else(|| {
                        q.site.err(
                            K::Value,
                            format!("expected a rate other than 0 m/s² in acceleration(…) beside distance(…) at {} and a speed change, found none", dm.site.at()),
                        )
                    })?
                    .abs();
                check_accel(q, a)?;
                (q, a)
            }
            None => (m, DEFAULT_ACCELERATION),
        };
        // Relative to another actor x: at a start the plan knows, x's planned speed where the
        // phase ends (`relative_end_speed`); after a run-time start the engine's x.
        let (v1, to) = match (relative, t0) {
            (Some(x), Some(t)) => {
                let v1 = self.relative_end_speed(m, (target, t), x, (a, d))?;
                (v1, SpeedTarget::Absolute(v1))
            }
            (Some(x), None) => {
                let end_name = format!("{name}.end");
                let to = self.relative_speed_over_distance(m, target, x, (end_name, after));
                (v1, to)
            }
            (None, _) => (v1, SpeedTarget::Absolute(v1)),
        };
        let relative_at_run_time = !matches!(to, SpeedTarget::Absolute(_));
        if !relative_at_run_time {
            check_speed(m, v1)?;
        }
        // At a start the plan knows: the change and the rest of d at v, so the phase's end.
        let end = match t0 {
            Some(t) => Some(self.speed_change_over(rated_by, (target, t), (v1, a), d)?),
            None => {
                out.push(speed_at_rate_check(
                    target,
                    (&rated_by.name, &rated_by.site),
                    (to.clone(), a, RateWithin::Distance(d)),
                    check_name,
                ));
                None
            }
        };
        out.push(Planned::with_phase(
            target,
            name,
            PrivateAction::Longitudinal(LongitudinalAction::Speed {
                dynamics: TransitionDynamics {
                    dynamics_shape: DynamicsShape::Linear,
                    dynamics_dimension: DynamicsDimension::Rate,
                    value: a,
                    following_mode: None,
                },
                target: to,
            }),
            &m.site,
        ));
        if !relative_at_run_time {
            self.last_v.insert(target.to_string(), v1);
        }
        Ok(end)
    }

    /// After a run-time start, the speed change `m` of `target` to `v1` (`relative`: to
    /// another actor's speed ± δ, `relative_rate_to_relative_speed`) at the rate of `q`, an `acceleration(a,
    /// faster_than/slower_than/same_as: x)`, beside `distance(d)` without a duration, as the
    /// action `name`: the engine's RelativeAccelerationAction toward v1 (`to_speed`, the rate
    /// x's acceleration ± a as the engine reads it, at: start over the phase's first step and
    /// held, at: all and end in every step of the change; `relative_rate_at_run_time`) with no
    /// time of its own (d ends the phase: `distance_watch`), and the engine's check at the
    /// phase end (in `after`, as `end_name`, named for `q`) that the actor is at v1 then: how
    /// far the change runs depends on x's acceleration over it, which no check at the start
    /// can read, so a change d cuts short is an error record and a failed run at the end.
    /// With `track: projected` the rate is x's acceleration over the phase's first step, held
    /// (`relative_rate_at_run_time`).
    fn relative_rate_over_distance(
        &mut self,
        (m, q): (&Modifier, &Modifier),
        target: &str,
        (v1, relative): (f64, Option<(String, f64)>),
        (name, end_name): (String, String),
        out: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        if let Some(x) = relative {
            // Toward x's speed, followed on until d ends the phase, checked at its end.
            let change = self.relative_rate_to_relative_speed(
                (m, q),
                target,
                x,
                f64::INFINITY,
                &name,
                after,
            )?;
            out.push(change);
            return Ok(());
        }
        check_speed(m, v1)?;
        let action = self.rate_at_run_time(q, v1, f64::INFINITY)?;
        out.push(Planned::with_phase(target, name, action, &m.site));
        let check = StateCheck {
            speed: Some((None, v1, SPEED_TOLERANCE)),
            ..StateCheck::default()
        };
        after.push(self.end_check(q, target, end_name, check));
        self.last_v.insert(target.to_string(), v1);
        Ok(())
    }

    /// At a start `t` the plan knows, the rate of the change of `target` to `v1` within `d` m
    /// at `q`, an `acceleration(a, faster_than/slower_than/same_as: x)`: \|x's planned
    /// acceleration ± a\| (`acceleration_value`: at: start x's first piece, at: all x's
    /// acceleration constant over the phase, at: end its last piece) over the phase, which ends
    /// when the change (\|v1 − v0\|/rate) and the rest of d at v1 are done, so read over that
    /// span until the rate and the span agree (at once where x's acceleration holds).
    fn relative_rate_over(
        &self,
        q: &Modifier,
        (target, t): (&str, f64),
        v1: f64,
        d: f64,
    ) -> Result<f64, Error> {
        /// Rates within this agree (m/s²); the most rounds of the search.
        const SETTLED: f64 = 1e-9;
        const ROUNDS: usize = 50;
        let v0 = self.track(target).at(t).1;
        // First x's acceleration as the phase starts (its first piece), then over the phase.
        let mut span = 1e-3;
        let mut a = f64::NAN;
        for _ in 0..ROUNDS {
            let next = self.acceleration_value(q, (Some(t), span))?.abs();
            if next <= SETTLED {
                return Err(q.site.err(
                    K::Unsatisfiable,
                    format!("expected a rate other than 0 m/s² for the speed change beside distance({d} m), found {next:.2} m/s² (the other actor's acceleration ± the value)"),
                ));
            }
            if (next - a).abs() <= SETTLED {
                return Ok(next);
            }
            a = next;
            // The change and the rest of d at v1 (a change longer than d, or a standing actor
            // with some of d left, is `speed_change_over`'s error with this rate).
            let covers = (v1 * v1 - v0 * v0).abs() / (2.0 * a);
            let rest = d - covers;
            if rest < 0.0 || (rest > 0.0 && v1 <= 0.0) {
                return Ok(a);
            }
            span = (v1 - v0).abs() / a + if rest > 0.0 { rest / v1 } else { 0.0 };
        }
        Err(q.site.err(
            K::Unsatisfiable,
            format!("expected the other actor's planned acceleration to settle as the rate of the change over distance({d} m), found it changing with the phase's end in {ROUNDS} rounds"),
        ))
    }

    /// At a start `t` the plan knows, the speed change of `target` to `v1` at the rate `a`
    /// (`q` gives it) within `d` m: the change covers \|v1² − v0²\|/(2a) from the speed v0 the
    /// plan has then (more than d: an error at `q`), the rest of d at v1; the track gains the
    /// ramp, and the phase ends when d is covered.
    fn speed_change_over(
        &mut self,
        q: &Modifier,
        (target, t): (&str, f64),
        (v1, a): (f64, f64),
        d: f64,
    ) -> Result<When, Error> {
        let v0 = self.track(target).at(t).1;
        let covers = (v1 * v1 - v0 * v0).abs() / (2.0 * a);
        if covers > d + 1e-9 {
            return Err(q.site.err(
                K::Unsatisfiable,
                format!("expected the speed change from {v0:.2} m/s to {v1:.2} m/s at {a} m/s² within the phase's distance of {d} m, found it covers {covers:.2} m"),
            ));
        }
        let rest = d - covers;
        if rest > 1e-9 && v1 <= 0.0 {
            return Err(q.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to move to travel the last {rest:.2} m of {d} m, found it standing after its speed change"),
            ));
        }
        let ramp = (v1 - v0).abs() / a;
        self.track_mut(target).ramp(t, t + ramp, v1);
        let after = if rest > 1e-9 { rest / v1 } else { 0.0 };
        Ok(When::At(t + ramp + after))
    }

    /// `position(d / time: t / neither, ahead_of/behind: x, at: end)` of `target` in a phase
    /// without a duration (at a start the plan knows too: the 1.x RelativeDistanceCondition
    /// has no sign, so a gap closing through d never rises through it):
    /// the check `name` noting the actor's side of the place at the start, and the end when
    /// the engine measures it there or past it (x projected from the start with `projected`).
    /// `None` for a `position` without a reference.
    pub(super) fn gap_watch(
        &self,
        m: &Modifier,
        target: &str,
        name: String,
    ) -> Result<Option<(Planned, When)>, Error> {
        let Some(gap) = self.speed_gap(m, target)? else {
            return Ok(None);
        };
        let end = since_mark(
            m,
            target,
            format!(
                "{target} at its place {} {}",
                if gap.ahead { "ahead of" } else { "behind" },
                gap.entity_ref
            ),
            EntityCondition::GapReachedSinceMark {
                mark: name.clone(),
                gap: gap.clone(),
            },
        );
        Ok(Some((self.mark_check(m, target, name, Some(gap)), end)))
    }

    /// Where `position(…, ahead_of/behind: x)` puts `target` relative to x, as the engine
    /// measures it at the moment (`None` without a reference): a distance, a time at x's speed
    /// then, or without either the default (`place::default_distance`: 2 s at x's speed, at
    /// least 10 m between the facing bumpers).
    pub(super) fn speed_gap(&self, m: &Modifier, target: &str) -> Result<Option<SpeedGap>, Error> {
        let (x, ahead) = match (m.arg("ahead_of"), m.arg("behind")) {
            (Some(e), _) => (self.entity_of(e)?, true),
            (None, Some(e)) => (self.entity_of(e)?, false),
            (None, None) => return Ok(None),
        };
        let (time, at_least) = match (m.arg("distance"), m.arg("time")) {
            (Some(d), _) => (0.0, d.number()?),
            (None, Some(t)) => (t.number()?, 0.0),
            (None, None) => (
                DEFAULT_TIME_GAP,
                GROUP_GAP + self.facing_overhangs(target, &x, !ahead),
            ),
        };
        Ok(Some(SpeedGap {
            entity_ref: x,
            ahead,
            time,
            at_least,
        }))
    }

    /// The state check `name` of `target` that only notes a mark (named `name`) when the
    /// phase starts.
    pub(super) fn mark_check(
        &self,
        m: &Modifier,
        target: &str,
        name: String,
        gap: Option<scenario::SpeedGap>,
    ) -> Planned {
        let check = StateCheck {
            mark: Some(Mark {
                name: name.clone(),
                gap,
                projected: m.projected,
            }),
            roads: self.chain(),
            ..StateCheck::default()
        };
        phase_start_check(target, (&m.name, &m.site), check, name)
    }

    /// `k` (`keep_lane()`, or `lane(…)` at: all) of `target` beside a `lateral(…, at: end)`
    /// beside another actor in a phase that starts on a run-time condition, where the engine
    /// finds the lane that holds the t asked: the engine's check at the phase end (in
    /// `after`, as `name.end`) that the actor is in the lane it was in at the phase start (a
    /// mark `name` noted then, for `keep_lane`) or in the lane `lane(…)` asks (also checked at
    /// the start, `start_check`).
    pub(super) fn lane_kept_to_end(
        &self,
        k: &Modifier,
        target: &str,
        name: String,
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<(), Error> {
        let check = match k.kind {
            ModKind::KeepLane => {
                out.push(self.mark_check(k, target, name.clone(), None));
                StateCheck {
                    lane_at_mark: Some((name.clone(), 0)),
                    ..StateCheck::default()
                }
            }
            _ => self.start_state(k, target)?,
        };
        after.push(self.end_check(k, target, format!("{name}.end"), check));
        Ok(())
    }

    /// The engine's check of `target` at the phase's end, as the action `name` (for the
    /// phase's `after` actions): `check`'s requirements, written as `m`'s.
    pub(super) fn end_check(
        &self,
        m: &Modifier,
        target: &str,
        name: String,
        check: StateCheck,
    ) -> Planned {
        let check = StateCheck {
            what: format!("{}(…) at the phase end at {}", m.name, m.site.at()),
            roads: self.chain(),
            ..check
        };
        Planned::with_phase(target, name, PrivateAction::Check(Box::new(check)), &m.site)
    }
}

/// The moment `condition` (on `target`, a mark's condition) holds, as the end of `m`'s phase.
fn since_mark(m: &Modifier, target: &str, what: String, condition: EntityCondition) -> When {
    When::Dyn(Trigger {
        condition_groups: vec![ConditionGroup {
            conditions: vec![scenario::Condition {
                name: what,
                // False before the mark is noted, so no edge is needed.
                condition_edge: ConditionEdge::None,
                delay: 0.0,
                kind: ConditionKind::by_entity(target, condition),
                pos: m.site.pos.clone(),
            }],
        }],
    })
}
