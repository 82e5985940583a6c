//! `lateral(d, side_of/left_of/right_of: x)` at: all (ASAM OpenSCENARIO DSL 2.1 §8.9
//! `lateral`: "an actor's lateral position (t-coordinate) relative to the road or another
//! actor"; §8.9.1.1.1 `at: all`: the constraint holds throughout the phase) where x moves
//! sideways in the phase, at a phase start the plan knows.
//!
//! With `track: actual` (the default; §8.9.1.1.3 "the vehicle reacts to the behavior of the
//! referenced vehicle") the actor's t is x's t plus the t asked at every step: the engine's
//! lane change beside a moving entity (`scenario::LaneChangeTarget::Beside` with `follow`, no
//! XML form) with a step shape, engine `actions::lateral_follow`: no transition, the target x's
//! t at each step's end plus d, held until the phase's Act stops it (the actor is beside x at
//! the phase start already: placed there in its first phase, checked at a later one). Its
//! offset from its lane's centre follows x's lateral position, and where x's t plus d leaves
//! the actor's lane, it is in the lane that holds it (the engine's blend of the two lanes). The
//! plan mirrors each sideways move of x in the phase on the actor's track (the lane holding x's
//! t plus d where the move ends, the offset from its centre), so later phases start from there;
//! once every phase is planned, x's moves in the phase must all be mirrored (x's invocation
//! planned after the actor's in another branch: an error naming the move).
//!
//! With `track: projected` x is projected from its state at the phase start, keeping its t:
//! the actor keeps x's t at the start plus d, so only the actor must not move sideways then
//! (x may). Either way a sideways move of the actor's own in the phase is an error (checked
//! once every phase is planned, `beside_checks`).
//!
//! After a run-time start (the plan does not know whether x moves in the phase) the engine
//! checks t − t_x at the phase start (`runtime`) and, with `track: actual`, follows x as here
//! from then on (`follow_beside`), beside its check of t − t_x held over the phase (§8.9.1.1.1,
//! `runtime::start_check`); x on another of the plan's roads is followed where their reference
//! lines join continuously (engine `lateral_follow::target_t`), else an error record and a
//! failed run. With `track: projected` only the check at the start, as before.
//!
//! A member of a group over several lanes (a block beside x) keeps its own slot: x's t plus d
//! plus its place across from member 0's (`Planner::beside_slot`), at a known start as the
//! block is then, after a run-time start as the plan last knows it; the check and following
//! above are each member's own at that slot.

use scenario::{DynamicsShape, LaneChangeTarget, LateralAction, PrivateAction};

use super::motion::sinusoidal_over;
use super::planner::Planner;
use super::types::{Planned, LATERAL_TOLERANCE};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::Modifier;

/// `lateral(…)` at: all beside x that the engine follows: (actor, x, phase start, phase end if
/// known, the actor's t minus x's, the modifier), checked once every phase is planned.
pub(crate) type BesideFollow = (String, String, f64, Option<f64>, f64, Site);

impl Planner<'_> {
    /// Plans `m`, a `lateral(…)` at: all beside another actor, over the phase from `t0`
    /// (known) to `te` (if known) for `target`, as the action `name` (module doc): the checks
    /// once every phase is planned, and with `track: actual` the engine's following of x
    /// where x moves sideways in the phase.
    pub(super) fn plan_beside_all(
        &mut self,
        m: &Modifier,
        target: &str,
        (t0, te): (f64, Option<f64>),
        name: String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        // A member of a group over several lanes keeps its slot in the block (`beside_slot`).
        let Some((x, dt)) = self.beside_slot(m, target, t0)? else {
            return Ok(());
        };
        // The actor's own sideways moves contradict the constraint either way.
        let (who, held) = (target.to_string(), (t0, te, m.site.clone()));
        let end = te.unwrap_or(f64::INFINITY);
        if m.projected || self.track(&x).moving_in(t0, end).is_none() {
            // x keeps its t (projected: as it is at the start): so must the actor.
            let checked = if m.projected { who.clone() } else { x };
            self.beside_checks
                .push((who, checked, held.0, held.1, held.2));
            return Ok(());
        }
        if let Some(from) = self.track(target).moving_in(t0, end) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to keep beside `{x}` while this lateral(…) holds (at: all), found `{target}` moving sideways of its own from {from:.2} s"),
            ));
        }
        self.mirror_moves(m, target, &x, (t0, end), dt)?;
        self.beside_follows
            .push((who, x.clone(), t0, te, dt, m.site.clone()));
        out.push(self.follow_beside(m, target, x, dt, name));
        Ok(())
    }

    /// The reference x of `m`, a `lateral(…)` beside another actor, and the t of `target`
    /// less x's it asks for with the block at `t` (`beside_gap`): for a member after the first
    /// of a group over several lanes, x's t plus d plus its place across from member 0's at
    /// `t` (`block_offset`), its slot in the block; for any other actor x's t plus d. At a
    /// phase start the plan knows `t` is that start; at one the engine finds (a run-time
    /// condition), the plan's last known time: the block as the plan last knows it, which the
    /// engine's check at the start holds each member to (`runtime::start_state`).
    pub(super) fn beside_slot(
        &self,
        m: &Modifier,
        target: &str,
        t: f64,
    ) -> Result<Option<(String, f64)>, Error> {
        Ok(self
            .beside_gap(m, target)?
            .map(|(x, dt)| (x, dt + self.block_offset(target, t).unwrap_or(0.0))))
    }

    /// For a member after the first of a group over several lanes (`Planner::across`): its
    /// place across the road less member 0's at `t` (m, + to the left), its slot in the block.
    /// A lateral position beside another actor is the group's, member 0's (as a group's
    /// relation at: all is member 0's, `held_relation`), and every other member keeps its slot
    /// (docs/dsl.md "Groups"). `None` for any other actor.
    pub(super) fn block_offset(&self, target: &str, t: f64) -> Option<f64> {
        let first = self.block_first(target)?;
        Some(self.t_at(target, t) - self.t_at(first, t))
    }

    /// Member 0 of the group over several lanes of which `target` is a later member.
    fn block_first(&self, target: &str) -> Option<&String> {
        self.across
            .iter()
            .filter_map(|g| self.groups.get(g))
            .find(|ms| ms.iter().skip(1).any(|m| m == target))?
            .first()
    }

    /// The engine's following of x at `dt` to its left for `m` of `target`, as the action
    /// `name`: its lane change beside a moving entity with a step shape, held until the
    /// phase's Act stops it (module doc).
    pub(super) fn follow_beside(
        &self,
        m: &Modifier,
        target: &str,
        x: String,
        dt: f64,
        name: String,
    ) -> Planned {
        Planned::with_phase(
            target,
            name,
            PrivateAction::Lateral(LateralAction::LaneChange {
                target_lane_offset: None,
                // A step: no transition, x's t plus d at every step until the phase ends.
                dynamics: scenario::TransitionDynamics {
                    dynamics_shape: DynamicsShape::Step,
                    ..sinusoidal_over(0.0)
                },
                target: LaneChangeTarget::Beside {
                    entity_ref: x,
                    t: dt,
                    what: format!("{}(…) at {}", m.name, m.site.at()),
                    follow: true,
                    roads: self.chain(),
                },
            }),
            &m.site,
        )
    }

    /// Writes x's sideways moves within `(t0, end)` on `target`'s track, `dt` to x's left.
    fn mirror_moves(
        &mut self,
        m: &Modifier,
        target: &str,
        x: &str,
        (t0, end): (f64, f64),
        dt: f64,
    ) -> Result<(), Error> {
        let mut moves: Vec<(f64, f64)> = self.track(x).moves_in(t0, end);
        moves.sort_by(|a, b| a.1.total_cmp(&b.1));
        for (m0, m1) in moves {
            if m1 > end + 1e-9 {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!("expected `{x}`'s sideways move from {m0:.2} s to end within the phase while lateral(…) beside it holds (at: all), found it ending at {m1:.2} s, after the phase's end at {end:.2} s"),
                ));
            }
            let s = self.s_at(target, m1);
            let t = self.t_at(x, m1) + dt;
            let lane = self.road.lane_holding(s, t).ok_or_else(|| {
                m.site.err(
                    K::Unsatisfiable,
                    format!("expected a driving lane at t = {t:.2} m (where lateral(…) puts `{target}` beside `{x}` at {m1:.2} s, s = {s:.2} m), found none"),
                )
            })?;
            let offset = t - self.road.lane_center(lane, s);
            let changes = self.lane_now(target, m1) != lane;
            let tr = self.track_mut(target);
            if changes {
                tr.set_lane(m1, lane);
            }
            tr.set_offset(m1, offset);
            tr.add_move(m0.max(t0), m1);
        }
        Ok(())
    }
}

/// Checks, once every phase is planned, that every sideways move of x within a phase in which
/// the actor follows it is on the actor's track (`follows`): t_a − t_x is the t asked at each
/// move's end.
pub(super) fn check_beside_follows(p: &Planner<'_>, follows: &[BesideFollow]) -> Result<(), Error> {
    for (a, x, t0, te, dt, site) in follows {
        let end = te.unwrap_or(f64::INFINITY);
        for (_, m1) in p.track(x).moves_in(*t0, end) {
            let got = p.t_at(a, m1) - p.t_at(x, m1);
            if (got - dt).abs() > LATERAL_TOLERANCE {
                return Err(site.err(
                    K::Unsatisfiable,
                    format!("expected `{a}` {dt:.2} m to the left of `{x}` when `{x}`'s sideways move ends at {m1:.2} s (lateral(…) at: all), found {got:.2} m: `{x}`'s move is planned after this phase (write `{x}`'s invocation before `{a}`'s)"),
                ));
            }
        }
    }
    Ok(())
}
