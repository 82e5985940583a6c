//! A shaped modifier relative to another actor (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.4 with
//! §8.9's reference objects): `speed(shape: s, faster_than/slower_than/same_as: x)`,
//! `acceleration(shape: s, faster_than/slower_than/same_as: x)`, `lateral(d, left_of/right_of/
//! side_of: x, at: end, shape: s)`, `position(d, ahead_of/behind: x, at: end, shape: s)` (x's s
//! at the phase end ± d, the position the shape's profile covers the distance to; without a
//! duration at the end the shape's timing sets, `position_shape`).
//!
//! The standard: the shape's target "can be taken from" the modifier (Code 79), and the
//! modifier's value relative to x is "the speed [acceleration, lateral position] of the actor
//! relative to" x's. oscsim's choice, where §8.9.1.1.4 says nothing of a reference: the shape
//! is the action's dynamics as without a reference (`shapes`), and its target is the state
//! variable the modifier asks for, x's ± the value (`same_as`: x's), read from x as the
//! modifier's `at` and `track` say (§8.9.1.1.1, §8.9.1.1.3): a shaped modifier holds at the
//! end of the phase, so with `track: actual` (the default) x's value where the phase ends, with
//! `track: projected` x's as the phase starts, fixed. Where the change itself ends the phase
//! (no duration of its own) x's value at that end depends on the target: x's value at the
//! start is taken and must still be x's where the change ends (an error naming x's value
//! there otherwise, never a target that misses the constraint silently).
//!
//! After a run-time start a shaped `lateral(…)` beside x with `track: projected` is the
//! engine's lane change with the shape's dynamics to the lane and offset beside x where x is as
//! it starts (`LaneChangeTarget::Beside`); with `track: actual` the engine's move beside a
//! moving x (`LaneChangeTarget::Beside` following) with the shape's dynamics: its rate profile
//! from the actor's t to x's t at each step plus d, then x's t plus d held until the phase
//! ends. An acceleration shape relative to x there
//! is oscsim's RelativeAccelerationAction with the shape's dynamics as its transition, to x's
//! acceleration ± the value as the engine reads it (actual: over each step, followed;
//! projected: over the first step, fixed); after a change at a rate, the held acceleration is
//! x's ± the value followed (actual) or the one reached, kept (projected).
//! After a run-time start a speed shape is the engine's SpeedAction with the shape's dynamics
//! to x's speed ± the value as the engine reads it: actual, a RelativeTargetSpeed read at each
//! step (not continuous: the change ends where it meets it); projected, oscsim's
//! RelativeAtStart target (x's speed as the action starts, fixed).

use scenario::{
    LaneChangeTarget, LateralAction, LongitudinalAction, PrivateAction, SpeedTarget,
    SpeedTargetValueType,
};

use super::lateral;
use super::planner::Planner;
use super::types::Planned;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Modifier, ShapeKind};

/// The value a relative shape's target differs from x's by, per unit of the modifier's own
/// value: `faster_than` +1, `slower_than` −1, `same_as` 0 (x's value itself).
const RELATIONS: [(&str, f64); 3] = [
    ("faster_than", 1.0),
    ("slower_than", -1.0),
    ("same_as", 0.0),
];

/// Tolerance of x's speed (m/s) or acceleration (m/s²) being the same at the change's start
/// and end, where the change ends its phase.
const HOLDS_TOL: f64 = 1e-6;

/// How far about a moment x's acceleration pieces are read (s): the piece that starts there at
/// the phase start, the one that ends there after it.
const READ_SPAN: f64 = 1e-6;

/// The reference of a `position(d, ahead_of/behind: x)` and the sign of d from x's s (ahead
/// +1, behind −1); `None` without one.
pub(super) fn place_reference(m: &Modifier) -> Option<(&crate::resolve::Arg, f64)> {
    match (m.arg("ahead_of"), m.arg("behind")) {
        (Some(e), _) => Some((e, 1.0)),
        (None, Some(e)) => Some((e, -1.0)),
        (None, None) => None,
    }
}

/// Where a shaped `lateral(…)` beside x puts the actor.
pub(super) enum ShapedBeside {
    /// The offset from the centre of the actor's own lane at the phase end (a known start).
    Offset(f64),
    /// After a run-time start: x and the actor's t minus x's, the engine's to find as the
    /// change starts (projected) or at every step (actual).
    AtRunTime(String, f64),
}

/// A shaped speed or acceleration modifier's reference x and how the target follows from it.
pub(super) struct Reference {
    /// x.
    pub x: String,
    /// Added to x's value (m/s or m/s²).
    pub delta: f64,
    /// When the plan reads x's value (`None`: after a run-time start, the engine's).
    pub read_at: Option<f64>,
    /// x's value where the plan reads it.
    pub value: f64,
}

impl Planner<'_> {
    /// The reference of `m`, a speed or acceleration modifier with a shape of `kind`, over the
    /// phase `(t0, len)` of `target`, `own` the modifier's value (its own or the shape's target);
    /// `None` without one.
    pub(super) fn shape_reference(
        &self,
        m: &Modifier,
        kind: ShapeKind,
        (t0, len): (Option<f64>, Option<f64>),
        own: f64,
    ) -> Result<Option<Reference>, Error> {
        let Some((e, sign)) = RELATIONS
            .iter()
            .find_map(|(key, sign)| m.arg(key).map(|e| (e, *sign)))
        else {
            return Ok(None);
        };
        let x = self.entity_of(e)?;
        let delta = sign * own;
        let Some(t) = t0 else {
            return Ok(Some(Reference {
                x,
                delta,
                read_at: None,
                value: 0.0,
            }));
        };
        // At the phase end (at: end) where the plan knows it, else at the start.
        let at = match len {
            Some(l) if !m.projected => t + l,
            _ => t,
        };
        let value = self.value_of(e, &x, kind, (at, at > t))?;
        Ok(Some(Reference {
            x,
            delta,
            read_at: Some(at),
            value,
        }))
    }

    /// x's planned speed or acceleration at `at` (an acceleration: of the piece that ends
    /// there when `before`, else of the one that starts there).
    fn value_of(
        &self,
        e: &crate::resolve::Arg,
        x: &str,
        kind: ShapeKind,
        (at, before): (f64, bool),
    ) -> Result<f64, Error> {
        if kind != ShapeKind::Acceleration {
            return Ok(self.track(x).at(at).1);
        }
        let (a, b) = if before {
            (at - READ_SPAN, at)
        } else {
            (at, at + READ_SPAN)
        };
        let pieces = self
            .track(x)
            .acceleration_pieces(a, b)
            .map_err(|from| {
                e.site.err(
                    K::Unsatisfiable,
                    format!("expected `{x}`'s planned acceleration constant about {at:.2} s to read it, found it changing continuously (or a step of speed) from {from:.2} s"),
                )
            })?;
        Ok(pieces.last().map_or(0.0, |p| p.2))
    }

    /// Checks that x's value where the shaped change of `m` ends, `te`, is still the one the
    /// target was read from at the phase start (`r`), where the change ends the phase.
    pub(super) fn check_shape_reference(
        &self,
        m: &Modifier,
        kind: ShapeKind,
        r: &Reference,
        te: f64,
    ) -> Result<(), Error> {
        let Some(at) = r.read_at.filter(|at| te > *at + 1e-9 && !m.projected) else {
            return Ok(());
        };
        let e = RELATIONS
            .iter()
            .find_map(|(key, _)| m.arg(key))
            .unwrap_or_else(|| unreachable!("a reference was read from one of RELATIONS"));
        let there = self.value_of(e, &r.x, kind, (te, true))?;
        if (there - r.value).abs() > HOLDS_TOL {
            let what = match kind {
                ShapeKind::Acceleration => "acceleration (m/s²)",
                _ => "speed (m/s)",
            };
            return Err(e.site.err(
                K::Unsatisfiable,
                format!("expected `{}`'s planned {what} where `{}(…)`'s shaped change ends its phase ({te:.2} s) to be the {:.2} its target was read from at {at:.2} s, found {there:.2} (give the phase a duration, or track: projected)", r.x, m.name, r.value),
            ));
        }
        Ok(())
    }

    /// After a run-time start, the planned speed change of a shaped `speed(…)` relative to x
    /// (`out[from..]`) aims at x's speed ± the value as the engine reads it, and the planned
    /// acceleration change of a shaped `acceleration(…)` at x's acceleration ± the value
    /// (module doc).
    pub(super) fn retarget_at_run_time(m: &Modifier, r: &Reference, out: &mut [Planned]) {
        Self::reaccelerate_at_run_time(m, r, out);
        let to = if m.projected {
            SpeedTarget::RelativeAtStart {
                entity_ref: r.x.clone(),
                value: r.delta,
            }
        } else {
            SpeedTarget::Relative {
                entity_ref: r.x.clone(),
                value: r.delta,
                speed_target_value_type: SpeedTargetValueType::Delta,
                continuous: false,
            }
        };
        for p in out {
            match &mut p.action {
                PrivateAction::Longitudinal(LongitudinalAction::Speed { target, .. }) => {
                    *target = to.clone();
                }
                PrivateAction::Check(check) => {
                    if let Some((target, ..)) = &mut check.speed_change {
                        *target = to.clone();
                    }
                }
                _ => {}
            }
        }
    }

    /// After a run-time start, the planned `change_acceleration` of a shaped `acceleration(…)`
    /// relative to x (`out`): its change (the transition, over a duration or at a rate) is
    /// oscsim's RelativeAccelerationAction with that transition to x's acceleration ± the
    /// value (actual: followed in every step; projected: as over the first step, fixed), and
    /// the acceleration held after a change at a rate (the step started when it ends) follows
    /// x's ± the value (actual) or keeps the one reached (projected).
    fn reaccelerate_at_run_time(m: &Modifier, r: &Reference, out: &mut [Planned]) {
        for p in out {
            let PrivateAction::Longitudinal(LongitudinalAction::Acceleration {
                target,
                dynamics,
                ends_at_target,
            }) = &mut p.action
            else {
                continue;
            };
            let (transition, ends) = match (p.at.is_some(), m.projected) {
                // The hold after a change at a rate: the acceleration the change reached,
                // kept (the engine hands it on).
                (true, true) => {
                    *target = None;
                    continue;
                }
                // x's acceleration ± the value, followed from the hold's start.
                (true, false) => (None, false),
                (false, _) => (Some(*dynamics), *ends_at_target),
            };
            p.action = PrivateAction::Longitudinal(LongitudinalAction::RelativeAcceleration {
                entity_ref: r.x.clone(),
                value: r.delta,
                continuous: !m.projected,
                to_speed: None,
                transition,
                ends_at_target: ends,
            });
        }
    }

    /// The s a shaped `position(d, ahead_of/behind: x, at: end)` asks `m`'s actor to reach at
    /// the end of the phase `(t0, len)` (a start and a duration the plan knows), `d` the
    /// modifier's distance (or the shape's target): x's s then ± d, x's planned s with `track:
    /// actual`, its s at the start plus its speed then times `len` with `projected` (along its
    /// lane, §8.9.1.1.3); `None` without a reference.
    pub(super) fn shaped_place(
        &self,
        m: &Modifier,
        (t0, len): (Option<f64>, Option<f64>),
        d: f64,
    ) -> Result<Option<f64>, Error> {
        let Some((e, sign)) = place_reference(m) else {
            return Ok(None);
        };
        let x = self.entity_of(e)?;
        let (Some(t), Some(len)) = (t0, len) else {
            return Err(e.site.err(
                K::Unsatisfiable,
                format!("expected a phase start and duration the plan knows for `{}(…)` with a shape relative to `{x}`, found none (x's place at the end is read from the plan)", m.name),
            ));
        };
        let s_x = if m.projected {
            self.s_at(&x, t) + self.track(&x).at(t).1 * len
        } else {
            self.s_at(&x, t + len)
        };
        Ok(Some(s_x + sign * d))
    }

    /// The offset from the centre of `target`'s lane that a shaped `lateral(d, left_of/
    /// right_of/side_of: x, at: end)`, `d` the shape's target, asks for at the end of the phase
    /// `(t, len)` (a start the plan knows; without a length, x must not move sideways then:
    /// the change ends the phase where x is at its start). The t asked must be in the lane the
    /// actor keeps: a shaped lateral is `follow_lane(offset: …)`'s dynamics (`shapes`).
    pub(super) fn shaped_beside(
        &self,
        m: &Modifier,
        target: &str,
        (t0, len): (Option<f64>, Option<f64>),
    ) -> Result<Option<ShapedBeside>, Error> {
        let Some((e, _)) = lateral::reference(m)? else {
            return Ok(None);
        };
        let x = self.entity_of(e)?;
        let Some(t) = t0 else {
            return Ok(self
                .beside_slot(m, target, self.last_known())?
                .map(|(x, dt)| ShapedBeside::AtRunTime(x, dt)));
        };
        let len = match len {
            Some(l) => l,
            None => {
                if let Some(from) = self.track(&x).moving_in(t, f64::INFINITY) {
                    return Err(e.site.err(
                        K::Unsatisfiable,
                        format!("expected `{x}` not moving sideways from the phase start for lateral(…, shape: …) beside it in a phase the change ends (x's place at the end depends on the change), found it moving from {from:.2} s (give the phase a duration)"),
                    ));
                }
                0.0
            }
        };
        let Some(t_a) = self.beside_end(m, target, t, len)? else {
            return Ok(None);
        };
        let s_end = self.s_at(target, t + len);
        let lane = self.lane_now(target, t);
        let o = t_a - self.road.lane_center(lane, s_end);
        let w = self.road.lane_width(lane, s_end);
        if o.abs() > w / 2.0 + 1e-9 {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{target}`'s reference point in its lane {lane} ({w:.2} m wide) for lateral(…, shape: …) beside `{x}` (the shape is follow_lane's offset in the lane), found it {o:.2} m from the lane's centre (write change_lane(…, shape: …) to change lanes)"),
            ));
        }
        Ok(Some(ShapedBeside::Offset(o)))
    }

    /// After a run-time start, the planned lane change of a shaped `lateral(…)` beside x
    /// (`out`, follow_lane's change within the lane) aims at the lane and offset that put the
    /// actor `dt` to x's left (`LaneChangeTarget::Beside`), with the shape's dynamics: where x
    /// is as the change starts (`track: projected`, found by the engine then), or where x is
    /// at every step (`actual`, the engine's following of x, then held).
    pub(super) fn beside_at_run_time(
        &self,
        m: &Modifier,
        (x, dt): (String, f64),
        out: &mut [Planned],
    ) {
        for p in out {
            if let PrivateAction::Lateral(LateralAction::LaneChange {
                target_lane_offset,
                target,
                ..
            }) = &mut p.action
            {
                *target_lane_offset = None;
                *target = LaneChangeTarget::Beside {
                    entity_ref: x.clone(),
                    t: dt,
                    what: format!("{}(…) at {}", m.name, m.site.at()),
                    // Actual: x's t at every step (engine actions::lateral_follow).
                    follow: !m.projected,
                    roads: self.chain(),
                };
            }
        }
    }
}
