//! Relations to another actor x at `at: all` (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.1: a
//! constraint at `all` "holds throughout the phase"): `position(d / time: t, ahead_of/behind:
//! x)` and `lane(same_as/side_of/left_of/right_of: x)`. Before, both were checked at the phase
//! start only, and a run in which they stopped holding passed (issue 27).
//!
//! | relation at: all | the actor free along its lane | at a start the plan knows | after a run-time start |
//! | --- | --- | --- | --- |
//! | `position(d / time: t, ahead_of/behind: x)` | yes | the engine holds it (LongitudinalDistanceAction, continuous, no limits: the actor put d from x along the road at every step at x's speed); the plan gives the actor x's speed profile over the phase | the same hold |
//! | `position(…)` | no | the plan's check at every step of the phase: an error before the run naming both speeds | the engine's check held over the phase (`StateCheck::throughout`) |
//! | `lane(…: x)` | — | the plan's check at every step of the phase: an error before the run | the engine's check held over the phase |
//!
//! "Free along its lane": a `move()`/`drive()` with no modifier of its own that sets its speed
//! or its travel (`speed`, `change_speed`, `acceleration`, `distance`, `keep_speed`,
//! `keep_position`, another `position`, `avoid_collisions`): the relation is then what
//! determines its motion, as `keep_space_gap` determines a follower's. A default gap
//! (`position(ahead_of/behind: x)` without distance or time: max(2 s · v_x, 10 m + the
//! overhangs), oscsim's: `place::default_distance`) is held at a known start as the time gap
//! 2 s where x's speed at the start makes it the larger, else as the distance; after a
//! run-time start (x's speed then is the engine's) as the larger of the two at x's speed at
//! every step (the LongitudinalDistanceAction's time gap 2 s with oscsim's `at_least`), the
//! gap the engine's held check measures.
//! With `track: projected` (§8.9.1.1.3) x is read as projected from the phase start (along
//! its lane at its speed then, in its lane then): at a start and end the plan knows, the
//! plan's check against that, an actor free along its lane keeping x's speed at the start (a
//! step SpeedAction); after a run-time start, with an end the plan does not know, or with an x
//! the engine moves, the engine's held check against x projected from the start the engine
//! finds (`StateCheck::projected`), an actor free along its lane keeping x's speed then (oscsim's
//! `SpeedTarget::RelativeAtStart`). A phase whose end the plan does not know is the engine's held check from
//! its known start, as is a relation to an x the engine moves then (a gap action's or a
//! model's controller: the plan has no track of x; an actor held to such an x is the engine's
//! to move too). A group's relation is member 0's, the group's reference (each other
//! member's place is its formation's from member 0): checked as above, never moving a member
//! (no hold, no lane following, no speed of x's kept: `hold_relation`'s `moves`).
//!
//! The plan checks its own tracks at the engine's steps from the phase start to its end, s
//! within [`POSITION_TOLERANCE`] of x's s ∓ d (d at x's speed then for a time), the lane the
//! one counted from x's then (lanes switch on the plan's tracks where a lane change ends), once
//! every phase is planned (x's phase may be planned after the actor's).
//! `lane(…: x)` at: all of a `move()`/`drive()` with no sideways motion of its own (no
//! `change_lane`, `lateral`, `keep_lane`, `lane(…, at: end)`): the actor follows x's lane
//! changes in the phase, each a sinusoidal LaneChangeAction over the span of x's (from its
//! start, an absolute time) into the lane counted from x's new one (the same shape as x's
//! `change_lane`/`lane(…, at: end)`: the two cross their lanes' border in the same step where
//! the lanes are as wide); a change of x's that runs past the phase is the check's error.
//! Where the plan does not know x's changes (after a run-time start, before a run-time end,
//! or an x the engine moves) the engine follows them as they begin (oscsim's
//! `LateralAction::FollowLanes`: the lane counted from x's new one, its transition at x's
//! weight at every step), beside its held check, and the actor's lane is the engine's from
//! the phase start (`engine_moved`, `lane_only`: a later phase of it at a time the plan sets
//! is an error where it reads that lane); where the invocation has several lane
//! relations, one following of them all (the lane counted from whichever x just began a
//! change; where several begin in the same step, the first in the modifiers' order: such
//! relations that then disagree are over-constrained, and the engine's held check of each
//! reports the one that fails), and where one of their x's is the engine's to move, every
//! one of them is the engine's (its following and held checks, not the plan's).
//! `lateral(…, side_of/left_of/right_of: x)` at: all is `lateral_follow`'s.

use scenario::{
    CoordinateSystem, DynamicsShape, FollowedLane, LaneChangeTarget, LateralAction,
    LongitudinalAction, LongitudinalDisplacement, PrivateAction, SpeedTarget,
};

use super::motion::{sinusoidal_over, speed_action};

use super::place::{DEFAULT_TIME_GAP, GROUP_GAP};
use super::planner::Planner;
use super::types::{Planned, When, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Action, At, ModKind, Modifier};

/// A relation at: all over a phase whose start and end the plan knows: (actor, the modifier,
/// phase start, phase end), checked once every phase is planned.
pub(crate) type HeldRelation = (String, Modifier, f64, f64);

/// The modifiers of an invocation that set the actor's speed or travel along its lane.
const OWN_ALONG: [ModKind; 8] = [
    ModKind::Speed,
    ModKind::ChangeSpeed,
    ModKind::Acceleration,
    ModKind::Distance,
    ModKind::KeepSpeed,
    ModKind::KeepPosition,
    ModKind::Position,
    ModKind::AvoidCollisions,
];

/// Whether `mods` move the actor sideways of their own (a lane change, a lateral position).
fn moves_sideways(mods: &[Modifier]) -> bool {
    mods.iter().any(|q| {
        matches!(
            q.kind,
            ModKind::ChangeLane | ModKind::Lateral | ModKind::KeepLane
        ) || (q.kind == ModKind::Lane && q.at == At::End)
    })
}

/// Whether an invocation `kind` with `mods` (`moves`: its relations may set the actor's motion)
/// has the actor follow the lane changes of the actors its `lane(…: x)` at: all relate it to:
/// a `move()`/`drive()` with no sideways motion of its own (module doc).
fn follows_lanes(kind: Action, mods: &[Modifier], moves: bool) -> bool {
    moves && kind == Action::Move && !moves_sideways(mods)
}

/// The `lane(…: x)` relations at: all of `mods` whose x's lane changes an actor with no
/// sideways motion of its own follows, in the modifiers' order (with `track: projected` x's
/// lane is the one at the phase start: nothing to follow).
fn followed_lanes(mods: &[Modifier]) -> impl Iterator<Item = &Modifier> {
    mods.iter()
        .filter(|q| q.kind == ModKind::Lane && q.at == At::All && !q.projected && relation(q))
}

/// Whether `m` relates the actor to another one along the road or by lane.
pub(super) fn relation(m: &Modifier) -> bool {
    let keys: &[&str] = match m.kind {
        ModKind::Position => &["ahead_of", "behind"],
        ModKind::Lane => &["same_as", "side_of", "left_of", "right_of"],
        _ => &[],
    };
    keys.iter().any(|k| m.arg(k).is_some())
}

/// Whether `m` (a `position(d / time: t, ahead_of/behind: x)` at: all, actual) is what
/// determines the motion along the lane of an invocation `kind` with `mods` (module doc).
pub(super) fn holds_motion(kind: Action, mods: &[Modifier], m: &Modifier) -> bool {
    !m.projected && free_along(kind, mods, m)
}

/// Whether `m`, a `position(…)` at: all, is the only modifier of an invocation `kind` with
/// `mods` that sets the actor's motion along its lane (module doc).
fn free_along(kind: Action, mods: &[Modifier], m: &Modifier) -> bool {
    m.kind == ModKind::Position
        && m.at == At::All
        && kind == Action::Move
        && !mods
            .iter()
            .any(|q| !std::ptr::eq(q, m) && OWN_ALONG.contains(&q.kind) && q.at != At::Start)
}

impl Planner<'_> {
    /// Plans `m`, a relation to another actor at: all of `target` in an invocation `kind`
    /// with `mods` (`moves`: the relation may set the actor's motion; not a group's member 0,
    /// whose formation moves by its own modifiers) over its phase from `t0` (`None`: a run-time start) to `te` (if known)
    /// (module doc): the engine's hold where it determines the motion, else the plan's check
    /// once every phase is planned, or the engine's held check where the plan knows the start
    /// but not the end (after a run-time start `runtime::start_check` holds it).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn hold_relation(
        &mut self,
        m: &Modifier,
        target: &str,
        (kind, mods, moves): (Action, &[Modifier], bool),
        (t0, te): (Option<f64>, Option<f64>),
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        if !relation(m) {
            return Ok(());
        }
        if m.projected {
            return self.hold_projected(m, target, (kind, mods, moves), (t0, te), name, out);
        }
        if moves && holds_motion(kind, mods, m) {
            let hold = self.hold_gap(m, target, t0.map(|t| (t, te)), name("hold"))?;
            out.push(hold);
            return Ok(());
        }
        // x moved by the engine (a gap action's or a model's controller): the plan has no
        // track of x to check against, the engine's held check is the check. Where the actor
        // follows the lanes of several, one of them moved by the engine makes every one's the
        // engine's: its following of them all, and its held checks.
        let x = self.reference_of(m)?;
        let follows = m.kind == ModKind::Lane && follows_lanes(kind, mods, moves);
        let engine_moved = match follows {
            true => followed_lanes(mods)
                .map(|q| self.reference_of(q))
                .collect::<Result<Vec<_>, Error>>()?,
            false => vec![x.clone()],
        };
        let te = te.filter(|_| {
            !engine_moved
                .iter()
                .any(|x| self.engine_moved.contains_key(x))
        });
        match (t0, te) {
            (Some(t0), Some(te)) => {
                if follows {
                    self.follow_lanes(m, target, (&x, t0, te), name, out)?;
                }
                self.held_relations
                    .push((target.to_string(), m.clone(), t0, te));
            }
            (Some(_), None) => {
                let mut check = self.start_state(m, target)?;
                check.throughout = true;
                self.follow_lanes_at_run_time(m, target, (kind, mods, moves), t0, name, out)?;
                out.push(self.checked(check, m, target, name("check")));
            }
            // After a run-time start `runtime::start_check` holds the check.
            (None, _) => {
                self.follow_lanes_at_run_time(m, target, (kind, mods, moves), t0, name, out)?;
            }
        }
        Ok(())
    }

    /// The `lane(…: x)` at: all of a `move()`/`drive()` of `target` with no sideways motion of
    /// its own (module doc) where the plan does not know x's lane changes in the phase (a
    /// run-time start or end, or an x the engine moves): the engine follows them as they begin
    /// (oscsim's `LateralAction::FollowLanes`, counted as the check counts: `start_state`).
    /// One action for every such relation of the invocation, written at the first (`m`): the
    /// actor takes the lane counted from whichever reference just began a change, the first
    /// of them in the modifiers' order where several begin at once. From the phase start
    /// `t0` (`None`: a run-time start) the actor's lane is the engine's, not its track's
    /// (`engine_moved`, and `lane_only` where nothing else moves it: its speed and place along
    /// its lane stay the plan's), so a relation of another actor to it is the engine's to
    /// check, and a later phase of it at a time the plan sets is an error where it reads the
    /// actor's lane (`Planner::lane_blind_error`; issue 27: before, its track kept the lane of
    /// the phase start, and a later `lane(n)` was checked against that).
    fn follow_lanes_at_run_time(
        &mut self,
        m: &Modifier,
        target: &str,
        (kind, mods, moves): (Action, &[Modifier], bool),
        t0: Option<f64>,
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let first = followed_lanes(mods)
            .next()
            .is_some_and(|q| std::ptr::eq(q, m));
        if !(first && follows_lanes(kind, mods, moves)) {
            return Ok(());
        }
        let mut followed = Vec::new();
        for q in followed_lanes(mods) {
            if let Some((entity_ref, value)) = self.start_state(q, target)?.lane_of {
                followed.push(FollowedLane { entity_ref, value });
            }
        }
        let follow = PrivateAction::Lateral(LateralAction::FollowLanes(followed));
        out.push(Planned::with_phase(target, name("lanes"), follow, &m.site));
        if !self.engine_moved.contains_key(target) {
            // Its lane only: its speed and place along its lane are still the plan's.
            self.engine_moved.insert(target.to_string(), t0);
            self.lane_only.insert(target.to_string(), t0);
        }
        Ok(())
    }

    /// Plans `m`, a relation at: all with `track: projected` (§8.9.1.1.3: x read as projected
    /// from the phase start, along its lane at its speed then, in its lane then), as
    /// [`Self::hold_relation`] (module doc): where the plan knows the phase and x's track, its
    /// check at every step; else the engine's check held over the phase against x projected
    /// from the start the engine finds (after a run-time start `runtime::start_check` writes
    /// it). An actor free along its lane keeps x's speed of the start: the plan's where it
    /// knows it, else x's when the engine starts the phase (`SpeedTarget::RelativeAtStart`).
    fn hold_projected(
        &mut self,
        m: &Modifier,
        target: &str,
        (kind, mods, moves): (Action, &[Modifier], bool),
        (t0, te): (Option<f64>, Option<f64>),
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let x = self.reference_of(m)?;
        // x's speed at the start where the plan has x's track then.
        let planned = !self.engine_moved.contains_key(&x);
        let v0 = t0.filter(|_| planned).map(|t| self.track(&x).at(t).1);
        if moves && free_along(kind, mods, m) {
            let keep = match (t0, v0) {
                (Some(t0), Some(v)) => {
                    self.track_mut(target).ramp(t0, t0, v);
                    self.last_v.insert(target.to_string(), v);
                    SpeedTarget::Absolute(v)
                }
                _ => {
                    // x's speed is the engine's: so is the actor's it keeps.
                    if t0.is_some() {
                        self.engine_moves(target, t0);
                    }
                    SpeedTarget::RelativeAtStart {
                        entity_ref: x.clone(),
                        value: 0.0,
                    }
                }
            };
            let keep = speed_action(DynamicsShape::Step, 0.0, keep);
            out.push(Planned::with_phase(target, name("speed"), keep, &m.site));
        }
        match (t0, te, planned) {
            (Some(t0), Some(te), true) => {
                self.held_relations
                    .push((target.to_string(), m.clone(), t0, te));
            }
            (Some(_), _, _) => {
                let mut check = self.start_state(m, target)?;
                check.throughout = true;
                check.projected = true;
                out.push(self.checked(check, m, target, name("check")));
            }
            // After a run-time start: `runtime::start_check`'s, held and projected.
            (None, _, _) => {}
        }
        Ok(())
    }

    /// `target`'s lane changes with x's within the phase from `t0` to `te` for `m`, a
    /// `lane(…: x)` at: all of an actor with no sideways motion of its own (module doc): for
    /// each lane change of x wholly in the phase, a sinusoidal LaneChangeAction over the same
    /// span into the lane counted from x's new one, on the plan's track too.
    fn follow_lanes(
        &mut self,
        m: &Modifier,
        target: &str,
        (x, t0, te): (&str, f64, f64),
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let mut moves = self.track(x).moves_in(t0, te);
        moves.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (m0, m1) in moves {
            if m0 < t0 || m1 > te + 1e-9 || !self.changes_lane(x, m0, m1) {
                // Not wholly in the phase, or no lane change: the check's (an error).
                continue;
            }
            let Some(lane) = self.lane_asked(m, target, m1)? else {
                continue;
            };
            out.push(Planned {
                entity: target.to_string(),
                at: Some(When::At(m0)),
                name: name("lane"),
                action: PrivateAction::Lateral(LateralAction::LaneChange {
                    target_lane_offset: None,
                    dynamics: sinusoidal_over(m1 - m0),
                    target: LaneChangeTarget::Absolute(lane.to_string()),
                }),
                site: m.site.clone(),
            });
            let tr = self.track_mut(target);
            tr.set_lane(m1, lane);
            tr.add_move(m0, m1);
        }
        Ok(())
    }

    /// The engine's hold of `m` (see [`holds_motion`]) on `target` over its phase, as the
    /// action `name`: a LongitudinalDistanceAction (OpenSCENARIO 1.3 §7.7.2.1) to x, between
    /// the reference points, along the road, continuous and without limits, so the engine puts
    /// the actor d (or t at x's speed) from x at every step and gives it x's speed. Where the
    /// plan knows the phase from `t0` to `te` the actor's track takes x's speed profile.
    pub(super) fn hold_gap(
        &mut self,
        m: &Modifier,
        target: &str,
        span: Option<(f64, Option<f64>)>,
        name: String,
    ) -> Result<Planned, Error> {
        let (x, sign, _) = self.position_target(m, target, span.map_or(0.0, |s| s.0))?;
        let Some(x) = x else {
            return Err(m.site.err(
                K::Modifier,
                "expected ahead_of or behind in position(…) held at: all, found neither",
            ));
        };
        let floor = || GROUP_GAP + self.facing_overhangs(target, &x, sign < 0.0);
        let (distance, time_gap, at_least) = match (m.arg("distance"), m.arg("time"), span) {
            (Some(d), _, _) => (Some(d.number()?), None, None),
            (None, Some(t), _) => (None, Some(t.number()?), None),
            // The default gap, max(2 s · v_x, 10 m + the overhangs): the time gap where x's
            // speed at the start makes it the larger, else the distance.
            (None, None, Some((t0, _))) => {
                let floor = floor();
                match DEFAULT_TIME_GAP * self.track(&x).at(t0).1 >= floor {
                    true => (None, Some(DEFAULT_TIME_GAP), None),
                    false => (Some(floor), None, None),
                }
            }
            // After a run-time start x's speed is the engine's: the larger of the two at x's
            // speed at every step (oscsim's `at_least`), as the engine's check measures it.
            (None, None, None) => (None, Some(DEFAULT_TIME_GAP), Some(floor())),
        };
        if let Some(since) = self.engine_moved.get(&x).copied() {
            // x's motion is the engine's from `since`: so is the actor's it holds.
            let from = span.map(|s| s.0).or(since);
            self.engine_moves(target, from);
        } else if let Some((t0, te)) = span {
            let end = te.unwrap_or(f64::INFINITY);
            let xs = self.track(&x).clone();
            self.track_mut(target).follow(&xs, (t0, end), 0.0).map_err(|t| {
                m.site.err(
                    K::Unsatisfiable,
                    format!("expected `{x}`'s speed profile one `{target}` can take from {t0:.2} s (position(…) at: all), found a sinusoidal change of `{x}`'s under way then, from {t:.2} s"),
                )
            })?;
            // x's speed where the hold ends (an end the plan does not know: at the start).
            let v = xs.at(te.unwrap_or(t0)).1;
            self.last_v.insert(target.to_string(), v);
        }
        // Ahead of x: x trails (the actor leads).
        let displacement = if sign > 0.0 {
            LongitudinalDisplacement::LeadingReferencedEntity
        } else {
            LongitudinalDisplacement::TrailingReferencedEntity
        };
        let action = PrivateAction::Longitudinal(LongitudinalAction::LongitudinalDistance {
            entity_ref: x,
            continuous: true,
            distance,
            time_gap,
            freespace: false,
            displacement: Some(displacement),
            coordinate_system: Some(CoordinateSystem::Road),
            dynamic_constraints: None,
            at_start: None,
            at_least,
        });
        Ok(Planned::with_phase(target, name, action, &m.site))
    }

    /// Checks each relation of `held` on the plan's tracks at the engine's steps over its
    /// phase (module doc): an error at the modifier at the first step it does not hold.
    pub(super) fn check_held_relations(&self, held: &[HeldRelation]) -> Result<(), Error> {
        let dt = self.settings.dt;
        for (a, m, t0, te) in held {
            let steps = ((te - t0) / dt + 1e-6).floor() as usize;
            for k in 0..=steps {
                let t = t0 + k as f64 * dt;
                self.check_held_at(a, m, (*t0, t))?;
            }
        }
        Ok(())
    }

    /// Checks the relation `m` of `a` at `t` on the plan's tracks (x as projected from the
    /// phase start `t0` where `m` says so).
    fn check_held_at(&self, a: &str, m: &Modifier, (t0, t): (f64, f64)) -> Result<(), Error> {
        // Where x is read: at `t`, or projected at the start.
        let tx = if m.projected { t0 } else { t };
        if m.kind == ModKind::Lane {
            let got = self.lane_now(a, t);
            let want = self.lane_asked(m, a, tx)?;
            if want != Some(got) {
                let x = self.reference_of(m)?;
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected `{a}` in {} throughout the phase (lane(…) at: all, counted from `{x}`'s lane {} then), found it in lane {got} at {t:.2} s",
                        want.map_or("a driving lane that does not exist".to_string(), |l| format!("lane {l}")),
                        self.lane_now(&x, tx),
                    ),
                ));
            }
            return Ok(());
        }
        let (Some(x), sign, d) = self.position_target(m, a, tx)? else {
            return Ok(());
        };
        let s_x = match m.projected {
            true => {
                let (lane, s0) = (self.lane_now(&x, t0), self.s_at(&x, t0));
                let v = self.track(&x).at(t0).1;
                self.road.s_after(lane, s0, v * (t - t0))
            }
            false => self.s_at(&x, t),
        };
        let got = sign * (self.s_at(a, t) - s_x);
        if (got - d).abs() > POSITION_TOLERANCE {
            let side = if sign > 0.0 { "ahead of" } else { "behind" };
            let (va, vx) = (self.track(a).at(t).1, self.track(&x).at(tx).1);
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{a}` {d:.2} m {side} `{x}` throughout the phase (position(…) at: all, within {POSITION_TOLERANCE} m), found {got:.2} m at {t:.2} s: `{a}`'s speed {va:.2} m/s, `{x}`'s {vx:.2} m/s"),
            ));
        }
        Ok(())
    }

    /// The actor a relation (`position(…, ahead_of/behind: x)`, `lane(…: x)`) is to.
    fn reference_of(&self, m: &Modifier) -> Result<String, Error> {
        [
            "same_as", "side_of", "left_of", "right_of", "ahead_of", "behind",
        ]
        .iter()
        .find_map(|k| m.arg(k))
        .map_or_else(
            || {
                Err(m
                    .site
                    .err(K::Modifier, "expected a reference in lane(…), found none"))
            },
            |e| self.entity_of(e),
        )
    }
}
