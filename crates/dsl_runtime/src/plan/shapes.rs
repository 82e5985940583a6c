//! Movement modifiers with a `shape:` (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.4, §8.9.1.2): the
//! common shape's `target`, `rate_profile` and `rate_peak` are the dynamics of the §8.8 action
//! whose semantic clarification names that shape, so the modifier is planned as that action
//! from the phase start (`speed_actions`, `lateral_actions`), no second profile:
//!
//! | modifier | shape | planned as |
//! | --- | --- | --- |
//! | `speed(shape: s)`, `speed(v, at: end, shape: s)`, `change_speed(v, shape: s)` | `common_speed_shape` | `change_speed(target, rate_profile, rate_peak)` (§8.8.2.12 Code 100) |
//! | `acceleration(shape: s)`, `acceleration(a, at: end, shape: s)` | `common_acceleration_shape` | `change_acceleration(target, rate_profile, rate_peak)` (§8.8.2.14 Code 106) |
//! | `change_lane(n, side, shape: s)` | `common_lateral_shape` | `change_lane(num_of_lanes: n, side, offset: target, rate_profile, rate_peak)` |
//! | `lane(…, at: end, shape: s)` | `common_lateral_shape` | the same, n lanes to the side where the lane `lane` asks for is, counted at the phase start |
//! | `lateral(d, measure_by, side, at: end, shape: s)` | `common_lateral_shape` | `follow_lane(offset: o, rate_profile, rate_peak)`, o the offset `lateral` asks for (its `d`, else the shape's target) |
//! | `position(d, at: end, shape: s)`, `distance(d, shape: s)` | `common_position_shape` | the speed profile that covers the distance (`position_shape`) |
//!
//! The target is the modifier's own value when it gives one (§8.9.1.1.4 Code 79), else the
//! shape's. The change starts with the phase (§8.9.1.2: compute's time "is measured from the
//! start of the scenario phase") and, as the action's, ends when the target is reached: in a
//! phase with an end of its own it must end within it (an error otherwise, never a cut
//! profile), and it ends a phase without one. Beside a shaped modifier no other modifier may
//! change the same state variable ("using the shape structs specifies the exact values for
//! certain state variables … throughout", §8.9.1.1.4).
//!
//! Relative to another actor (`faster_than`, `slower_than`, `same_as`; `left_of`, `right_of`,
//! `side_of`; `ahead_of`, `behind`) the target is that actor's value ± the modifier's
//! (`shape_relative`); a shaped `position(…)` relative to another actor without a phase
//! duration reads x's place at the end its own timing sets (`position_shape`).

use super::lateral;
use super::planner::Planner;
use super::shape_relative::ShapedBeside;
use super::speed_actions::Slot;
use super::types::When;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Arg, At, Invoke, ModKind, Modifier, Phase, ShapeKind, Val};

/// Whether `q` changes the state variable a shape of `kind` fixes.
fn changes(q: &Modifier, kind: ShapeKind) -> bool {
    match kind {
        ShapeKind::Speed | ShapeKind::Acceleration => match q.kind {
            ModKind::ChangeSpeed | ModKind::Acceleration | ModKind::Distance => true,
            ModKind::Speed | ModKind::Position => q.at == At::End,
            _ => false,
        },
        ShapeKind::Position => match q.kind {
            ModKind::ChangeSpeed | ModKind::Acceleration | ModKind::Distance => true,
            ModKind::Speed => q.at != At::Start,
            ModKind::Position => q.at == At::End,
            _ => false,
        },
        ShapeKind::Lateral => match q.kind {
            ModKind::ChangeLane => true,
            ModKind::Lane | ModKind::Lateral => q.at == At::End,
            _ => false,
        },
    }
}

impl Planner<'_> {
    /// Plans the shaped modifier `m` of invocation `mods` for `slot`'s actor as the action its
    /// shape describes; returns when the change ends (`None`: it sets no end of its own).
    pub(super) fn plan_shaped(
        &mut self,
        p: &Phase,
        m: &Modifier,
        mods: &[Modifier],
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Some(shape) = &m.shape else {
            return Ok(None);
        };
        if let Some(q) = mods
            .iter()
            .find(|q| !std::ptr::eq(*q, m) && changes(q, shape.kind))
        {
            return Err(q.site.err(
                K::Unsatisfiable,
                format!(
                    "expected no `{}(…)` beside `{}(…)` at {}, whose {} fixes that state variable over the phase (§8.9.1.1.4), found one",
                    q.name,
                    m.name,
                    m.site.at(),
                    shape.kind.library_name()
                ),
            ));
        }
        let mut args = shape.args.clone();
        let num = |x: f64| Arg {
            site: m.site.clone(),
            path: None,
            value: Ok(Val::Num(x)),
        };
        // The modifier's own value is the target (Code 79); a shape's own target must agree.
        let own = match shape.kind {
            ShapeKind::Speed => m.arg("speed"),
            ShapeKind::Acceleration => m.arg("acceleration"),
            ShapeKind::Lateral | ShapeKind::Position => m.arg("distance"),
        };
        let given = arg(&args, "target").cloned();
        if let (Some(o), Some(g)) = (own, &given) {
            let (a, b) = (o.number()?, g.number()?);
            if (a - b).abs() > 1e-9 {
                return Err(g.site.err(
                    K::Unsatisfiable,
                    format!("expected the shape's target to agree with `{}(…)`'s own value, found {b} against {a} (SI units; give the target once)", m.name),
                ));
            }
        }
        args.retain(|(n, _)| n != "target");
        let target = match (own, given) {
            (Some(o), _) => o.clone(),
            (None, Some(g)) => g,
            // The library's default target, 0.
            (None, None) => num(0.0),
        };
        let mut reference = None;
        let mut beside_at_run_time = None;
        let kind = match (shape.kind, m.kind) {
            // Not an action's dynamics: the speed profile that covers the distance.
            (ShapeKind::Position, _) => {
                let profile = match arg(&args, "rate_profile").map(Arg::eval).transpose()? {
                    Some(Val::Enum(p)) => p,
                    _ => "none".to_string(),
                };
                let peak = arg(&args, "rate_peak").map(Arg::number).transpose()?;
                let d = target.number()?;
                // Relative to x: its place at the phase end, or without a duration at the end
                // the shape's own timing sets (`shape_relative`, `position_shape`).
                let place = match slot.len {
                    Some(_) => self.shaped_place(m, (slot.t0, slot.len), d)?,
                    None => {
                        self.shaped_place_at_rate(m, (slot.target, slot.t0), d, (&profile, peak))?
                    }
                };
                let value = place.unwrap_or(d);
                return self.plan_position_shape(m, slot, (value, &profile, peak), name);
            }
            (ShapeKind::Speed | ShapeKind::Acceleration, _) => {
                // Relative to x: x's value ± the target (`shape_relative`).
                reference =
                    self.shape_reference(m, shape.kind, (slot.t0, slot.len), target.number()?)?;
                let target = match &reference {
                    Some(r) if r.read_at.is_some() => num(r.value + r.delta),
                    // After a run-time start the engine reads x: the plan's speed (or
                    // acceleration) of x where it last knows it stands in for the checks of
                    // the arguments.
                    Some(r) if shape.kind == ShapeKind::Speed => {
                        num((self.last_v[&r.x] + r.delta).clamp(0.0, super::types::MAX_SPEED))
                    }
                    Some(r) => {
                        let a = self.track(&r.x).acceleration(self.last_known()) + r.delta;
                        let max = super::types::MAX_ACCELERATION;
                        num(a.clamp(-max, max))
                    }
                    None => target,
                };
                args.push(("target".to_string(), target));
                if shape.kind == ShapeKind::Speed {
                    Action::ChangeSpeed
                } else {
                    Action::ChangeAcceleration
                }
            }
            (ShapeKind::Lateral, ModKind::ChangeLane | ModKind::Lane) => {
                if let Some(q) = mods
                    .iter()
                    .find(|q| q.kind == ModKind::Lateral && q.at == At::End)
                {
                    return Err(q.site.err(
                        K::Unsatisfiable,
                        format!("expected the offset in the target lane as the target of `{}(…)`'s shape, found lateral(…, at: end) beside it", m.name),
                    ));
                }
                if m.kind == ModKind::Lane {
                    // The lane lane(…) asks for at the end, as so many lanes to a side.
                    let Some((n, left)) = self.lanes_to(m, slot.target, slot.t0, slot.len)? else {
                        return Ok(None);
                    };
                    args.push(("num_of_lanes".to_string(), num(n as f64)));
                    let side = Arg {
                        value: Ok(Val::Enum(if left { "left" } else { "right" }.to_string())),
                        ..num(0.0)
                    };
                    args.push(("side".to_string(), side));
                } else {
                    if let Some(n) = m.arg("lane") {
                        args.push(("num_of_lanes".to_string(), n.clone()));
                    }
                    if let Some(s) = m.arg("side") {
                        args.push(("side".to_string(), s.clone()));
                    }
                }
                args.push(("offset".to_string(), target));
                Action::ChangeLane
            }
            (ShapeKind::Lateral, _) => {
                // The offset lateral(…) asks for, in the lane the actor is in at the start.
                let t = slot.t0.unwrap_or_else(|| self.last_known());
                let lane = match slot.t0 {
                    Some(t) => self.lane_now(slot.target, t),
                    None => self.lane_last(slot.target),
                };
                let w = self.road.lane_width(lane, self.s_at(slot.target, t));
                let mut asked = m.clone();
                asked.args.retain(|(n, _)| n != "distance");
                asked.args.push(("distance".to_string(), target));
                let o = match self.shaped_beside(&asked, slot.target, (slot.t0, slot.len))? {
                    Some(ShapedBeside::Offset(o)) => o,
                    // The engine finds the lane and offset beside x (below): the plan's
                    // offset 0 stands in for the checks of the arguments.
                    Some(ShapedBeside::AtRunTime(x, dt)) => {
                        beside_at_run_time = Some((asked.clone(), x, dt));
                        0.0
                    }
                    None => lateral::lane_offset(&asked, w, self.width(slot.target))?,
                };
                args.push(("offset".to_string(), num(o)));
                Action::FollowLane
            }
        };
        let inv = Invoke {
            actor: slot.target.to_string(),
            actor_site: m.site.clone(),
            action: m.name.clone(),
            kind,
            args,
            places: Vec::new(),
            modifiers: Vec::new(),
            lane_target: None,
        };
        // The action's messages name the modifier's place.
        let at_modifier = Phase {
            site: m.site.clone(),
            ..p.clone()
        };
        if let Some(r) = reference {
            let from = (slot.out.len(), slot.persist.len());
            let t0 = slot.t0;
            let again = Slot {
                out: &mut *slot.out,
                persist: &mut *slot.persist,
                ..slot
            };
            let ends = self.plan_speed_action(&at_modifier, &inv, again, name)?;
            match (t0, &ends) {
                (None, _) => {
                    Self::retarget_at_run_time(m, &r, &mut slot.out[from.0..]);
                    Self::retarget_at_run_time(m, &r, &mut slot.persist[from.1..]);
                }
                (Some(_), Some(When::At(te))) if slot.len.is_none() => {
                    self.check_shape_reference(m, shape.kind, &r, *te)?;
                }
                _ => {}
            }
            return Ok(ends);
        }
        match kind {
            Action::ChangeLane | Action::FollowLane => {
                let Some((asked, x, dt)) = beside_at_run_time else {
                    return self.plan_lateral_action(&at_modifier, &inv, slot, name);
                };
                let from = slot.out.len();
                let again = Slot {
                    out: &mut *slot.out,
                    persist: &mut *slot.persist,
                    ..slot
                };
                let ends = self.plan_lateral_action(&at_modifier, &inv, again, name)?;
                self.beside_at_run_time(&asked, (x, dt), &mut slot.out[from..]);
                Ok(ends)
            }
            _ => self.plan_speed_action(&at_modifier, &inv, slot, name),
        }
    }
}

impl Planner<'_> {
    /// The lane `lane(…, at: end)` of `target` asks for, as (number of lanes, to the left)
    /// from the lane the actor is in at the phase start `t0` (`None`: it is in it already).
    /// The target lane is read at the end of a phase `len` long (at its start without a length
    /// of its own: the shape's change then ends it).
    fn lanes_to(
        &self,
        m: &Modifier,
        target: &str,
        t0: Option<f64>,
        len: Option<f64>,
    ) -> Result<Option<(i64, bool)>, Error> {
        let Some(t) = t0 else {
            return Err(m.site.err(
                K::Unsatisfiable,
                "expected a phase start the plan knows for lane(…, at: end) with a shape (the lanes to change are counted where the plan has the actor), found one after a run-time condition",
            ));
        };
        let (_, lane) = self.lane_target(m, target, Some(t), len.unwrap_or(0.0))?;
        let now = self.lane_now(target, t);
        let s = self.s_at(target, t);
        let Some(l) = lane.filter(|l| *l != now) else {
            return Ok(None);
        };
        let found = (1..=MAX_LANES)
            .flat_map(|n| [(n, true), (n, false)])
            .find(|(n, left)| self.road.beside(now, *left, *n, s) == Some(l));
        found.map(Some).ok_or_else(|| {
            m.site.err(
                K::Unsatisfiable,
                format!("expected lane {l} beside `{target}`'s lane {now} at s = {s:.2} m, found it on no side"),
            )
        })
    }
}

/// The most driving lanes one lane change crosses that the planner counts.
const MAX_LANES: i64 = 16;
