//! Motion helpers of the planner: speed profiles (two linear halves), the values of speed,
//! acceleration and position modifiers, lane change targets, and the limits they are checked
//! against (ASAM OpenSCENARIO DSL 2.1 §8.9).

use scenario::{
    ConditionGroup, DynamicsDimension, DynamicsShape, LaneChangeTarget, LongitudinalAction,
    PrivateAction, SpeedTarget, TransitionDynamics, Trigger,
};

use super::planner::Planner;
use super::types::{Planned, When, MAX_ACCELERATION, MAX_SPEED, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Arg, At, ModKind, Modifier, Val};

impl Planner<'_> {
    /// The speed at the end `te` of a phase that starts at `t` an end-speed modifier asks for
    /// (a reference's speed then, or with `track: projected` at `t`), else `v0`.
    pub(super) fn end_speed(
        &self,
        q: Option<&Modifier>,
        (t, te): (f64, f64),
        v0: f64,
    ) -> Result<f64, Error> {
        Ok(match q {
            Some(q) => {
                self.speed_value(q, Some(if q.projected { t } else { te }))?
                    .0
            }
            None => v0,
        })
    }

    /// s of the reference `x` of `m` at the end `te` of a phase that starts at `t`: where its
    /// planned track has it, or with `track: projected` (§8.9.1.1.3) where it gets from its
    /// place at `t` keeping the speed it has then, along its lane.
    pub(super) fn reference_s(&self, m: &Modifier, x: &str, (t, te): (f64, f64)) -> f64 {
        if !m.projected {
            return self.s_at(x, te);
        }
        let v = self.track(x).at(t).1;
        self.road
            .s_after(self.lane_now(x, t), self.s_at(x, t), v * (te - t))
    }

    /// Plans a speed profile of two halves over [t, t + len] that covers `ds` (m along the
    /// lane) from speed `v0` to `ve`: v0 → vm over len/2 and vm → ve over len/2, with vm =
    /// (4·ds/len − v0 − ve)/2, each half `shape` (linear, or the engine's sinusoidal change,
    /// whose mean speed is the same, so the same vm covers ds), within the limits (and
    /// monotonous when `m` asks). It replaces a speed change the phase planned already.
    pub(super) fn two_halves(
        &mut self,
        m: &Modifier,
        target: &str,
        (t, len, shape): (f64, f64, DynamicsShape),
        (v0, ds, ve): (f64, f64, f64),
        names: (String, String),
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        self.last_v.insert(target.to_string(), ve);
        let vm = (4.0 * ds / len - v0 - ve) / 2.0;
        // movement_mode: monotonous: the speed only rises or only falls.
        if m.monotonous && (vm - v0) * (ve - vm) < -1e-9 {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected a monotonous speed profile (movement_mode: monotonous) from {v0:.2} m/s to {ve:.2} m/s, found it needs {vm:.2} m/s half way"),
            ));
        }
        // A half's peak acceleration: its mean, π/2 times that for the sinusoid.
        let peak = if shape == DynamicsShape::Sinusoidal {
            std::f64::consts::FRAC_PI_2
        } else {
            1.0
        };
        check_speed(m, vm)?;
        check_accel(m, peak * (vm - v0) / (len / 2.0))?;
        check_accel(m, peak * (ve - vm) / (len / 2.0))?;
        // Drop a speed ramp this phase planned already (change_speed).
        out.retain(|a| !(a.entity == target && a.name.ends_with(":speed")));
        out.push(Planned {
            entity: target.to_string(),
            at: None,
            name: names.0,
            action: speed_action(shape, len / 2.0, SpeedTarget::Absolute(vm)),
            site: m.site.clone(),
        });
        out.push(Planned {
            entity: target.to_string(),
            at: Some(When::At(t + len / 2.0)),
            name: names.1,
            action: speed_action(shape, len / 2.0, SpeedTarget::Absolute(ve)),
            site: m.site.clone(),
        });
        let tr = self.track_mut(target);
        if shape == DynamicsShape::Sinusoidal {
            tr.sine(t, t + len / 2.0, vm);
            tr.sine(t + len / 2.0, t + len, ve);
        } else {
            tr.ramp(t, t + len / 2.0, vm);
            tr.ramp(t + len / 2.0, t + len, ve);
        }
        Ok(())
    }

    /// The moment the gap of a `position(d, ahead_of|behind: x)` is reached, as the engine
    /// measures it: a RelativeDistanceCondition (longitudinal, road coordinates, reference
    /// points) of the actor in front over the one behind rising through d. Without a reference: s ≥ d is
    /// not measured by a 1.x condition, so it is an error.
    pub(super) fn gap_reached(
        &self,
        m: &Modifier,
        target: &str,
        x: Option<&str>,
        sign: f64,
        d: f64,
    ) -> Result<When, Error> {
        let Some(x) = x else {
            return Err(m.site.err(
                K::Unsatisfiable,
                "expected a duration for position(d, at: end) without a reference, found none",
            ));
        };
        let (front, back) = if sign > 0.0 { (target, x) } else { (x, target) };
        Ok(When::Dyn(Trigger {
            condition_groups: vec![ConditionGroup {
                conditions: vec![scenario::Condition {
                    name: format!("{front} {d} m ahead of {back}"),
                    // The engine's longitudinal distance has no sign: the gap is reached when
                    // it grows through d (an actor behind first closes, passes, then opens it).
                    condition_edge: scenario::ConditionEdge::Rising,
                    delay: 0.0,
                    kind: scenario::ConditionKind::by_entity(
                        front,
                        scenario::EntityCondition::RelativeDistance {
                            entity_ref: back.to_string(),
                            value: d,
                            rule: scenario::Rule::GreaterOrEqual,
                            measure: scenario::DistanceMeasure {
                                freespace: false,
                                coordinate_system: Some(scenario::CoordinateSystem::Road),
                                relative_distance_type: Some(
                                    scenario::RelativeDistanceType::Longitudinal,
                                ),
                                routing_algorithm: None,
                            },
                        },
                    ),
                    pos: m.site.pos.clone(),
                }],
            }],
        }))
    }

    /// The speed a speed-like modifier asks for at time `t`, and its relative form.
    pub(super) fn speed_value(
        &self,
        m: &Modifier,
        t: Option<f64>,
    ) -> Result<(f64, Option<(String, f64)>), Error> {
        let own = m.arg("speed").map(Arg::number).transpose()?;
        for (key, sign) in [
            ("faster_than", 1.0),
            ("slower_than", -1.0),
            ("same_as", 0.0),
        ] {
            if let Some(e) = m.arg(key) {
                let x = self.entity_of(e)?;
                let delta = sign * own.unwrap_or(0.0);
                let vx = t.map_or(0.0, |t| self.track(&x).at(t).1);
                return Ok((vx + delta, Some((x, delta))));
            }
        }
        match own {
            Some(v) => Ok((v, None)),
            None => Err(m.site.err(
                K::Modifier,
                "expected a speed (or faster_than/slower_than/same_as) in this modifier, found none",
            )),
        }
    }

    /// The acceleration of an `acceleration(…)` modifier over the phase `(t0, len)` (m/s²):
    /// `a` itself, or relative to x's acceleration as x's planned track has it (§8.9: the
    /// actor's acceleration relative to x's): `faster_than: x` x's + a, `slower_than: x`
    /// x's − a, `same_as: x` x's. x's is its value as the phase starts (`at: start`), as it
    /// ends (`at: end`), or the one it keeps over the whole phase (`at: all`, the default;
    /// where x's changes within the phase it is the engine's to follow alone,
    /// `followed_acceleration`, and as the rate of a speed change an error). With `track:
    /// projected` x's as the phase starts, in every `at` (§8.9.1.1.3: x projected from its
    /// state at the start, so its acceleration then, fixed). After a run-time start the engine
    /// reads it in every form (`acceleration_follow`).
    pub(super) fn acceleration_value(
        &self,
        m: &Modifier,
        (t0, len): (Option<f64>, f64),
    ) -> Result<f64, Error> {
        let own = m.arg("acceleration").map(Arg::number).transpose()?;
        let relative = [
            ("faster_than", 1.0),
            ("slower_than", -1.0),
            ("same_as", 0.0),
        ]
        .into_iter()
        .find_map(|(key, sign)| m.arg(key).map(|e| (e, sign)));
        let Some((e, sign)) = relative else {
            return own.ok_or_else(|| {
                m.site.err(
                    K::Modifier,
                    "expected an acceleration (or faster_than/slower_than/same_as) in acceleration(…), found none",
                )
            });
        };
        let x = self.entity_of(e)?;
        // After a run-time start the engine reads x's acceleration (`acceleration_follow`,
        // which takes every reading of it before this one).
        let Some(t) = t0 else {
            return Err(e.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows to read `{x}`'s planned acceleration, found one after a run-time condition"),
            ));
        };
        let pieces = self.track(&x).acceleration_pieces(t, t + len).map_err(|at| {
            e.site.err(
                K::Unsatisfiable,
                format!("expected `{x}`'s planned acceleration constant over each part of the phase, found it changing continuously (or a step of speed) from {at:.2} s"),
            )
        })?;
        let (first, last) = match (pieces.first(), pieces.last()) {
            (Some(f), Some(l)) => (f.2, l.2),
            _ => (0.0, 0.0),
        };
        // Projected (§8.9.1.1.3): x as it is at the phase start, its acceleration then fixed
        // over the phase whatever x does in it (as `speed(…, track: projected)` reads x's
        // speed at the start).
        let ax = match m.at {
            _ if m.projected => first,
            At::Start => first,
            At::End => last,
            At::All => {
                if let Some(p) = pieces.iter().find(|p| (p.2 - first).abs() > 1e-9) {
                    return Err(e.site.err(
                        K::Unsatisfiable,
                        format!("expected `{x}`'s planned acceleration constant over the phase for acceleration(…) at: all, found it changing from {first:.2} m/s² to {:.2} m/s² at {:.2} s (give at: start or at: end)", p.2, p.0),
                    ));
                }
                first
            }
        };
        Ok(ax + sign * own.unwrap_or(0.0))
    }

    pub(super) fn entity_of(&self, e: &Arg) -> Result<String, Error> {
        e.path
            .clone()
            .filter(|p| self.index.contains_key(p))
            .ok_or_else(|| {
                e.site.err(
                    K::UnknownActor,
                    "expected a vehicle of the scenario, found another value",
                )
            })
    }

    /// (reference entity, +1 ahead / −1 behind, distance) of a position modifier.
    pub(super) fn position_target(
        &self,
        m: &Modifier,
        target: &str,
        t: f64,
    ) -> Result<(Option<String>, f64, f64), Error> {
        let (x, sign) = match (m.arg("ahead_of"), m.arg("behind")) {
            (Some(e), _) => (Some(self.entity_of(e)?), 1.0),
            (None, Some(e)) => (Some(self.entity_of(e)?), -1.0),
            (None, None) => (None, 1.0),
        };
        let d =
            match (m.arg("distance"), m.arg("time"), &x) {
                (Some(e), _, _) => e.number()?,
                (None, Some(e), Some(x)) => e.number()? * self.track(x).at(t).1,
                // Ahead of x (sign +1): x is behind the actor.
                (None, None, Some(x)) => super::place::default_distance(
                    self.track(x).at(t).1,
                    self.facing_overhangs(target, x, sign < 0.0),
                ),
                _ => return Err(m.site.err(
                    K::Unsatisfiable,
                    "expected a distance (or a time and a reference) in position(…), found neither",
                )),
            };
        Ok((x, sign, d))
    }

    /// Checks a constraint at the start of a phase that is not the actor's first.
    pub(super) fn check_start(&self, m: &Modifier, target: &str, t: f64) -> Result<(), Error> {
        if m.kind == ModKind::Position {
            let (x, sign, d) = self.position_target(m, target, t)?;
            let want = x.as_ref().map_or(0.0, |x| self.s_at(x, t)) + sign * d;
            let got = self.s_at(target, t);
            if (got - want).abs() > POSITION_TOLERANCE {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!("expected this position at the phase start, found `{target}` {:.2} m from it (plan an earlier phase to reach it)", got - want),
                ));
            }
        }
        if m.kind == ModKind::Lane {
            let got = self.lane_now(target, t);
            let want = self.lane_asked(m, target, t)?;
            if want != Some(got) {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected `{target}` in {} at the phase start, found it in lane {got} (plan the change in an earlier phase, with lane(…, at: end) or change_lane)",
                        want.map_or("a driving lane that does not exist".to_string(), |l| format!("lane {l}"))
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The lane a `lane(…)` modifier of `target` asks for at time `t` (`None`: no such
    /// driving lane).
    pub(super) fn lane_asked(
        &self,
        m: &Modifier,
        target: &str,
        t: f64,
    ) -> Result<Option<i32>, Error> {
        let n = m
            .arg("lane")
            .map(Arg::number)
            .transpose()?
            .map_or(1, |x| x.round() as i64);
        for (key, left) in [
            ("same_as", None),
            ("left_of", Some(true)),
            ("right_of", Some(false)),
            (
                "side_of",
                Some(
                    !matches!(m.arg("side").map(Arg::eval).transpose()?, Some(Val::Enum(s)) if s == "right"),
                ),
            ),
        ] {
            if let Some(e) = m.arg(key) {
                let x = self.entity_of(e)?;
                let lx = self.lane_now(&x, t);
                return Ok(match left {
                    None => Some(lx),
                    Some(left) => self.road.beside(lx, left, n, self.s_at(&x, t)),
                });
            }
        }
        let from_left =
            matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
        Ok(self
            .road
            .numbered(n, from_left, self.s_at(target, t), self.walks(target)))
    }

    /// The LaneChangeAction target of a lane modifier at the phase end, and the lane the plan
    /// expects there. `t` is the phase's start, `None` after a run-time condition: a lane
    /// relative to another actor is then the engine's to find (the plan expects none), and
    /// lanes are numbered where the plan last knows the actor.
    pub(super) fn lane_target(
        &self,
        m: &Modifier,
        target: &str,
        t0: Option<f64>,
        len: f64,
    ) -> Result<(LaneChangeTarget, Option<i32>), Error> {
        let t = t0.unwrap_or_else(|| self.last_known());
        let n = m
            .arg("lane")
            .map(Arg::number)
            .transpose()?
            .map_or(1, |x| x.round() as i32);
        let side = m.arg("side").map(Arg::eval).transpose()?;
        let left = !matches!(&side, Some(Val::Enum(s)) if s == "right");
        let shift = if left { n } else { -n };
        if m.kind == ModKind::ChangeLane {
            let now = self.lane_now(target, t);
            let s_now = self.s_at(target, t);
            let exists = |left: bool| self.road.beside(now, left, n.into(), s_now).is_some();
            // change_lane without a side: "the side is randomized" (§8.9 change_lane), drawn
            // once per modifier from the run's seed among the sides that have the lane.
            let left = match side {
                Some(_) => left,
                None => *self
                    .sides
                    .borrow_mut()
                    .entry(format!("{:?}", m.site.span))
                    .or_insert_with(|| match (exists(true), exists(false)) {
                        (true, true) => self.choose(2) == 0,
                        (l, _) => l,
                    }),
            };
            let shift = if left { n } else { -n };
            if !exists(left) {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected a driving lane {n} to the {} of `{target}`'s lane {now} at s = {s_now:.2} m, found none",
                        if left { "left" } else { "right" }
                    ),
                ));
            }
            // Counted where the change starts; at a start the plan knows, the id that lane
            // has where the change ends (a lane section between may renumber it: OpenDRIVE
            // 1.8 §11.5 lane linkage, which the engine follows).
            let lane = self
                .road
                .beside(now, left, n.into(), s_now)
                .map(|l| match t0 {
                    Some(t) => self.road.lane_along(l, s_now, self.s_at(target, t + len)),
                    None => l,
                });
            return Ok((
                LaneChangeTarget::Relative {
                    entity_ref: target.to_string(),
                    value: shift,
                },
                lane,
            ));
        }
        for (key, value) in [
            ("same_as", 0),
            ("side_of", shift),
            ("left_of", n),
            ("right_of", -n),
        ] {
            if let Some(e) = m.arg(key) {
                let x = self.entity_of(e)?;
                if t0.is_none() {
                    // x's lane at the start is the engine's: a missing lane is its error then.
                    return Ok((
                        LaneChangeTarget::Relative {
                            entity_ref: x,
                            value,
                        },
                        None,
                    ));
                }
                // Projected (§8.9.1.1.3): x keeps the lane it has at the start.
                let tx = if m.projected { t } else { t + len };
                let lx = self.lane_now(&x, tx);
                let s_end = self.s_at(&x, tx);
                let lane = match value {
                    0 => Some(lx),
                    v => self.road.beside(lx, v > 0, v.abs().into(), s_end),
                };
                if lane.is_none() {
                    return Err(m.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected a driving lane {} to the {} of `{x}`'s lane {lx} at the phase end (s = {s_end:.2} m), found none",
                            value.abs(),
                            if value > 0 { "left" } else { "right" }
                        ),
                    ));
                }
                // The engine reads a RelativeTargetLane at the action's start: where x changes
                // lanes within the phase (track: actual), the lane the plan has at the end is
                // an absolute target (a lane section that renumbers x's lane is no change).
                if let (Some(l), true) = (lane, self.changes_lane(&x, t, tx)) {
                    return Ok((LaneChangeTarget::Absolute(l.to_string()), lane));
                }
                return Ok((
                    LaneChangeTarget::Relative {
                        entity_ref: x,
                        value,
                    },
                    lane,
                ));
            }
        }
        // A lane number (1 = the rightmost driving lane, or the leftmost with from: left) at
        // the phase end: an absolute target lane.
        let from_left =
            matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
        let s_end = self.s_at(target, t + len);
        match self
            .road
            .numbered(n.into(), from_left, s_end, self.walks(target))
        {
            Some(l) => Ok((LaneChangeTarget::Absolute(l.to_string()), Some(l))),
            None => Err(m.site.err(
                K::Unsatisfiable,
                format!(
                    "expected a driving lane numbered {n} from the {} on road {} at s = {s_end:.2} m, found none",
                    if from_left { "left" } else { "right" },
                    self.road.id()
                ),
            )),
        }
    }
}

/// The `speed(…, at: end)` or `change_speed(…)` of an invocation, if any.
pub(super) fn end_speed_mod(mods: &[Modifier]) -> Option<&Modifier> {
    mods.iter()
        .find(|q| (q.kind == ModKind::Speed && q.at == At::End) || q.kind == ModKind::ChangeSpeed)
}

/// Whether an invocation holds its speed throughout (`speed(v)`, at: all).
pub(super) fn holds_speed(mods: &[Modifier]) -> bool {
    mods.iter()
        .any(|q| q.kind == ModKind::Speed && q.at == At::All)
}

/// The lane change of an invocation (`change_lane`, `lane(…, at: end)`), if any.
pub(super) fn lane_change(mods: &[Modifier]) -> Option<&Modifier> {
    mods.iter()
        .find(|m| m.kind == ModKind::ChangeLane || (m.kind == ModKind::Lane && m.at == At::End))
}

/// The `lateral(…, at: end)` of an invocation, if any.
pub(super) fn lateral_end(mods: &[Modifier]) -> Option<&Modifier> {
    mods.iter()
        .find(|m| m.kind == ModKind::Lateral && m.at == At::End)
}

/// The peak lateral acceleration of a sinusoidal move of `delta` m over `span` s:
/// π²·|Δ|/(2T²) (the engine times its sinusoidal lane and offset changes by it).
pub(super) fn sinusoid_peak_acceleration(delta: f64, span: f64) -> f64 {
    std::f64::consts::PI * std::f64::consts::PI * delta.abs() / (2.0 * span * span)
}

/// A sinusoidal transition over `len` s (a lane or offset change that lasts the phase).
pub(super) fn sinusoidal_over(len: f64) -> TransitionDynamics {
    TransitionDynamics {
        dynamics_shape: DynamicsShape::Sinusoidal,
        dynamics_dimension: DynamicsDimension::Time,
        value: len,
        following_mode: None,
    }
}

pub(super) fn speed_action(shape: DynamicsShape, time: f64, target: SpeedTarget) -> PrivateAction {
    PrivateAction::Longitudinal(LongitudinalAction::Speed {
        dynamics: TransitionDynamics {
            dynamics_shape: shape,
            dynamics_dimension: DynamicsDimension::Time,
            value: time,
            following_mode: None,
        },
        target,
    })
}

/// An AccelerationAction that holds its target.
pub(super) fn acceleration(target: Option<f64>, dynamics: TransitionDynamics) -> PrivateAction {
    PrivateAction::Longitudinal(LongitudinalAction::Acceleration {
        target,
        dynamics,
        ends_at_target: false,
    })
}

pub(super) fn check_speed(m: &Modifier, v: f64) -> Result<(), Error> {
    if !(0.0..=MAX_SPEED).contains(&v) {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a plan within 0 to {MAX_SPEED} m/s, found it needs {v:.2} m/s"),
        ));
    }
    Ok(())
}

pub(super) fn check_accel(m: &Modifier, a: f64) -> Result<(), Error> {
    if a.abs() > MAX_ACCELERATION + 1e-9 {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a plan within ±{MAX_ACCELERATION} m/s², found it needs {a:.2} m/s²"),
        ));
    }
    Ok(())
}
