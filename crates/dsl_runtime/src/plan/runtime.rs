//! The line between the plan and the run (ASAM OpenSCENARIO DSL 2.1 §7.3.9 `until`, `wait`;
//! §8.9 `at: start`): a phase that starts on a run-time condition starts at a moment the plan
//! does not know, so what the plan would check against its tracks at a known start is checked
//! by the engine when the phase starts (oscsim's state check, `scenario::StateCheck`), and a
//! motion the plan would work out from the state at a known start the engine works out then
//! (oscsim's TravelAction, `scenario::Travel`). A failure of either is an error record in the
//! event log and a failed run, never a silent change.
//!
//! | at the start of a phase that starts on a run-time condition | done by |
//! | --- | --- |
//! | `lane(n [, from: left])` (at: start, all) | the engine's check: the actor in that driving lane |
//! | `lane(same_as/side_of/left_of/right_of: x)` (at: start, all) | the engine's check: the actor in the lane counted from x's, as a RelativeTargetLane counts (at: all held over the phase, and an actor with no sideways motion of its own follows x's lane changes as they begin: `held_relation`) |
//! | `position(d)` (at: start, all) | the engine's check: the actor at s = d (0.5 m) |
//! | `position(d / time: t / neither, ahead_of/behind: x)` (at: start, all) | the engine's check: x at ∓d along the road, d the distance, t at x's speed then, or the default gap (0.5 m) (at: all held over the phase, with `track: projected` against x projected from the start; an actor free along its lane the engine's hold, `held_relation`) |
//! | `lateral(d, measure_by, side)` in its lane (at: start, all) | the engine's check: the offset from the lane's centre, from a border with the lane's width where the engine finds the actor (1 cm) |
//! | `lateral(d, side_of/left_of/right_of: x)` (at: start, all) | the engine's check: the actor's t minus x's (1 cm), a member of a group over several lanes at its slot in the block as the plan last knows it (`beside_slot`) (at: all held over the phase, with `track: projected` against x's t at the start; with `track: actual` the engine follows x, `lateral_follow`) |
//! | `position(d [, ahead_of/behind: x], at: end)`, `distance(d)` over a phase of duration T | the engine's TravelAction: the two-halves profile worked out from the state at the start |
//! | `along(r)` on a named route (at: start, all) | the engine's check: the actor in the route's lane, its s within the route's interval |
//! | `yaw(ψ)`, `orientation(yaw: ψ)` relative to the road | the engine's check of the actor's heading minus the road's where it is: at the start (at: start, all) and the end (at: end, all) (`runtime_kept`) |
//! | `keep_position()` | the engine's check that the actor stands at the start (`runtime_kept`) |
//! | `lateral(d, measure_by, side, at: end)` without a lane change, over a phase of duration T | the engine's sinusoidal offset change over T in the actor's own lane to k·W + c, W the lane's width where the actor is at each step (at the end: where it ends the phase) |
//! | `lateral(d, side_of/left_of/right_of: x, at: end)` over a phase of duration T | projected: the engine's sinusoidal LaneChangeAction over T to the lane holding x's t at the start plus the t asked; actual: the engine's sinusoidal blend to x's t at every step plus it; beside a lane change the change's lane is the engine's check at the end (`lateral_end`) |
//! | `acceleration(a, faster_than/slower_than/same_as: x)` alone, at: all, start or end | the engine's RelativeAccelerationAction: x's acceleration ± a in every step (at: all, end), or x's over the first step held (at: start) (`acceleration_follow`) |
//! | `change_speed(v)` at the rate of such an `acceleration(…)`, at: start, all or end | the engine's RelativeAccelerationAction toward v at that rate (at: end read in every step, as at: all: x's acceleration at the phase end is not there to read when the change starts), failing when v is not reached within the phase (`acceleration_follow`) |
//! | `acceleration(a)` alone (no speed target beside it) over a phase of duration T | the engine's AccelerationAction holding a from the speed the actor has at the start until the phase ends, beside the engine's check that v₀ + a·T is within 0 and the vehicle's maximum speed then |
//! | `speed(v, at: end)`, `change_speed(v)` (or to another actor's speed) over a phase of duration T, `change_speed(v, duration)` | the engine's SpeedAction over T from the speed the actor has, beside the engine's check that its peak rate fits the vehicle's limit then (a failure: an error record and a failed run, not a stretched change) |
//! | `change_speed(v)`, `speed(v, at: end)` beside `acceleration(a)` over a phase of duration T | the engine's SpeedAction at the rate a, beside the engine's check that \|v − v₀\|/a ≤ T from the speed v₀ the actor has then (`speed_at_rate_check`) |
//! | `speed(same_as/faster_than/slower_than: x, at: end)` beside `acceleration(a)` over a phase of duration T | the engine's SpeedAction at the rate a to x's speed (actual: read each step, followed after the change, checked at the end; projected: x's at the start), beside the engine's check that \|v_x ± δ − v₀\|/a ≤ T from both speeds then (`runtime_rate`); at the rate of another actor's acceleration, the engine's RelativeAccelerationAction toward x's speed, followed once reached (`runtime_rate`) |
//! | `change_speed(v)`, `speed(v, at: end)` beside `distance(d)` without a duration | the engine's SpeedAction at the rate of `acceleration(a)` beside it, else `change_speed`'s default, beside the engine's check that \|v² − v₀²\|/(2a) ≤ d from the speed v₀ the actor has then (`speed_at_rate_check`); the phase ends at d travelled since the start's mark (`runtime_end`); relative to another actor x, to x's speed read at each step and followed after the change, checked at the end (projected: x's speed at the start) (`relative_over_distance`) |
//! | `change_speed(v)`, `speed(v, at: end)` at the rate of `acceleration(a, faster_than/slower_than/same_as: x)` beside `distance(d)` without a duration | the engine's RelativeAccelerationAction toward v with no time of its own, and its check at the phase end (d travelled) that the actor is at v (`runtime_end`) |
//! | `change_acceleration(target)` at a rate | the engine's AccelerationAction ending at its target, then one holding it (`speed_actions`) |
//! | `keep_space_gap` / `keep_time_headway` without a known gap | the engine's LongitudinalDistanceAction keeping the value it measures at its start (`gap_actions`) |
//!
//! On a plan over several roads (`crate::road`) the checks, marks and TravelAction name the
//! plan's roads with the plan's s at each start (`Planner::chain`: `StateCheck::roads`,
//! `Travel::roads`): the engine takes the lane on whichever of them the actor is on (their
//! lane ids are the same), measures s and gaps in the plan's s, and a TravelAction's Δs along
//! the actor's lane across the roads' joints. For an actor driving against s (`crate::road`'s
//! view) they carry that direction too (`PlanRoads::against`): the engine measures in the
//! view's u = L − s, t and offsets to the actor's left, so what the plan writes for it is
//! what the engine checks.
//!
//! Lanes are numbered where the plan last knows the actor (a road whose lanes change between
//! there and the run-time start may number them otherwise); a lane's width, where the
//! offset depends on it, is the engine's where it finds the actor. A gap that
//! depends on another actor's speed (`position(time: t, …)`, or the default gap) is measured
//! at that actor's speed when the engine checks it (`scenario::SpeedGap`).

use scenario::{
    DynamicsShape, LaneChangeTarget, LateralAction, LongitudinalAction, OffsetInWidth, PlanRoads,
    PrivateAction, RateWithin, SpeedTarget, StateCheck, Travel, TravelGoal,
};

use super::action_args::timed;
use super::lateral;
use super::motion::{acceleration, check_speed, end_speed_mod, holds_speed};
use super::planner::Planner;
use super::route::StartOnRoute;
use super::types::{
    Planned, When, LATERAL_TOLERANCE, MAX_ACCELERATION, MAX_SPEED, POSITION_TOLERANCE,
    SPEED_TOLERANCE,
};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Arg, At, ModKind, Modifier, Val};

impl Planner<'_> {
    /// The engine's check of `m` (a `lane`, `position` or `lateral` constraint at the start of
    /// a phase of `target` that starts on a run-time condition), as the action `name`.
    pub(super) fn start_check(
        &self,
        m: &Modifier,
        target: &str,
        name: String,
    ) -> Result<Planned, Error> {
        let mut check = self.start_state(m, target)?;
        // A relation to another actor at: all "holds throughout the phase" (§8.9.1.1.1):
        // the engine checks it at every step until the phase's Act ends (`held_relation`),
        // with track: projected against x as projected from the phase start (§8.9.1.1.3).
        check.throughout = m.at == At::All && relates(&check);
        check.projected = check.throughout && m.projected;
        Ok(self.checked(check, m, target, name))
    }

    /// What the engine's check of `m` (as [`Self::start_check`]) requires of `target`.
    pub(super) fn start_state(&self, m: &Modifier, target: &str) -> Result<StateCheck, Error> {
        let t = self.last_known();
        let what = format!("{}(…) at {}", m.name, m.site.at());
        let mut check = StateCheck {
            what,
            roads: self.chain(),
            ..StateCheck::default()
        };
        match m.kind {
            ModKind::Lane => {
                let n = m
                    .arg("lane")
                    .map(Arg::number)
                    .transpose()?
                    .map_or(1, |x| x.round() as i64);
                let left = !matches!(m.arg("side").map(Arg::eval).transpose()?, Some(Val::Enum(s)) if s == "right");
                let shift = i32::try_from(n).unwrap_or(i32::MAX);
                for (key, shift) in [
                    ("same_as", 0),
                    ("left_of", shift),
                    ("right_of", -shift),
                    ("side_of", if left { shift } else { -shift }),
                ] {
                    if let Some(e) = m.arg(key) {
                        check.lane_of = Some((self.entity_of(e)?, shift));
                        return Ok(check);
                    }
                }
                let from_left = matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
                let lane = self
                    .road
                    .numbered(n, from_left, self.s_at(target, t), self.walks(target))
                    .ok_or_else(|| {
                        m.site.err(
                            K::Unsatisfiable,
                            format!("expected a driving lane {n} on road {}, found none", self.road.id()),
                        )
                    })?;
                check.lane = Some((self.road.id().to_string(), lane));
            }
            ModKind::Position => match self.speed_gap(m, target)? {
                Some(gap) => check.gap = Some((gap, POSITION_TOLERANCE)),
                None => check.s = Some((self.position_target(m, target, t)?.2, POSITION_TOLERANCE)),
            },
            ModKind::Lateral => {
                // A block's member: its slot as the plan last knows the block (`beside_slot`).
                if let Some((x, dt)) = self.beside_slot(m, target, t)? {
                    check.beside = Some((x, dt, LATERAL_TOLERANCE));
                    return Ok(check);
                }
                // The offset is k·W + c in the lane's width W, which the engine takes where
                // the actor is then (the plan's width, where it last knows the actor, checks
                // the arguments).
                let s = self.s_at(target, t);
                let w = self.road.lane_width(self.lane_now(target, t), s);
                let (k, c) = lateral::offset_in_width(m, w, self.width(target))?;
                check.offset_in_width = Some((k, c, LATERAL_TOLERANCE));
            }
            // The callers pass only these three kinds (invoke's `lane`/`position`/`lateral`
            // at a run-time start, `lane_kept_to_end`'s `lane(…)`): no modifier reaches this
            // (every other one at a run-time start is the table's, a check of its own, or
            // holds by the plan's construction: docs/dsl.md, the run-time table).
            _ => {
                return Err(m.site.err(
                    K::Modifier,
                    format!("expected lane, position or lateral for the engine's check of a place at the start of a phase that starts on a run-time condition, found {}(…)", m.name),
                ))
            }
        }
        Ok(check)
    }

    /// The check `check` of `m` as the action `name` of `target`.
    pub(super) fn checked(
        &self,
        check: StateCheck,
        m: &Modifier,
        target: &str,
        name: String,
    ) -> Planned {
        Planned::with_phase(target, name, PrivateAction::Check(Box::new(check)), &m.site)
    }

    /// The reference x of a `lateral(…)` beside another actor and the actor's t minus x's
    /// it asks for (`lateral::beside` with x's centre at 0), if it has one.
    pub(super) fn beside_gap(
        &self,
        m: &Modifier,
        target: &str,
    ) -> Result<Option<(String, f64)>, Error> {
        let Some((e, sigma)) = lateral::reference(m)? else {
            return Ok(None);
        };
        let x = self.entity_of(e)?;
        let dt = lateral::beside(m, sigma, (0.0, self.width(&x)), self.width(target))?;
        Ok(Some((x, dt)))
    }

    /// The engine's TravelAction for `m` (a `position(…, at: end)` or `distance(…)` of
    /// `target`) over a phase of `len` s that starts on a run-time condition, as the action
    /// `name`: the two-halves profile from the state at the start, worked out by the engine
    /// then. It replaces the speed change the phase planned already (its end speed is the
    /// profile's).
    ///
    /// Beside `speed(v)` at: all the speed holds and no profile runs: the engine checks the
    /// place (or the distance travelled since the start) at the phase end (`runtime_end`). An
    /// end speed relative to another actor x is x's speed at the start (± the value), as the
    /// goal takes x's motion, and the engine checks x's speed at the phase end.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn start_travel(
        &mut self,
        m: &Modifier,
        target: &str,
        mods: &[Modifier],
        len: f64,
        name: String,
        out: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let (ve_given, hold) = (end_speed_mod(mods), holds_speed(mods));
        let goal = if m.kind == ModKind::Distance {
            match m.arg("distance").map(Arg::number).transpose()? {
                Some(d) if d >= 0.0 => TravelGoal::Distance(d),
                _ => {
                    return Err(m.site.err(
                        K::Value,
                        "expected a distance of 0 m or more in distance(…), found none",
                    ))
                }
            }
        } else {
            match self.speed_gap(m, target)? {
                Some(gap) => TravelGoal::FromEntity(gap),
                None => TravelGoal::RoadS(self.position_target(m, target, self.last_known())?.2),
            }
        };
        if hold && ve_given.is_none() {
            // The speed holds: what the constraint asks is the engine's check at the end.
            let mut check = StateCheck::default();
            match goal {
                TravelGoal::Distance(d) => {
                    out.push(self.mark_check(m, target, name.clone(), None));
                    check.travelled = Some((name.clone(), d, POSITION_TOLERANCE));
                }
                TravelGoal::RoadS(s) => check.s = Some((s, POSITION_TOLERANCE)),
                TravelGoal::FromEntity(gap) => check.gap = Some((gap, POSITION_TOLERANCE)),
                _ => {}
            }
            after.push(self.end_check(m, target, format!("{name}.end"), check));
            return Ok(());
        }
        let (end_speed, end_speed_of) = match ve_given {
            Some(q) => match self.speed_value(q, None)? {
                (_, Some((x, delta))) => {
                    // x's speed at the start; checked at the end unless projected (x as it
                    // is at the start is what projected asks for).
                    if !q.projected {
                        let check = StateCheck {
                            speed: Some((Some(x.clone()), delta, SPEED_TOLERANCE)),
                            ..StateCheck::default()
                        };
                        after.push(self.end_check(q, target, format!("{name}.speed"), check));
                    }
                    (None, Some((x, delta)))
                }
                (v, None) => {
                    check_speed(q, v)?;
                    self.last_v.insert(target.to_string(), v);
                    (Some(v), None)
                }
            },
            None => (None, None),
        };
        // Drop the speed ramp this phase planned already (change_speed, speed(…, at: end)).
        out.retain(|a| !(a.entity == target && a.name.ends_with(":speed")));
        out.push(Planned {
            entity: target.to_string(),
            at: None,
            name,
            action: PrivateAction::Longitudinal(LongitudinalAction::Travel(Box::new(Travel {
                what: format!("{}(…) at {}", m.name, m.site.at()),
                goal,
                duration: len,
                end_speed,
                end_speed_of,
                monotonous: m.monotonous,
                limits: (MAX_SPEED, MAX_ACCELERATION),
                roads: self.chain(),
            }))),
            site: m.site.clone(),
        });
        Ok(())
    }

    /// The engine's `acceleration(a)` (alone, no speed target beside it) for `target` over a
    /// phase of `len` s that starts on a run-time condition, as the actions `name("check")`
    /// and `name("acceleration")`: the engine's check that v₀ + a·T stays within 0 and the
    /// vehicle's maximum speed from the speed v₀ the actor has then (beyond, the
    /// AccelerationAction would end with the vehicle standing or at its top speed before the
    /// phase ends, its acceleration no longer a: an error record and a failed run, as the
    /// plan's error at a known start), and a step AccelerationAction to `a`, so the actor
    /// accelerates at exactly a from that speed until the phase's Act stops (at a known start
    /// the plan's linear SpeedAction to v₀ + a·T, whose v₀ is the plan's: after a gap action
    /// or a `change_acceleration` the speed the plan last knows is not the actor's). The plan
    /// records v₀ + a·T from the speed it last knows, within 0 and the maximum.
    pub(super) fn start_acceleration(
        &mut self,
        m: &Modifier,
        target: &str,
        (a, len): (f64, f64),
        name: &mut dyn FnMut(&str) -> String,
    ) -> [Planned; 2] {
        let v1 = (self.last_v[target] + a * len).clamp(0.0, MAX_SPEED);
        self.last_v.insert(target.to_string(), v1);
        let check = StateCheck {
            held_acceleration: Some((a, len)),
            ..StateCheck::default()
        };
        [
            phase_start_check(target, (&m.name, &m.site), check, name("check")),
            Planned::with_phase(
                target,
                name("acceleration"),
                acceleration(Some(a), timed(DynamicsShape::Step, 0.0)),
                &m.site,
            ),
        ]
    }

    /// The engine's change of `target`'s offset in its lane to the one `m` (a `lateral(…, at:
    /// end)` without a lane change) asks for, over a phase of `len` s that starts on a run-time
    /// condition, as the action `name`: oscsim's sinusoidal offset change over `len` within the
    /// actor's own lane (`LateralAction::OffsetInWidth`, no XML form), from the offset the
    /// actor has then (a LaneOffsetAction gives no duration, only a peak lateral acceleration,
    /// which depends on that offset) to k·W + c, W the lane's width where the actor is at each
    /// step, so at the end the width where it ends the phase (§8.9 `at: end`; from a border
    /// the offset depends on it, from the centre k = 0). Beside a lane change of the phase
    /// (`lane`, numbered `planned` where the plan last knows the actor) the same into its
    /// target lane, in that lane's width. The plan's width where it last knows the actor checks
    /// the arguments (the reference point in the lane).
    pub(super) fn start_offset_change(
        &self,
        m: &Modifier,
        target: &str,
        (lane, planned, len): (Option<LaneChangeTarget>, Option<i32>, f64),
        name: String,
    ) -> Result<Planned, Error> {
        let t = self.last_known();
        let w = self.road.lane_width(
            planned.unwrap_or_else(|| self.lane_now(target, t)),
            self.s_at(target, t),
        );
        let (per_width, offset) = lateral::offset_in_width(m, w, self.width(target))?;
        let change = LateralAction::OffsetInWidth(Box::new(OffsetInWidth {
            lane,
            per_width,
            offset,
            shape: DynamicsShape::Sinusoidal,
            duration: len,
        }));
        Ok(Planned::with_phase(
            target,
            name,
            PrivateAction::Lateral(change),
            &m.site,
        ))
    }

    /// The engine's check that `target` is on a named route (`along(…)` at `site`) at the
    /// start of a phase that starts on a run-time condition, as the action `name`: in the
    /// route's lane, its s within the route's interval (checked as s at the interval's middle
    /// within half its length).
    pub(super) fn route_check(
        &self,
        site: &Site,
        target: &str,
        start: StartOnRoute,
        name: String,
    ) -> Result<Planned, Error> {
        let (lo, hi) = start.s;
        let check = StateCheck {
            lane: Some((self.road.id().to_string(), start.lane)),
            s: Some(((lo + hi) / 2.0, (hi - lo) / 2.0)),
            roads: self.chain(),
            ..StateCheck::default()
        };
        Ok(phase_start_check(target, ("along", site), check, name))
    }

    /// The plan's roads with the plan's s at each start, for the engine's checks, marks and
    /// TravelAction on a plan over several roads (their lane ids are the same, so the engine
    /// takes the lane on whichever of them the actor is on and measures in the plan's s);
    /// none on one road (the engine measures on the road the actor is on). On the view of an
    /// actor driving against s (`PlanRoad::against`) the same roads driven so: the engine
    /// measures in the view's u = L − s and t to the left of the direction of travel, the
    /// numbers the plan writes (`position::RoadChain` there).
    pub(super) fn chain(&self) -> PlanRoads {
        PlanRoads {
            chain: match self.road.ids().len() {
                1 => Vec::new(),
                _ => self.road.starts(),
            },
            against: self.road.is_against(),
        }
    }

    /// The latest moment the plan knows (s): the latest known start or end of a phase
    /// planned so far.
    pub(super) fn last_known(&self) -> f64 {
        self.phases
            .iter()
            .flat_map(|p| [&p.start, &p.end])
            .filter_map(When::time)
            .fold(0.0, f64::max)
    }
}

/// The engine's check that a speed change to `to` of `shape` over `len` s, starting in a
/// phase of `target` that starts on a run-time condition, fits the vehicle's acceleration
/// limit from the speed the actor has then, as the action `name` (`what` names the
/// modifier or action and `site` where it is written): the engine's SpeedAction would
/// stretch a faster change in time; here it is an error record and a failed run instead.
pub(super) fn speed_change_check(
    target: &str,
    (what, site): (&str, &Site),
    (to, shape, len): (SpeedTarget, DynamicsShape, f64),
    name: String,
) -> Planned {
    let check = StateCheck {
        speed_change: Some((to, shape, len)),
        ..StateCheck::default()
    };
    phase_start_check(target, (what, site), check, name)
}

/// The engine's check that a speed change to `to` at the rate `a` (m/s²), starting in a phase
/// of `target` that starts on a run-time condition, ends within the phase (its length, or
/// the distance that ends it) from the speed the actor has then, as the action `name`
/// (`what` names the modifier and `site` where it is written): the phase's end would cut a
/// longer change short; here it is an error record and a failed run instead.
pub(super) fn speed_at_rate_check(
    target: &str,
    (what, site): (&str, &Site),
    (to, a, len): (SpeedTarget, f64, RateWithin),
    name: String,
) -> Planned {
    let check = StateCheck {
        speed_at_rate: Some((to, a, len)),
        ..StateCheck::default()
    };
    phase_start_check(target, (what, site), check, name)
}

/// `check` as the engine's check at the start of a phase of `target`, named for the modifier
/// or action `what` written at `site`.
pub(super) fn phase_start_check(
    target: &str,
    (what, site): (&str, &Site),
    check: StateCheck,
    name: String,
) -> Planned {
    let check = StateCheck {
        what: format!("{what}(…) at {}", site.at()),
        ..check
    };
    Planned::with_phase(target, name, PrivateAction::Check(Box::new(check)), site)
}

/// Whether `check` relates its actor to another one: a lane counted from another actor's
/// (`lane_of`), a place along the road from it (`gap`) or a t beside it (`beside`).
pub(super) fn relates(check: &StateCheck) -> bool {
    check.lane_of.is_some() || check.gap.is_some() || check.beside.is_some()
}
