//! The actions that control a vehicle's lateral position (ASAM OpenSCENARIO DSL 2.1 §8.8.3.3
//! `change_lane`, §8.8.3.2 `follow_lane`), as the standard's tables say when each starts and
//! ends:
//!
//! | action | lowered to | ends |
//! | --- | --- | --- |
//! | `change_lane(num_of_lanes, side, reference, offset, rate_profile, rate_peak)` | LaneChangeAction to the lane `num_of_lanes` (default 1) to the `side` of `reference`'s lane (default: the actor's own), at `offset` from its centre: `constant` linear, else sinusoidal; at `rate_peak` (the peak lateral speed, m/s), over the action's `duration` (or the phase's length), `asap` at the vehicle's lateral limit, else at [`DEFAULT_LATERAL_SPEED`] | when the actor is in the target lane at the offset |
//! | `follow_lane(offset, rate_profile, rate_peak)` | `keep_lane()` (its semantic clarification); with `offset`, a LaneOffsetAction to it timed as above (after a run-time condition, a LaneChangeAction into the actor's own lane at that offset, timed as above, so the change starts from the offset the engine finds) | with its phase |
//!
//! `side: inside` is the side towards the road's centre line and `outside` the side away from
//! it (right-hand traffic: left and right); `same` is the reference's own lane. A side left out
//! is drawn from the run's seed among the sides that have the lane, as for the `change_lane()`
//! modifier. `target: l` of both names a `lane` field, bound to a lane of the plan road
//! (`lane_fields`): `change_lane` moves into it as a LaneChangeAction with an absolute target
//! lane, `follow_lane` follows it when the actor is in it.

use std::f64::consts::{FRAC_PI_2, PI};

use scenario::{DynamicsShape, LaneOffsetTarget, LateralAction, PrivateAction};

use super::action_args::{positive, profile, rate, timed, Profile};
use super::planner::Planner;
use super::speed_actions::Slot;
use super::types::{Planned, When, MAX_ACCELERATION};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Arg, At, Invoke, ModKind, Modifier, Phase, Val};

/// Peak lateral speed of a lane change or lane offset that gives neither a rate nor a duration
/// (m/s): a 3.5 m lane change then takes π·3.5/2 ≈ 5.5 s, an unhurried lane change
/// (naturalistic driving studies measure around 5 to 6 s).
pub(crate) const DEFAULT_LATERAL_SPEED: f64 = 1.0;

/// How a lateral transition of `delta` m is timed: its dynamics and how long it lasts.
struct Timing {
    shape: DynamicsShape,
    span: f64,
    dynamics: scenario::TransitionDynamics,
}

impl Planner<'_> {
    /// Plans `inv`'s lateral action for one actor; returns when the action ends on its own
    /// (`None`: with its phase).
    pub(super) fn plan_lateral_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            len,
            out,
            ..
        } = slot;
        check_lateral_modifiers(inv)?;
        // Where the plan knows the actor: at the phase start, or (after a run-time condition)
        // in the lane it was last planned in.
        let t = t0.unwrap_or_else(|| self.last_known());
        let s = self.s_at(target, t);
        let tr = self.track(target);
        let (lane0, o0) = match t0 {
            Some(t) => (self.lane_now(target, t), tr.offset(t)),
            None => (self.lane_last(target), tr.offset(f64::MAX)),
        };
        let planned = |name: String, action| Planned::with_phase(target, name, action, &p.site);
        match inv.kind {
            Action::ChangeLane => {
                let (lane_target, lane1) = match &inv.lane_target {
                    Some(f) => {
                        let l = self.change_lane_field(inv, f, target, lane0, s)?;
                        (scenario::LaneChangeTarget::Absolute(l.to_string()), Some(l))
                    }
                    None => self.change_lane_target(p, inv, target, t)?,
                };
                let Some(lane1) = lane1 else {
                    return Err(p.site.err(
                        K::Unsatisfiable,
                        "expected a target lane the plan knows for change_lane(…), found none",
                    ));
                };
                let offset = lane_offset(inv, self.road.lane_width(lane1, s))?.unwrap_or(0.0);
                let delta = self.road.lane_center(lane1, s) + offset
                    - (self.road.lane_center(lane0, s) + o0);
                let tm = timing(p, inv, len, delta)?;
                let n = name("change_lane");
                out.push(planned(
                    n.clone(),
                    PrivateAction::Lateral(LateralAction::LaneChange {
                        target_lane_offset: (offset != 0.0).then_some(offset),
                        dynamics: tm.dynamics,
                        target: lane_target,
                    }),
                ));
                if let Some(t) = t0 {
                    // lane1 is counted where the change starts; a lane section before its end
                    // may number that lane otherwise (OpenDRIVE 1.8 §11.5 lane linkage): the
                    // track keeps the id it has where the change ends, the lane the engine
                    // takes the actor into (it follows the target lane's links).
                    let lane1 = self
                        .road
                        .lane_along(lane1, s, self.s_at(target, t + tm.span));
                    let tr = self.track_mut(target);
                    tr.set_lane(t + tm.span, lane1);
                    tr.set_offset(t + tm.span, offset);
                    tr.add_move(t, t + tm.span);
                }
                Ok(Some(self.ends(t0, tm.span, &n, p)))
            }
            Action::FollowLane => {
                if let Some(f) = &inv.lane_target {
                    self.follow_lane_field(f, target, lane0, s)?;
                }
                let Some(o1) = lane_offset(inv, self.road.lane_width(lane0, s))? else {
                    // Nothing to change: the engine's vehicles follow their lane.
                    return Ok(None);
                };
                let delta = o1 - o0;
                if t0.is_none() {
                    // After a run-time start the offset the actor starts from is the engine's:
                    // a change within its own lane (a LaneChangeAction to a RelativeTargetLane
                    // of 0 on itself at that targetLaneOffset) over the span, starting from it.
                    let tm = timing(p, inv, len, delta)?;
                    out.push(planned(
                        name("follow_lane"),
                        PrivateAction::Lateral(LateralAction::LaneChange {
                            target_lane_offset: Some(o1),
                            dynamics: tm.dynamics,
                            target: scenario::LaneChangeTarget::Relative {
                                entity_ref: target.to_string(),
                                value: 0,
                            },
                        }),
                    ));
                    return Ok(None);
                }
                if delta.abs() < 1e-9 {
                    return Ok(None);
                }
                let tm = timing(p, inv, len, delta)?;
                // The engine times a LaneOffsetAction by its peak lateral acceleration: π²Δ/(2T²)
                // for a sinusoid, and for a linear change the cubic's 6Δ/T² (its module doc).
                let max_lateral_acc = if tm.shape == DynamicsShape::Sinusoidal {
                    super::motion::sinusoid_peak_acceleration(delta, tm.span)
                } else {
                    6.0 * delta.abs() / (tm.span * tm.span)
                };
                out.push(planned(
                    name("follow_lane"),
                    PrivateAction::Lateral(LateralAction::LaneOffset {
                        continuous: false,
                        dynamics_shape: tm.shape,
                        max_lateral_acc: Some(max_lateral_acc),
                        target: LaneOffsetTarget::Absolute(o1),
                    }),
                ));
                if let Some(t) = t0 {
                    let tr = self.track_mut(target);
                    tr.set_offset(t + tm.span, o1);
                    tr.add_move(t, t + tm.span);
                }
                Ok(None)
            }
            _ => Ok(None),
        }
    }

    /// The target of `change_lane(…)` for `target` at time `t`: the 1.x LaneChangeTarget and the
    /// lane id it names on the plan road. Read as the `change_lane()`/`lane()` modifier with the
    /// same arguments, at the action's start.
    fn change_lane_target(
        &self,
        p: &Phase,
        inv: &Invoke,
        target: &str,
        t: f64,
    ) -> Result<(scenario::LaneChangeTarget, Option<i32>), Error> {
        let given = arg(&inv.args, "num_of_lanes");
        let n = num_of_lanes(inv)?;
        let side = match arg(&inv.args, "side") {
            None => None,
            Some(a) => match a.eval()? {
                Val::Enum(m) => Some((a, m)),
                _ => {
                    return Err(a.site.err(
                        K::Argument,
                        "expected left, right, inside, outside or same, found another value",
                    ))
                }
            },
        };
        let reference = arg(&inv.args, "reference");
        let num = |x: f64| Arg {
            site: p.site.clone(),
            path: None,
            value: Ok(Val::Num(x)),
        };
        let enumerated = |a: &Arg, m: &str| Arg {
            value: Ok(Val::Enum(m.to_string())),
            ..a.clone()
        };
        let mut args = vec![("lane".to_string(), num(n))];
        let mut kind = ModKind::ChangeLane;
        match (&side, reference) {
            (Some((a, m)), r) if m == "same" => {
                if let Some(g) = given {
                    return Err(g.site.err(
                        K::Argument,
                        "expected no num_of_lanes with side: same (the reference's own lane), found one",
                    ));
                }
                let Some(r) = r else {
                    return Err(a.site.err(
                        K::Argument,
                        "expected a reference with side: same (the lane of another actor), found none: the actor's own lane is no lane change",
                    ));
                };
                kind = ModKind::Lane;
                args = vec![("same_as".to_string(), r.clone())];
            }
            (s, r) => {
                if let Some((a, m)) = s {
                    // Right-hand traffic: the centre line is on the left.
                    let lr = match m.as_str() {
                        "left" | "inside" => "left",
                        "right" | "outside" => "right",
                        _ => {
                            return Err(a.site.err(
                                K::Argument,
                                format!("expected left, right, inside, outside or same, found {m}"),
                            ))
                        }
                    };
                    args.push(("side".to_string(), enumerated(a, lr)));
                }
                if let Some(r) = r {
                    if self.entity_of(r)? != target {
                        if s.is_none() {
                            return Err(r.site.err(
                                K::Argument,
                                "expected a side with reference in change_lane(…) (the target lane is num_of_lanes to the side of the reference), found none",
                            ));
                        }
                        kind = ModKind::Lane;
                        let side = args.pop();
                        args.push(("side_of".to_string(), r.clone()));
                        args.extend(side);
                    }
                }
            }
        }
        let m = Modifier {
            kind,
            name: inv.action.clone(),
            at: At::End,
            monotonous: false,
            projected: false,
            args,
            along: None,
            path: None,
            shape: None,
            site: p.site.clone(),
        };
        // The reference's lane at the action's start (len 0).
        self.lane_target(&m, target, Some(t), 0.0)
    }
}

/// The `num_of_lanes` of `change_lane(…)` `inv`: a whole number of 1 or more, 1 when not given.
pub(super) fn num_of_lanes(inv: &Invoke) -> Result<f64, Error> {
    match arg(&inv.args, "num_of_lanes") {
        None => Ok(1.0),
        Some(a) => match a.number()? {
            x if x >= 1.0 && x.fract() == 0.0 => Ok(x),
            x => Err(a.site.err(
                K::Argument,
                format!("expected num_of_lanes of 1 or more, found {x}"),
            )),
        },
    }
}

/// The `offset` of `inv` from the lane's centre, which must keep the actor's reference point
/// in a lane `width` m wide.
fn lane_offset(inv: &Invoke, width: f64) -> Result<Option<f64>, Error> {
    let Some(a) = arg(&inv.args, "offset") else {
        return Ok(None);
    };
    let o = a.number()?;
    if o.abs() > width / 2.0 + 1e-9 {
        return Err(a.site.err(
            K::Unsatisfiable,
            format!(
                "expected an offset within the lane's half width ±{:.2} m, found {o:.2} m",
                width / 2.0
            ),
        ));
    }
    Ok(Some(o))
}

/// The timing of a lateral change by `delta` m: `rate_peak` is the peak lateral speed,
/// `duration` (or the phase's length `len`) the time, `asap` the vehicle's lateral limit, else
/// [`DEFAULT_LATERAL_SPEED`]. `constant` is linear, every other profile sinusoidal.
fn timing(p: &Phase, inv: &Invoke, len: Option<f64>, delta: f64) -> Result<Timing, Error> {
    let profile = profile(inv)?;
    let peak = positive(inv, "rate_peak")?;
    let own = positive(inv, "duration")?;
    let (shape, slope) = if profile == Profile::Constant {
        (DynamicsShape::Linear, 1.0)
    } else {
        (DynamicsShape::Sinusoidal, FRAC_PI_2)
    };
    if profile == Profile::Asap && own.is_some() {
        return Err(p.site.err(
            K::Argument,
            format!(
                "expected rate_profile: asap (as soon as possible) or a duration in {}(…), found both",
                inv.action
            ),
        ));
    }
    let (dynamics, span) = match (profile, peak, own.or(len)) {
        (Profile::Asap, None, _) => {
            // A sinusoid of Δ over T peaks at π²Δ/(2T²) lateral acceleration.
            let span = PI * (delta.abs() / (2.0 * MAX_ACCELERATION)).sqrt();
            (timed(shape, span), span)
        }
        (_, Some(v), _) => rate(shape, v, delta, slope),
        (_, None, Some(d)) => (timed(shape, d), d),
        (_, None, None) => rate(shape, DEFAULT_LATERAL_SPEED, delta, slope),
    };
    if shape == DynamicsShape::Sinusoidal && span > 0.0 {
        let a = super::motion::sinusoid_peak_acceleration(delta, span);
        if a > MAX_ACCELERATION + 1e-9 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected {}(…) within the vehicle's ±{MAX_ACCELERATION} m/s² lateral acceleration, found it needs {a:.2} m/s² to move {:.2} m sideways in {span:.2} s", inv.action, delta.abs()),
            ));
        }
    }
    if let (Some(d), Some(_)) = (own, peak) {
        if span > d + 1e-9 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected the {:.2} m sideways within the action's {d} s, found it needs {span:.2} s at its rate_peak", delta.abs()),
            ));
        }
    }
    Ok(Timing {
        shape,
        span,
        dynamics,
    })
}

/// A lateral action (`change_lane`, `follow_lane`, a lateral gap action) controls the lateral
/// position: no modifier beside it may change it.
pub(super) fn check_lateral_modifiers(inv: &Invoke) -> Result<(), Error> {
    let follow = inv.kind == Action::FollowLane;
    let offset = !follow || arg(&inv.args, "offset").is_some();
    let conflict = inv.modifiers.iter().find(|m| match m.kind {
        ModKind::ChangeLane => true,
        ModKind::Lane => m.at == At::End,
        ModKind::Lateral => m.at != At::Start && offset,
        // follow_lane's own keep_lane() (named after it) is its clarification.
        ModKind::KeepLane => !follow,
        _ => false,
    });
    match conflict {
        Some(m) => Err(m.site.err(
            K::Unsatisfiable,
            format!(
                "expected no lane or lateral modifier beside {}(…), which controls the lateral position, found `{}(…)`",
                inv.action, m.name
            ),
        )),
        None => Ok(()),
    }
}
