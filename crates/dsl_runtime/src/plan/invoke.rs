//! Planning one invocation (ASAM OpenSCENARIO DSL 2.1 §8.9 movement modifiers): the actions
//! its modifiers lower to, checked against the vehicles' limits, and the end a
//! `position(…, at: end)` or `distance(…)` gives a phase without a duration.

use std::f64::consts::PI;

use scenario::{
    DynamicsDimension, DynamicsShape, LateralAction, LongitudinalAction, PrivateAction, RateWithin,
    SpeedTarget, SpeedTargetValueType, TransitionDynamics,
};

use super::checks::{check_keeps, check_orientation};
use super::group_path::along_points;
use super::lateral;
use super::motion::{
    check_accel, check_speed, end_speed_mod, holds_speed, lane_change, lateral_end,
    sinusoidal_over, speed_action,
};
use super::planner::Planner;
use super::route::{self, OnRoute};
use super::runtime::{speed_at_rate_check, speed_change_check};
use super::runtime_kept::standing_check;
use super::speed_actions::{check_speed_modifiers, Slot};
use super::types::{Planned, When, LATERAL_TOLERANCE, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Action, Arg, At, Invoke, ModKind, Modifier, Phase, Route};

impl Planner<'_> {
    /// Runs `plan` with `self.road` the view the invocation's actor drives: the plan's roads
    /// against s for an actor driving against s (`crate::road`; what runs so: `against`),
    /// else the plan road as it is.
    pub(super) fn in_actor_view<R>(
        &mut self,
        inv: &Invoke,
        mods: &[Modifier],
        plan: impl FnOnce(&mut Self) -> Result<R, Error>,
    ) -> Result<R, Error> {
        // Random traffic's members drive both ways by the engine's model: no plan of its own.
        if self.random.contains_key(&inv.actor) {
            return plan(self);
        }
        // A group drives its members' direction (one, `against::check_references`).
        let against = match self.groups.get(&inv.actor) {
            Some(members) => members.first().map(String::as_str),
            None => Some(inv.actor.as_str()),
        }
        .and_then(|n| self.index.get(n))
        .is_some_and(|&i| self.entities[i].against);
        super::against::check_alongs(&inv.actor, against, mods, &self.against_routes)?;
        let Some(view) = self.against_road.clone().filter(|_| against) else {
            return plan(self);
        };
        let kept = super::against::turn_stationary(&mut self.entities, view.length());
        let forward = std::mem::replace(&mut self.road, view);
        let planned = plan(self);
        self.road = forward;
        super::against::restore_stationary(&mut self.entities, kept);
        planned
    }

    /// Plans one invocation on the road view in `self.road` (see
    /// [`in_actor_view`](Self::in_actor_view)): its actions, and the time its
    /// `position(…, at: end)` is met when nothing else ends it.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn plan_invoke(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        mods: &[Modifier],
        t0: Option<f64>,
        end: Option<f64>,
        len: Option<f64>,
        out: &mut Vec<Planned>,
        persist: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        // Every action of the standard library is planned; one the program declares is not.
        if inv.kind == Action::Other {
            return Err(p.site.err(
                K::Invocation,
                format!(
                    "expected a `do` in `{}`, an action the program declares without one and without a movement action of the standard library (§8.8) among its ancestors, found neither: the engine runs an action's own `do` (§7.3.9), or the action it inherits",
                    inv.action
                ),
            ));
        }
        if self.random.contains_key(&inv.actor) {
            return self.plan_random_traffic(p, inv, t0, out, after);
        }
        let targets: Vec<String> = match self.groups.get(&inv.actor) {
            Some(m) => m.clone(),
            None => vec![inv.actor.clone()],
        };
        // A relation to a member of random traffic reads a motion only the engine knows: the
        // run-time forms (random_traffic_relations), for each target after its first phase (a
        // group's phase that is the first of some of its members only: those placed from the
        // member as drawn, the others read it at run time).
        let starts: Vec<Option<f64>> = targets
            .iter()
            .map(|a| match (self.reads_members(p, inv, a), t0) {
                (Some(moves), Some(t)) => {
                    if moves {
                        self.engine_moves(a, Some(t));
                    }
                    None
                }
                (_, t0) => t0,
            })
            .collect();
        // The phase's start the plan knows for the group as a whole: none where every target
        // reads a member at run time.
        let t0 = t0.filter(|_| starts.iter().any(Option::is_some));
        // Each member's place in its group's formation at the start, before any member's
        // action changes the plan (position_actions moves the formation as a whole).
        let formation: Vec<Option<(f64, f64)>> = targets
            .iter()
            .zip(&starts)
            .map(|(m, start)| {
                let lead = self.groups.get(&inv.actor)?.first()?;
                let t = (*start)?;
                Some((
                    self.s_at(m, t) - self.s_at(lead, t),
                    self.t_at(m, t) - self.t_at(lead, t),
                ))
            })
            .collect();
        // The group's speed at the start: member 0's (a column's trajectory headways).
        let group_speed = match (self.groups.get(&inv.actor).and_then(|m| m.first()), t0) {
            (Some(lead), Some(t)) => Some(self.track(lead).at(t).1),
            _ => None,
        };
        if self.groups.contains_key(&inv.actor) && along_points(inv.kind) {
            self.check_group_path(p, inv, t0)?;
        }
        let mut derived = None;
        for ((target, formation), t0) in targets.iter().zip(formation).zip(starts) {
            let first = self.first_leaf.get(target) == Some(&p.path);
            let mut n = 0;
            let mut name = |what: &str| {
                n += 1;
                format!("{}/{target}/{n}:{what}", p.path)
            };
            // A step of speed at the phase start (`speed(v)` after the first phase).
            let step = match (t0, first) {
                (Some(t), false) => match mods
                    .iter()
                    .find(|m| m.kind == ModKind::Speed && m.at != At::End)
                {
                    Some(m) => Some((m, self.track(target).at(t).1, self.speed_value(m, t0)?.0)),
                    None => None,
                },
                _ => None,
            };
            // After a gap action, avoid_collisions(true) or a motion relative to a member of
            // random traffic the engine moves the actor: the plan knows no track to start a
            // phase at a time from.
            if let (Some(t), Some(since)) = (t0, self.engine_moved.get(target)) {
                // Its lane only the engine's (a following of the lanes of an actor the engine
                // moves): the plan knows its speed and place along its lane, and plans the
                // phase unless something reads its lane (`Planner::lane_blind_error`).
                if let Some(&lane_since) = self.lane_only.get(target) {
                    let blind = super::planner::LaneBlind {
                        since: lane_since,
                        start: t,
                        site: p.site.clone(),
                        read: None,
                    };
                    self.lane_blind
                        .borrow_mut()
                        .entry(target.clone())
                        .or_insert(blind);
                } else if self.random_member(target) {
                    // A member's motion is its model's from its creation: say so, not the
                    // gap-action reading below (found in review of b78c5936).
                    return Err(p.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected this phase of `{target}` of random traffic to start on a run-time condition (until, wait), found it at {t:.2} s, where the plan knows no place of it: its driver model moves it from its creation (§8.7.18.1: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\"); give the group the action (g.drive(), g.change_speed(…)) instead"
                        ),
                    ));
                } else {
                    return Err(p.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected this phase of `{target}` to start on a run-time condition (until, wait, or the end of its gap action), found it at {t:.2} s, after a gap action, avoid_collisions(true) or a motion relative to a member of random traffic{} from which the engine moves `{target}`",
                            since.map_or(String::new(), |s| format!(" started at {s:.2} s"))
                        ),
                    ));
                }
            }
            check_keeps(mods, step)?;
            // A member's own acceleration (plain, or relative to an actor outside its group;
            // relative to another member it is bad input, `random_traffic_relations`) after a
            // run-time condition is its model's free-road acceleration over the phase
            // (`member_acceleration`, below), or as the rate of its speed change
            // (`change_speed(v)`, `speed(v, at: end)`, v fixed or another actor's speed ± δ)
            // its model's rate toward v (`member_rate`, below), beside every action that leaves the member's longitudinal domain to its
            // model: a drive or move, its own lane action (follow_lane, change_lane: the
            // model's kept or mandatory lane), and a position, path or orientation action (a
            // TeleportAction is no motion control; change_position, follow_path and
            // replay_path are FollowTrajectoryActions without a time reference, which hold the
            // lateral domain only, the actor keeping its own speed along the path: the one
            // its model gives it). Beside keep_speed or remain_stationary it is every actor's
            // bad input (`check_keeps`, above), beside an action that controls the speed too
            // (`check_speed_modifiers`). A member's own timed trajectory is bad input: its
            // times would set the speed the model sets (`check_member_trajectory`).
            if self.random_member(target) {
                if mods.iter().any(|m| m.kind == ModKind::Acceleration) {
                    check_speed_modifiers(inv, first)?;
                }
                self.check_member_trajectory(p, inv, target)?;
            }
            let e = self.index[target.as_str()];
            // The yaw relative to the road's s-axis of an actor along its lane (§8.9.9).
            let along = if self.entities[e].against { PI } else { 0.0 };
            let planned = self.entities[e].yaw.as_ref().map_or(along, |(y, _)| *y);
            // A later phase's yaw relative to the road is checked once the plan is made where
            // the first phase's heading is (`heading`).
            let road_later = !first
                && self
                    .heading_asks
                    .iter()
                    .any(|a| a.first && a.actor == *target);
            let end_known = match (t0, end, len) {
                (_, Some(b), _) => Some(b),
                (Some(a), None, Some(l)) => Some(a + l),
                _ => None,
            };
            let (yaw, asks) = check_orientation(
                mods,
                planned,
                along,
                first,
                (target, &p.path, road_later),
                (t0, end_known),
                |x| self.entity_of(x),
            )?;
            if let Some(y) = yaw {
                self.entities[e].yaw = Some(y);
            }
            self.heading_asks.extend(asks);
            if t0.is_none() && !first {
                // After a run-time start the actor's heading is the engine's (plan::runtime).
                self.start_yaws(mods, target, &mut name, (&mut *out, &mut *after))?;
            }
            self.check_avoid_collisions(inv, mods, target)?;
            // keep_position() in a later phase: the vehicle must stand when it starts.
            if let Some(k) = mods.iter().find(|m| m.kind == ModKind::KeepPosition) {
                match t0 {
                    // After a run-time start the speed is the engine's (plan::runtime).
                    None => out.push(standing_check(target, (&k.name, &k.site), name("check"))),
                    Some(t) => {
                        let v = self.track(target).at(t).1;
                        if !first && v.abs() > 1e-9 {
                            return Err(k.site.err(
                                K::Unsatisfiable,
                                format!("expected `{target}` standing at the start of {}(), found it at {v:.2} m/s (stop it in an earlier phase)", k.name),
                            ));
                        }
                    }
                }
            }
            // The action itself, then its modifiers.
            let before_action = out.len();
            let slot = Slot {
                target,
                t0,
                len: match (t0, end, len) {
                    (Some(a), Some(b), _) if b > a => Some(b - a),
                    (_, _, l) => l,
                },
                first,
                out: &mut *out,
                persist: &mut *persist,
                formation,
                group_speed,
            };
            // A walk along a crossing the map bound (`crossing_walk`).
            let crossing = self.alongs.get(&p.path).and_then(|a| {
                a.iter()
                    .find(|(_, a)| matches!(a.route, Route::Crossing { .. }))
                    .map(|(_, a)| a.clone())
            });
            let action_end = match (&crossing, inv.kind) {
                (Some(along), _) => {
                    self.plan_crossing_walk(p, inv, mods, along, slot, &mut name)?
                }
                (_, Action::ChangeLane | Action::FollowLane) => {
                    self.plan_lateral_action(p, inv, slot, &mut name)?
                }
                (
                    _,
                    Action::ChangeSpaceGap
                    | Action::KeepSpaceGap
                    | Action::ChangeTimeHeadway
                    | Action::KeepTimeHeadway,
                ) => self.plan_gap_action(p, inv, slot, &mut name)?,
                (
                    _,
                    Action::FollowTrajectory
                    | Action::FollowPath
                    | Action::ReplayTrajectory
                    | Action::ReplayPath,
                ) => self.plan_trajectory_action(p, inv, slot, &mut name)?,
                (
                    _,
                    Action::AssignPosition | Action::AssignOrientation | Action::ChangePosition,
                ) => self.plan_position_action(p, inv, slot, &mut name)?,
                _ => self.plan_speed_action(p, inv, slot, &mut name)?,
            };
            derived = all_of(derived, action_end);
            // A member's path followed by the default controller: its model's lateral domain
            // taken back over the phase where the model holds it.
            self.member_path_lateral((p, inv), target, &mut name, before_action, (out, after));
            // Speed first, position at end last: it builds on the phase's speed.
            let mut ordered: Vec<&Modifier> = mods.iter().collect();
            ordered.sort_by_key(|m| {
                ((m.kind == ModKind::Position && m.at == At::End) || m.kind == ModKind::Distance)
                    as u8
            });
            for m in ordered {
                let need_t = |what: &str| -> Result<f64, Error> {
                    t0.ok_or_else(|| {
                        m.site.err(
                            K::Unsatisfiable,
                            format!("expected a phase start the plan knows for {what}, found one after a run-time condition"),
                        )
                    })
                };
                // The phase's start (when the plan knows it) and duration.
                let need_len = |what: &str| -> Result<(Option<f64>, f64), Error> {
                    match (t0, end, len) {
                        (Some(a), Some(b), _) if b > a => Ok((Some(a), b - a)),
                        (_, _, Some(l)) if l > 0.0 => Ok((t0, l)),
                        _ => Err(m.site.err(
                            K::Unsatisfiable,
                            format!("expected a phase duration the plan knows for {what}, found none (give the phase a duration)"),
                        )),
                    }
                };
                if m.shape.is_some() {
                    // The action the shape describes, from the phase start (`shapes`).
                    let phase_len = match (t0, end, len) {
                        (Some(a), Some(b), _) if b > a => Some(b - a),
                        (_, _, l) => l,
                    };
                    let slot = Slot {
                        target,
                        t0,
                        len: phase_len,
                        first,
                        out: &mut *out,
                        persist: &mut *persist,
                        formation: None,
                        group_speed: None,
                    };
                    let ends = self.plan_shaped(p, m, mods, slot, &mut name)?;
                    match (t0, phase_len, ends) {
                        (Some(t), Some(l), Some(When::At(te))) if te > t + l + 1e-9 => {
                            return Err(m.site.err(
                                K::Unsatisfiable,
                                format!("expected the change of `{}(…)`'s shape within the phase's {l:.2} s, found it takes {:.2} s", m.name, te - t),
                            ));
                        }
                        (_, None, e) if end.is_none() => derived = all_of(derived, e),
                        _ => {}
                    }
                    continue;
                }
                match (m.kind, m.at) {
                    // Checked against the planned motion (see check_keeps, route::check).
                    (
                        ModKind::Along
                        | ModKind::Orientation
                        | ModKind::KeepLane
                        | ModKind::KeepPosition
                        | ModKind::KeepSpeed
                        | ModKind::PhysicalMovement
                        | ModKind::AvoidCollisions,
                        _,
                    ) => {}
                    (ModKind::Speed, At::Start | At::All) => {
                        let (v, relative) = self.speed_value(m, t0)?;
                        // §8.9.1.1.1: at: all "holds throughout the phase": relative to x
                        // (x's speed as it goes, not projected) the actor's speed is x's ± the
                        // value at every step, in its first phase too (`speed_follow`).
                        let held = relative.is_some()
                            && m.at == At::All
                            && !m.projected
                            && crossing.is_none();
                        if let Some((x, delta)) = relative.as_ref().filter(|_| held) {
                            self.hold_speed(target, m, (x, *delta), t0, end)?;
                        }
                        // A walk along a crossing is timed at this speed (`crossing_walk`): a
                        // SpeedAction beside its FollowTrajectoryAction would replace it.
                        if (first && !held) || crossing.is_some() {
                            continue;
                        }
                        let target_speed = match relative {
                            Some((x, delta)) => SpeedTarget::Relative {
                                entity_ref: x,
                                value: delta,
                                speed_target_value_type: SpeedTargetValueType::Delta,
                                // Projected: x's speed as the action starts, held.
                                continuous: m.at == At::All && !m.projected,
                            },
                            None => SpeedTarget::Absolute(v),
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("speed"),
                            action: speed_action(DynamicsShape::Step, 0.0, target_speed),
                            site: m.site.clone(),
                        });
                        if !held {
                            if let Some(t) = t0 {
                                self.track_mut(target).ramp(t, t, v);
                            }
                            self.last_v.insert(target.clone(), v);
                        }
                    }
                    (ModKind::Speed, At::End) | (ModKind::ChangeSpeed, _) => {
                        // A member's own change at the rate of acceleration(…): its model's.
                        let rate = mods.iter().find(|q| q.kind == ModKind::Acceleration);
                        if let Some(q) = rate.filter(|_| self.random_member(target)) {
                            let names = (name("check"), name("speed"));
                            self.member_rate((m, q), target, len, names, (out, after))?;
                            continue;
                        }
                        // Beside distance(d) without a duration after a run-time start: at
                        // its rate, checked to end within d (`runtime_end`).
                        let timed = match t0 {
                            Some(t) => end.is_some_and(|te| te > t),
                            None => len.is_some_and(|l| l > 0.0),
                        };
                        if let Some(dm) = mods
                            .iter()
                            .find(|q| q.kind == ModKind::Distance && q.at != At::Start)
                            .filter(|_| !timed)
                        {
                            let names = (name("check"), name("speed"));
                            let ends = self.speed_over_distance(
                                (m, dm),
                                mods,
                                (target, t0),
                                names,
                                (out, after),
                            )?;
                            if let Some(te) = ends {
                                // As distance(d)'s own end (below).
                                derived = Some(match derived {
                                    None => te,
                                    Some(w) => w.or(te),
                                });
                            }
                            continue;
                        }
                        let (t, len) = need_len("a speed at the phase end")?;
                        let read_at = if m.projected { t } else { t.map(|t| t + len) };
                        let (v1, relative) = self.speed_value(m, read_at)?;
                        if let (None, Some((x, delta))) = (t, relative) {
                            // After a run-time start x's speed is the engine's: a linear
                            // SpeedAction to x's speed (plus the delta) as the engine reads it
                            // each step, so it ends at x's speed at the phase end; projected,
                            // x's speed as the action starts, then fixed (oscsim's
                            // RelativeAtStart target).
                            // At the rate of acceleration(a): the change's length is the
                            // engine's to check from both speeds then (plan::runtime).
                            if let Some(q) = mods.iter().find(|q| q.kind == ModKind::Acceleration) {
                                let names = (name("check"), name("speed"));
                                let rated = (m, q);
                                out.extend(self.start_relative_speed_at_rate(
                                    rated,
                                    target,
                                    ((x, delta), len),
                                    names,
                                    after,
                                )?);
                                continue;
                            }
                            let to = if m.projected {
                                SpeedTarget::RelativeAtStart {
                                    entity_ref: x,
                                    value: delta,
                                }
                            } else {
                                SpeedTarget::Relative {
                                    entity_ref: x,
                                    value: delta,
                                    speed_target_value_type: SpeedTargetValueType::Delta,
                                    continuous: false,
                                }
                            };
                            out.push(speed_change_check(
                                target,
                                (&m.name, &m.site),
                                (to.clone(), DynamicsShape::Linear, len),
                                name("check"),
                            ));
                            out.push(Planned::with_phase(
                                target,
                                name("speed"),
                                speed_action(DynamicsShape::Linear, len, to),
                                &m.site,
                            ));
                            continue;
                        }
                        let v0 = t.map_or(self.last_v[target], |t| self.track(target).at(t).1);
                        check_speed(m, v1)?;
                        // At the rate of another actor's acceleration after a run-time start:
                        // the engine reads it then (`acceleration_follow`).
                        let rated = mods.iter().find(|q| q.kind == ModKind::Acceleration);
                        if let Some(action) = self.relative_rate_at_run_time(rated, t, (v1, len))? {
                            out.push(Planned::with_phase(target, name("speed"), action, &m.site));
                            self.last_v.insert(target.clone(), v1);
                            continue;
                        }
                        // With acceleration(a): the change at that rate, done within the phase.
                        let rate = match mods.iter().find(|q| q.kind == ModKind::Acceleration) {
                            Some(q) => Some((q, self.acceleration_value(q, (t, len))?.abs())),
                            None => None,
                        };
                        let (action, ramp) = match rate {
                            Some((q, a)) => {
                                check_accel(q, a)?;
                                let needed = (v1 - v0).abs() / a;
                                if t.is_none() {
                                    // After a run-time start the speed the actor has is the
                                    // engine's: it checks the change ends within the phase.
                                    out.push(speed_at_rate_check(
                                        target,
                                        (&q.name, &q.site),
                                        (SpeedTarget::Absolute(v1), a, RateWithin::Time(len)),
                                        name("check"),
                                    ));
                                } else if needed > len + 1e-9 {
                                    return Err(q.site.err(
                                        K::Unsatisfiable,
                                        format!("expected the speed change from {v0:.2} m/s to {v1:.2} m/s at {a} m/s² within the phase's {len} s, found it needs {needed:.2} s"),
                                    ));
                                }
                                let dynamics = TransitionDynamics {
                                    dynamics_shape: DynamicsShape::Linear,
                                    dynamics_dimension: DynamicsDimension::Rate,
                                    value: a,
                                    following_mode: None,
                                };
                                (
                                    PrivateAction::Longitudinal(LongitudinalAction::Speed {
                                        dynamics,
                                        target: SpeedTarget::Absolute(v1),
                                    }),
                                    needed,
                                )
                            }
                            None => {
                                match t {
                                    Some(_) => check_accel(m, (v1 - v0) / len)?,
                                    // After a run-time start the engine checks the rate from
                                    // the speed the actor has then (plan::runtime).
                                    None => out.push(speed_change_check(
                                        target,
                                        (&m.name, &m.site),
                                        (SpeedTarget::Absolute(v1), DynamicsShape::Linear, len),
                                        name("check"),
                                    )),
                                }
                                (
                                    speed_action(
                                        DynamicsShape::Linear,
                                        len,
                                        SpeedTarget::Absolute(v1),
                                    ),
                                    len,
                                )
                            }
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("speed"),
                            action,
                            site: m.site.clone(),
                        });
                        if let Some(t) = t {
                            self.track_mut(target).ramp(t, t + ramp, v1);
                        }
                        self.last_v.insert(target.clone(), v1);
                    }
                    (ModKind::Acceleration, _) => {
                        // Alone: a constant acceleration over the phase.
                        let paired = mods.iter().any(|q| {
                            q.kind == ModKind::ChangeSpeed
                                || (q.kind == ModKind::Speed && q.at == At::End)
                        });
                        if paired {
                            continue;
                        }
                        if self.random_member(target) {
                            let names = (name("acceleration"), name("acceleration_end"));
                            self.member_acceleration(m, target, names, (out, after))?;
                            continue;
                        }
                        let (t, len) = need_len("acceleration(…)")?;
                        if let Some((x, delta, pieces)) = self.followed_acceleration(m, (t, len))? {
                            let n = name("acceleration");
                            self.plan_followed_acceleration(
                                m,
                                target,
                                (t, x, delta),
                                &pieces,
                                n,
                                out,
                            )?;
                            continue;
                        }
                        let a = self.acceleration_value(m, (t, len))?;
                        check_accel(m, a)?;
                        let Some(t) = t else {
                            // After a run-time start the speed the actor has is the engine's:
                            // its AccelerationAction holds a from that speed until the
                            // phase's Act stops (plan::runtime).
                            out.extend(self.start_acceleration(m, target, (a, len), &mut name));
                            continue;
                        };
                        let v0 = self.track(target).at(t).1;
                        let v1 = v0 + a * len;
                        check_speed(m, v1)?;
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("acceleration"),
                            action: speed_action(
                                DynamicsShape::Linear,
                                len,
                                SpeedTarget::Absolute(v1),
                            ),
                            site: m.site.clone(),
                        });
                        self.track_mut(target).ramp(t, t + len, v1);
                        self.last_v.insert(target.clone(), v1);
                    }
                    (ModKind::Position, At::Start | At::All)
                    | (ModKind::Lane, At::Start | At::All) => {
                        // A group's place is member 0's, its reference (the others are at
                        // their formation's places from it).
                        let (alone, reference) = match self.groups.get(&inv.actor) {
                            None => (true, true),
                            Some(g) => (false, g.first() == Some(target)),
                        };
                        // A first phase is placed by it, but one that starts at run time
                        // starts where the actor's motion before it has taken it (placed at
                        // the run's start): its place (position(d), lane(n)) or relation to
                        // another actor is the engine's check then too, a relation held at:
                        // all (issue 27).
                        let late = t0.is_none();
                        if (!first || late) && reference {
                            match t0 {
                                Some(t) => self.check_start(m, target, t)?,
                                // After a run-time start the engine checks it (plan::runtime).
                                None => out.push(self.start_check(m, target, name("check"))?),
                            }
                        }
                        // Relative to another actor at: all, held throughout (held_relation);
                        // a group's is member 0's and moves no member.
                        if m.at == At::All && reference {
                            let span = (t0, end_known);
                            let kind = (inv.kind, mods, alone);
                            self.hold_relation(m, target, kind, span, &mut name, out)?;
                        }
                    }
                    (ModKind::Position, At::End) => {
                        let Some(t) = t0 else {
                            // After a run-time start: the engine works out the profile then,
                            // or (no duration) measures the gap reached.
                            match len.filter(|l| *l > 0.0) {
                                Some(l) => {
                                    let n = name("position");
                                    self.start_travel(m, target, mods, l, n, out, after)?;
                                }
                                None => {
                                    let t = self.last_known();
                                    let (_, sign, d) = self.position_target(m, target, t)?;
                                    // The gap (at x's speed as the engine measures it for
                                    // a time or the default) reached from the side the actor
                                    // starts on, in the plan's s on several roads; projected,
                                    // to x projected from the start (plan::runtime_end).
                                    let w = match self.gap_watch(m, target, name("position"))? {
                                        Some((check, w)) => {
                                            out.push(check);
                                            w
                                        }
                                        None => self.gap_reached(m, target, None, sign, d)?,
                                    };
                                    derived = all_of(derived, Some(w));
                                }
                            }
                            continue;
                        };
                        let (x, sign, d) = self.position_target(m, target, t)?;
                        let (ve_given, hold) = (end_speed_mod(mods), holds_speed(mods));
                        let v0 = self.track(target).at(t).1;
                        let s_a = self.s_at(target, t);
                        let lane_a = self.lane_now(target, t);
                        match end {
                            None => {
                                // Constant speeds: when does the gap reach its value?
                                let (s_x, v_x) =
                                    x.as_ref().map_or((0.0, 0.0), |x| self.track(x).at(t));
                                let gap = s_x + sign * d - s_a;
                                let closing = v0 - v_x;
                                let tau = gap / closing;
                                if !(tau.is_finite() && tau > 0.0) {
                                    return Err(m.site.err(
                                        K::Unsatisfiable,
                                        format!("expected the actors to close the {gap:.2} m to this position at their speeds ({v0:.2} m/s and {v_x:.2} m/s), found they never do"),
                                    ));
                                }
                                // The phase ends when the engine measures the gap reached
                                // (the same step an XML trigger on it would fire); to x
                                // projected at its start speed, when the plan has it reached.
                                let w = if m.projected {
                                    When::At(t + tau)
                                } else {
                                    // Reached from the side the actor starts on (a mark:
                                    // plan::runtime_end; on several roads in the plan's s).
                                    match self.gap_watch(m, target, name("position"))? {
                                        Some((check, w)) => {
                                            out.push(check);
                                            w
                                        }
                                        None => {
                                            self.gap_reached(m, target, x.as_deref(), sign, d)?
                                        }
                                    }
                                };
                                derived = Some(match derived {
                                    None => w,
                                    Some(When::Dyn(mut a)) => {
                                        // Both gaps reached: one group with every condition.
                                        if let (Some(ga), When::Dyn(b)) =
                                            (a.condition_groups.first_mut(), &w)
                                        {
                                            ga.conditions.extend(
                                                b.condition_groups
                                                    .iter()
                                                    .flat_map(|g| g.conditions.clone()),
                                            );
                                        }
                                        When::Dyn(a)
                                    }
                                    Some(other) => other,
                                });
                            }
                            Some(te) => {
                                let len = te - t;
                                let s_x =
                                    x.as_ref().map_or(0.0, |x| self.reference_s(m, x, (t, te)));
                                let want = s_x + sign * d;
                                // The distance to cover along the actor's lane.
                                let ds = self.road.lane_distance(lane_a, s_a, want);
                                if hold && ve_given.is_none() {
                                    let got = self.road.s_after(lane_a, s_a, v0 * len);
                                    if (got - want).abs() > POSITION_TOLERANCE {
                                        return Err(m.site.err(
                                            K::Unsatisfiable,
                                            format!("expected position(…, at: end) met at the constant speed {v0:.2} m/s, found it {:.2} m off at the phase end", got - want),
                                        ));
                                    }
                                    continue;
                                }
                                let ve = self.end_speed(ve_given, (t, te), v0)?;
                                let names = (name("position.1"), name("position.2"));
                                self.two_halves(
                                    m,
                                    target,
                                    (t, len, DynamicsShape::Linear),
                                    (v0, ds, ve),
                                    names,
                                    out,
                                )?;
                            }
                        }
                    }
                    (ModKind::Distance, at) => {
                        if at == At::Start {
                            return Err(m.site.err(
                                K::Modifier,
                                "expected distance(…) over the phase (at: all or end), found at: start",
                            ));
                        }
                        // Without a duration, acceleration(a) is the rate of the speed change
                        // beside it (`speed_over_distance`).
                        let timed = match t0 {
                            Some(t) => end.is_some_and(|te| te > t),
                            None => len.is_some_and(|l| l > 0.0),
                        };
                        let rates_change = !timed && end_speed_mod(mods).is_some();
                        if let Some(q) = mods.iter().find(|q| q.kind == ModKind::Acceleration) {
                            if !rates_change {
                                return Err(q.site.err(
                                    K::Unsatisfiable,
                                    format!("expected the speed profile of distance(…) at {} planned by the runtime, found acceleration(…) beside it", m.site.at()),
                                ));
                            }
                        }
                        if t0.is_none() {
                            // After a run-time start: the engine works out the profile then,
                            // or (no duration) measures d travelled from the start.
                            let n = name("distance");
                            match len.filter(|l| *l > 0.0) {
                                Some(l) => self.start_travel(m, target, mods, l, n, out, after)?,
                                None => {
                                    let d = m.arg("distance").map(Arg::number).transpose()?;
                                    let Some(d) = d.filter(|d| *d >= 0.0) else {
                                        return Err(m.site.err(
                                            K::Value,
                                            "expected a distance of 0 m or more in distance(…), found none",
                                        ));
                                    };
                                    let (check, w) = self.distance_watch(m, target, d, n);
                                    out.push(check);
                                    derived = Some(match derived {
                                        None => w,
                                        Some(e) => e.or(w),
                                    });
                                }
                            }
                            continue;
                        }
                        let t = need_t("distance(…)")?;
                        let d =
                            match m.arg("distance").map(Arg::number).transpose()? {
                                Some(d) if d >= 0.0 => d,
                                _ => return Err(m.site.err(
                                    K::Value,
                                    "expected a distance of 0 m or more in distance(…), found none",
                                )),
                            };
                        let v0 = self.track(target).at(t).1;
                        let (ve_given, hold) = (end_speed_mod(mods), holds_speed(mods));
                        match end.filter(|te| *te > t) {
                            Some(te) => {
                                let len = te - t;
                                if hold && ve_given.is_none() {
                                    if (v0 * len - d).abs() > POSITION_TOLERANCE {
                                        return Err(m.site.err(
                                            K::Unsatisfiable,
                                            format!("expected distance({d} m) at the constant speed {v0:.2} m/s over {len} s, found {:.2} m", v0 * len),
                                        ));
                                    }
                                    continue;
                                }
                                let ve = self.end_speed(ve_given, (t, te), v0)?;
                                let names = (name("distance.1"), name("distance.2"));
                                self.two_halves(
                                    m,
                                    target,
                                    (t, len, DynamicsShape::Linear),
                                    (v0, d, ve),
                                    names,
                                    out,
                                )?;
                            }
                            None => {
                                // No duration: the phase ends when d is travelled at the speed
                                // it starts with; beside a speed change, when the change and
                                // the rest of d at its speed are (`speed_over_distance`).
                                if ve_given.is_some() {
                                    continue;
                                }
                                if v0 <= 0.0 && d > 0.0 {
                                    return Err(m.site.err(
                                        K::Unsatisfiable,
                                        format!("expected `{target}` to move to travel {d} m, found it standing"),
                                    ));
                                }
                                let te = When::At(t + if d > 0.0 { d / v0 } else { 0.0 });
                                derived = Some(match derived {
                                    None => te,
                                    Some(w) => w.or(te),
                                });
                            }
                        }
                    }
                    (ModKind::Lane, At::End) | (ModKind::ChangeLane, _) => {
                        let (t, len) = need_len("a lane change")?;
                        let (target_lane, planned) = self.lane_target(m, target, t, len)?;
                        // Beside another actor after a run-time start: the engine finds the
                        // lane holding the t asked, and checks the change's lane at the end.
                        if let Some(q) = lateral_end(mods).filter(|_| t.is_none()) {
                            let n = (name("lateral"), name("lane"));
                            let io = (&mut *out, &mut *after);
                            if self.beside_with_lane_change(
                                q,
                                (m, target_lane.clone()),
                                target,
                                len,
                                n,
                                io,
                            )? {
                                continue;
                            }
                            // In the lane: the offset in the target lane's width where the
                            // actor ends the phase (the engine's, `start_offset_change`).
                            let lane = (Some(target_lane), planned, len);
                            out.push(self.start_offset_change(q, target, lane, name("lane"))?);
                            continue;
                        }
                        // lateral(…, at: end): the offset in the target lane.
                        let offset = match (lateral_end(mods), planned) {
                            (Some(q), Some(l)) => Some(self.end_offset_in(q, target, l, t, len)?),
                            (Some(q), None) => {
                                return Err(q.site.err(
                                    K::Unsatisfiable,
                                    "expected a target lane the plan knows for lateral(…, at: end) with a lane change, found none",
                                ))
                            }
                            (None, _) => None,
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("lane"),
                            action: PrivateAction::Lateral(LateralAction::LaneChange {
                                target_lane_offset: offset,
                                dynamics: sinusoidal_over(len),
                                target: target_lane,
                            }),
                            site: m.site.clone(),
                        });
                        if let (Some(l), Some(t)) = (planned, t) {
                            let tr = self.track_mut(target);
                            tr.set_lane(t + len, l);
                            tr.set_offset(t + len, offset.unwrap_or(0.0));
                            tr.add_move(t, t + len);
                        }
                    }
                    // Beside a walk along a crossing: the walk's line moved across
                    // (`crossing_walk::crossing_shift`).
                    (ModKind::Lateral, _) if crossing.is_some() => {}
                    (ModKind::Lateral, At::Start | At::All) => {
                        if m.at == At::All {
                            if let Some(c) = lane_change(mods) {
                                return Err(c.site.err(
                                    K::Unsatisfiable,
                                    format!("expected no lane change while lateral(…) at {} holds throughout the phase, found `{}(…)`", m.site.at(), c.name),
                                ));
                            }
                        }
                        if first {
                            // Placed; beside another actor and throughout, the actor keeps
                            // beside it (`lateral_follow`).
                            if m.at == At::All {
                                let te = end.or(len.and_then(|l| t0.map(|t| t + l)));
                                let span = (t0.unwrap_or(0.0), te);
                                self.plan_beside_all(m, target, span, name("lateral"), out)?;
                            }
                            continue;
                        }
                        let Some(t) = t0 else {
                            // After a run-time start the engine checks it (plan::runtime);
                            // beside another actor at: all it follows x (`lateral_follow`), a
                            // block's member at its slot where the plan last knows the block.
                            out.push(self.start_check(m, target, name("check"))?);
                            if let (At::All, false) = (m.at, m.projected) {
                                let last = self.last_known();
                                if let Some((x, dt)) = self.beside_slot(m, target, last)? {
                                    let n = name("lateral");
                                    out.push(self.follow_beside(m, target, x, dt, n));
                                }
                            }
                            continue;
                        };
                        // Beside another actor: the planned t of both at the start (a member
                        // of a block, its slot's: `beside_slot`).
                        if let Some((x, want)) = self.beside_slot(m, target, t)? {
                            let got = self.t_at(target, t) - self.t_at(&x, t);
                            if (got - want).abs() > LATERAL_TOLERANCE {
                                return Err(m.site.err(
                                    K::Unsatisfiable,
                                    format!("expected `{target}` {want:.2} m to the left of `{x}` across the road at the phase start, found it {got:.2} m (plan an earlier phase to reach it)"),
                                ));
                            }
                            if m.at == At::All {
                                let span = (t, end.or(len.map(|l| t + l)));
                                self.plan_beside_all(m, target, span, name("lateral"), out)?;
                            }
                            continue;
                        }
                        let lane = self.lane_now(target, t);
                        let w = self.road.lane_width(lane, self.s_at(target, t));
                        let want = lateral::lane_offset(m, w, self.width(target))?;
                        let got = self.track(target).offset(t);
                        if (got - want).abs() > LATERAL_TOLERANCE {
                            return Err(m.site.err(
                                K::Unsatisfiable,
                                format!("expected this lateral position at the phase start, found `{target}` {:.2} m from it (plan an earlier phase to reach it, with lateral(…, at: end))", got - want),
                            ));
                        }
                    }
                    (ModKind::Lateral, At::End) => {
                        if lane_change(mods).is_some() {
                            // Planned with the lane change.
                            continue;
                        }
                        let (t, len) = need_len("a lateral position at the phase end")?;
                        // Beside another actor: where the plan has it at the phase end.
                        if lateral::reference(m)?.is_some() {
                            let mut keeps = mods.iter().find(|q| {
                                q.kind == ModKind::KeepLane
                                    || (q.kind == ModKind::Lane && q.at == At::All)
                            });
                            // After a run-time start the engine finds the lane that holds the
                            // t asked: the lane kept is its check at the phase end.
                            if let Some(k) = keeps.filter(|_| t.is_none()) {
                                let n = name("lane");
                                self.lane_kept_to_end(k, target, n, (&mut *out, &mut *after))?;
                                keeps = None;
                            }
                            let n = name("lateral");
                            self.plan_beside_end(m, target, (t, len), keeps, n, out)?;
                            continue;
                        }
                        let Some(t) = t else {
                            // After a run-time start the offset the actor starts from is the
                            // engine's: a change over the phase within its own lane.
                            let lane = (None, None, len);
                            out.push(self.start_offset_change(m, target, lane, name("lateral"))?);
                            continue;
                        };
                        // Its lane at the start, followed to where the phase ends.
                        let lane = self.lane_now(target, t);
                        let o0 = self.track(target).offset(t);
                        let (s0, s1) = (self.s_at(target, t), self.s_at(target, t + len));
                        let w = self.road.lane_width(self.road.lane_along(lane, s0, s1), s1);
                        let o1 = lateral::lane_offset(m, w, self.width(target))?;
                        // A sinusoidal change of Δ has its peak lateral acceleration
                        // π²Δ/(2T²): given as the action's maximum, the engine's change lasts T.
                        let a = super::motion::sinusoid_peak_acceleration(o1 - o0, len);
                        check_accel(m, a)?;
                        if a > 0.0 {
                            out.push(Planned {
                                entity: target.clone(),
                                at: None,
                                name: name("lateral"),
                                action: PrivateAction::Lateral(LateralAction::LaneOffset {
                                    continuous: false,
                                    dynamics_shape: DynamicsShape::Sinusoidal,
                                    max_lateral_acc: Some(a),
                                    target: scenario::LaneOffsetTarget::Absolute(o1),
                                }),
                                site: m.site.clone(),
                            });
                        }
                        let tr = self.track_mut(target);
                        tr.set_offset(t + len, o1);
                        if a > 0.0 {
                            tr.add_move(t, t + len);
                        }
                    }
                }
            }
            self.plan_avoid_collisions(mods, target, t0, &mut name, out, after)?;
            // The routes, against the motion just planned: at the end only where the plan
            // knows the actor's place then, not where the engine's controller moves it
            // (avoid_collisions(true), a gap action).
            let te = match (t0, end, len) {
                (Some(a), Some(b), _) if b > a => Some(b),
                (Some(a), _, Some(l)) => Some(a + l),
                _ => None,
            }
            .filter(|_| !self.engine_moved.contains_key(target));
            let alongs = self.alongs.get(&p.path).cloned().unwrap_or_default();
            // The lane changes of a route through points in other lanes (`route_moves`), where
            // the plan knows the actor's motion.
            let known = t0.filter(|_| !self.engine_moved.contains_key(target));
            for along in &alongs {
                self.plan_route_moves(along, mods, target, (known, te), &mut name, out)?;
            }
            let mut shared = std::mem::take(&mut self.route_lanes);
            let lane = |t: f64| self.lane_now(target, t);
            let s = |t: f64| self.s_at(target, t);
            let on = OnRoute {
                actor: target,
                t0,
                te,
                lane: &lane,
                s: &s,
                roads: &self.route_roads,
            };
            let checked: Result<Vec<_>, Error> = alongs
                .iter()
                .map(|(at, a)| {
                    route::check(&self.road, a, *at, mods, &on, &mut shared)
                        .map(|start| start.map(|start| (a.site.clone(), start)))
                })
                .collect();
            self.route_lanes = shared;
            // Named routes at a run-time start: the engine's check there.
            for (site, start) in checked?.into_iter().flatten() {
                out.push(self.route_check(&site, target, start, name("check"))?);
            }
        }
        Ok(derived)
    }
}

/// Both ends: the later of two times, or every condition of both.
fn all_of(a: Option<When>, b: Option<When>) -> Option<When> {
    Some(match (a, b) {
        (None, x) | (x, None) => return x,
        (Some(When::At(x)), Some(When::At(y))) => When::At(x.max(y)),
        (Some(x), Some(y)) => {
            let (gx, gy) = (x.groups(), y.groups());
            let mut groups = Vec::new();
            for p in &gx {
                for q in &gy {
                    let mut c = p.conditions.clone();
                    c.extend(q.conditions.iter().cloned());
                    groups.push(scenario::ConditionGroup { conditions: c });
                }
            }
            When::Dyn(scenario::Trigger {
                condition_groups: groups,
            })
        }
    })
}
