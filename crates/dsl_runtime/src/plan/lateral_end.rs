//! `lateral(d, side_of/left_of/right_of: x, at: end)` (ASAM OpenSCENARIO DSL 2.1 §8.9
//! `lateral`, "an actor's lateral position (t-coordinate) relative to the road or another
//! actor", with `at: end`: the constraint holds at the end of the phase): a lateral target for
//! the actor at the phase end, where the plan has x then.
//!
//! x's t at the phase end is read from x's planned track (its lane and offset then, after any
//! sideways move x makes in the phase), the actor's t from it as `lateral::beside` says, and
//! that t becomes the motion `lateral(…, at: end)` without a reference already plans: in the
//! actor's own lane, a sinusoidal LaneOffsetAction over the phase; in another driving lane, a
//! sinusoidal LaneChangeAction over the phase into the lane that holds that t, at the offset
//! from its centre; beside a lane change of the phase (`change_lane`, `lane(…, at: end)`), the
//! offset in the lane change's target lane, which must hold that t.
//!
//! After a run-time start, with `track: projected` (§8.9.1.1.3: x projected from its state at
//! the phase start, so x's t then), the engine's sinusoidal LaneChangeAction over the phase to
//! a target beside x (`scenario::LaneChangeTarget::Beside`): the lane of the actor's road that
//! holds x's t at the start plus the t asked, found when the action starts (none: an error
//! record and a failed run). With `track: actual` (x's sideways moves in the phase are x's
//! then) the engine's blend to a moving target (`Beside` with `follow`, engine
//! `actions::lateral_follow`): t(τ) = (1 − f)·t₀ + f·(t_x(τ) + d), f the sinusoid over the
//! phase, so the actor ends at x's t at the phase end plus d. A modifier that keeps the lane
//! beside it (`keep_lane()`, `lane(…)` at: all) is the engine's check at the phase end that
//! the actor is in the lane kept (`runtime_end`). Beside a lane change of the phase
//! (`change_lane(n, side)`, `lane(n, at: end)`) the same action, and the engine's check at the
//! phase end that the actor is in the change's target lane (`change_lane`: n lanes to its side
//! of the lane it had at the start, which a mark notes; `lane(n)`: that lane; a lane relative to
//! another actor y, `lane(same_as/side_of/left_of/right_of: y, at: end)`: so many lanes from
//! y's lane at the phase end, oscsim's StateCheck `lane_of`): the lane the t asked lies in is
//! the engine's to find, and a t outside the change's lane an error record.
//! On a plan over several roads the target names the plan's roads (`Beside::roads`): x may be
//! on another of them, its t compared with the actor's where their reference lines join
//! continuously (engine `RoadChain::lateral_compares`).

use scenario::{
    DynamicsShape, LaneChangeTarget, LaneOffsetTarget, LateralAction, PrivateAction, StateCheck,
};

use super::lateral;
use super::motion::{check_accel, sinusoid_peak_acceleration, sinusoidal_over};
use super::planner::Planner;
use super::types::Planned;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::Modifier;

impl Planner<'_> {
    /// t of `target`'s reference point at the phase end `t + len` that `m` (a `lateral(…, at:
    /// end)` beside another actor) asks for, from x's planned track; `None` when `m` has no
    /// reference. `t` is the phase start, one the plan knows (after a run-time condition the
    /// engine reads x: `beside_after_runtime_start`).
    pub(super) fn beside_end(
        &self,
        m: &Modifier,
        target: &str,
        t: f64,
        len: f64,
    ) -> Result<Option<f64>, Error> {
        // A member of a group over several lanes ends at its slot in the block as it is at the
        // phase start (`beside_slot`).
        let Some((x, dt)) = self.beside_slot(m, target, t)? else {
            return Ok(None);
        };
        if !m.projected {
            return Ok(Some(self.t_at(&x, t + len) + dt));
        }
        // Projected (§8.9.1.1.3): x keeps the t it has at the start, which needs it not moving
        // sideways then (a projection at its lateral speed would leave the road).
        if let Some(from) = self.track(&x).moving_in(t, t) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{x}` not moving sideways at the phase start for lateral(…, at: end, track: projected), found it moving from {from:.2} s"),
            ));
        }
        Ok(Some(self.t_at(&x, t) + dt))
    }

    /// The offset from the centre of `lane` (the target lane of the phase's lane change) at the
    /// phase end that `m`, a `lateral(…, at: end)`, asks for: in that lane, or beside another
    /// actor where the plan has it then (the t asked must lie in `lane`).
    pub(super) fn end_offset_in(
        &self,
        m: &Modifier,
        target: &str,
        lane: i32,
        t: Option<f64>,
        len: f64,
    ) -> Result<f64, Error> {
        let s_end = t.map_or(0.0, |t| self.s_at(target, t + len));
        let w = self.road.lane_width(lane, s_end);
        // After a run-time start a reference is the engine's (`beside_with_lane_change`,
        // planned before this is asked).
        let Some(t_a) = t
            .map(|t| self.beside_end(m, target, t, len))
            .transpose()?
            .flatten()
        else {
            return super::lateral::lane_offset(m, w, self.width(target));
        };
        let o = t_a - self.road.lane_center(lane, s_end);
        if o.abs() > w / 2.0 + 1e-9 {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{target}`'s reference point in the lane change's target lane {lane} ({w:.2} m wide) at the phase end, found lateral(…) puts it {o:.2} m from the lane's centre"),
            ));
        }
        Ok(o)
    }

    /// Plans `m`, a `lateral(…, at: end)` beside another actor without a lane change in the
    /// phase, over the phase from `t` (known) to `t + len`, as the action `name`: a lane offset
    /// in the actor's lane or a lane change into the lane holding the t asked (module doc).
    /// Without a reference `m` asks for nothing here (it is an offset in the lane). `keeps`
    /// is a modifier of the phase that keeps the actor in its lane (`keep_lane()`, `lane(…)`
    /// at: all): a t in another lane is then an error.
    pub(super) fn plan_beside_end(
        &mut self,
        m: &Modifier,
        target: &str,
        (t, len): (Option<f64>, f64),
        keeps: Option<&Modifier>,
        name: String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        if t.is_none() {
            // A lane kept beside it is the engine's check at the phase end (`runtime_end`).
            return self.beside_after_runtime_start(m, target, len, name, out);
        }
        // After a run-time start (above) the engine's; here a start the plan knows.
        let t = t.unwrap_or_default();
        let Some(t_a) = self.beside_end(m, target, t, len)? else {
            return Ok(());
        };
        let te = t + len;
        let s_end = self.s_at(target, te);
        let lane0 = self.lane_now(target, t);
        let lane = self.road.lane_holding(s_end, t_a).ok_or_else(|| {
            m.site.err(
                K::Unsatisfiable,
                format!("expected a driving lane at t = {t_a:.2} m (where lateral(…) puts `{target}` at the phase end, s = {s_end:.2} m), found none"),
            )
        })?;
        if let (Some(k), true) = (keeps, lane != lane0) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to stay in lane {lane0} ({}(…) at {}), found lateral(…) puts it in lane {lane} at the phase end", k.name, k.site.at()),
            ));
        }
        let o1 = t_a - self.road.lane_center(lane, s_end);
        check_accel(
            m,
            sinusoid_peak_acceleration(t_a - self.t_at(target, t), len),
        )?;
        let action = if lane == lane0 {
            let o0 = self.track(target).offset(t);
            let a = sinusoid_peak_acceleration(o1 - o0, len);
            if a == 0.0 {
                None
            } else {
                // Given as the action's maximum, the engine's sinusoidal change lasts T.
                Some(LateralAction::LaneOffset {
                    continuous: false,
                    dynamics_shape: DynamicsShape::Sinusoidal,
                    max_lateral_acc: Some(a),
                    target: LaneOffsetTarget::Absolute(o1),
                })
            }
        } else {
            Some(LateralAction::LaneChange {
                target_lane_offset: Some(o1),
                dynamics: sinusoidal_over(len),
                target: LaneChangeTarget::Absolute(lane.to_string()),
            })
        };
        let tr = self.track_mut(target);
        tr.set_lane(te, lane);
        tr.set_offset(te, o1);
        if let Some(action) = action {
            tr.add_move(t, te);
            out.push(Planned::with_phase(
                target,
                name,
                PrivateAction::Lateral(action),
                &m.site,
            ));
        }
        Ok(())
    }

    /// `q`, a `lateral(…, at: end)` beside another actor, beside the lane change `c` (its
    /// target `lane`) of `target` after a run-time start, over `len` s (`names`: the lateral
    /// action and the lane check): the engine's move beside x (`beside_after_runtime_start`),
    /// and its check at the phase end (in `after`) that the actor is in the change's target
    /// lane: for `change_lane` n lanes to its side of the lane it had at the start (a mark
    /// notes it then), for `lane(n, at: end)` that lane, for a lane relative to another actor
    /// y the lane so many lanes from y's lane at the phase end. `false` when `q` has no
    /// reference (an offset in the lane, planned with the change).
    pub(super) fn beside_with_lane_change(
        &self,
        q: &Modifier,
        (c, lane): (&Modifier, LaneChangeTarget),
        target: &str,
        len: f64,
        (lateral_name, lane_name): (String, String),
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<bool, Error> {
        if lateral::reference(q)?.is_none() {
            return Ok(false);
        }
        let check = match lane {
            LaneChangeTarget::Relative { entity_ref, value } if entity_ref == target => {
                out.push(self.mark_check(c, target, lane_name.clone(), None));
                StateCheck {
                    lane_at_mark: Some((lane_name.clone(), value)),
                    ..StateCheck::default()
                }
            }
            LaneChangeTarget::Absolute(l) => {
                let l = l.parse().map_err(|_| {
                    c.site.err(
                        K::Value,
                        format!("expected a lane id of the road, found `{l}`"),
                    )
                })?;
                StateCheck {
                    lane: Some((self.road.id().to_string(), l)),
                    ..StateCheck::default()
                }
            }
            // Relative to another actor x (lane(same_as/side_of/…: x, at: end), change_lane
            // with a reference): x's lane at the phase end, counted as the change counts.
            LaneChangeTarget::Relative { entity_ref, value } => StateCheck {
                lane_of: Some((entity_ref, value)),
                ..StateCheck::default()
            },
            // `lane_target` makes no other.
            other => {
                return Err(c.site.err(
                    K::Modifier,
                    format!("expected a lane target of `{target}`'s lane change, found {other:?}"),
                ))
            }
        };
        self.beside_after_runtime_start(q, target, len, lateral_name, out)?;
        after.push(self.end_check(c, target, format!("{lane_name}.end"), check));
        Ok(true)
    }

    /// `m` beside x after a run-time start, over `len` s: with `track: projected` the engine's
    /// sinusoidal lane change to the lane holding x's t at the start plus the t `m` asks for
    /// (`LaneChangeTarget::Beside`); with `track: actual` the engine's sinusoidal blend to x's
    /// t at every step plus that t (`Beside` with `follow`).
    fn beside_after_runtime_start(
        &self,
        m: &Modifier,
        target: &str,
        len: f64,
        name: String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        // A member of a group over several lanes: its slot as the plan last knows the block.
        let Some((x, dt)) = self.beside_slot(m, target, self.last_known())? else {
            return Ok(());
        };
        let change = LateralAction::LaneChange {
            target_lane_offset: None,
            dynamics: sinusoidal_over(len),
            target: LaneChangeTarget::Beside {
                entity_ref: x,
                t: dt,
                what: format!("{}(…) at {}", m.name, m.site.at()),
                // Actual: x's t at every step (engine actions::lateral_follow).
                follow: !m.projected,
                // x on another of the plan's roads: t compares across their joints.
                roads: self.chain(),
            },
        };
        out.push(Planned::with_phase(
            target,
            name,
            PrivateAction::Lateral(change),
            &m.site,
        ));
        Ok(())
    }
}
