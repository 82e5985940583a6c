//! The actions of a `random_traffic_vehicle_group` (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1,
//! non-normative: "the group defines the initial conditions of actors in the scenario, meaning
//! their creation and destruction. The behavioral model assigned to each vehicle defines the
//! actual behavior of the vehicle within the group").
//!
//! The group's first phase creates its members (`random_traffic` places them; what the phase
//! asks, `Planner::creation`, is read by `random_traffic_creation`): `drive()`, `move()`,
//! `follow_lane()` (`drive() with: keep_lane()`, §8.8.3.2) or `remain_stationary()` (placed
//! standing, desired speed 0), starting with the run or at a later time the plan knows
//! (`random_traffic_late`: created then). From then on each member's driver model
//! drives it, so a later action of the group is given to every member's model as what that
//! model takes from it — its desired speed v0 (the engine hands a SpeedAction on a domain a
//! model holds to the model, `engine::controller::strategy`), or what keeps it to its lane:
//!
//! | action on the group | each member's model | the phase ends |
//! | --- | --- | --- |
//! | `drive()`/`move()` with `speed(v)` | v0 = v | by its duration or `until` |
//! | `drive()`/`move()` without | unchanged | by its duration or `until` |
//! | `change_speed(v)`, `assign_speed(v)` | v0 = v: the model gets there at its own rate (the IDM's a and b), behind a slower leader not at all | at once (the members' models have the target), or by the action's `duration:` |
//! | `keep_speed()` | v0 = the speed the member has at the phase start (a SpeedAction to its own speed) | by its duration or `until` |
//! | `remain_stationary()` | v0 = 0: the model brakes at its comfortable deceleration b to a stop and stands | by its duration or `until` |
//! | `change_lane(n, side [, reference: x])` | a LaneChangeAction to the lane n to the side of its own (x's) lane in its direction of travel, which `mobil` makes its next lane change with its own lateral shape; no drivable lane there driven the same way: the member keeps its lane (the engine logs it) | at once, or by the action's `duration:` |
//! | `lane(n [, from: left])` (at: all, end) beside an action | the lane so numbered in the member's direction of travel where it is when the phase starts (oscsim's `LaneChangeTarget::Numbered` on the member): the member's model's mandatory lane over the phase (oscsim's `LateralAction::MandatoryLane`, released at the phase end: the model changes lane by lane into gaps MOBIL's safety criterion accepts and keeps it, engine controller/mobil.rs; no gap before the phase end: the member keeps its lane), `mobil` keeping its lateral domain for it, the IDM (no lateral domain) handed it by the engine, which carries out each change the IDM starts; the lane must be there all along the plan's roads in each direction a member drives; `lane(same_as/left_of/right_of/side_of: x)`: the members driving x's way so to x's lane or the one n beside it (a RelativeTargetLane on x), the others kept in their lanes as by `keep_lane()` | by its duration or `until` |
//! | `follow_lane()`, `keep_lane()` beside an action | the model's lateral domain taken back over the phase (ActivateControllerAction, lateral false): the default controller keeps the member in the lane it is in, brought to its centre (a LaneChangeAction to that lane: a change under way ends there); handed back at the phase end | by its duration or `until` |
//!
//! Where the road's lanes are numbered otherwise along it (a lane added or dropped at a lane
//! section), the number is counted where each member is when the phase starts: §8.9.1.1.1
//! gives `at: all` as "This constraint holds throughout this phase (default)", and §8.9 counts
//! `lane(n)` across the road (`lane(lane: 1)`, `lane(1)` and `lane()` "have the same effect":
//! the rightmost driving lane of the direction of travel, `crate::road`) without saying at
//! which s; the member's place at the phase start is the one the engine knows, its model having
//! driven it there. So the plan checks only that lane n is there all along the plan's roads
//! in each direction a member drives (else an error at the modifier, `Unsatisfiable`), and
//! the engine reads the lane's id at the member's road, side and s as the phase starts. Over
//! the phase the member keeps that lane (its model, or the default controller, follows its id), also where
//! the numbering changes under it later: oscsim's choice, as the equal-numbering case keeps
//! the id it changed to.
//!
//! Bad input, refused at its place with §8.7.18.1's words ("the behavioral model assigned to
//! each vehicle defines the actual behavior of the vehicle within the group"): `rate_profile`/
//! `rate_peak` (the model's rate is its own), `change_lane` without a side (the side "among
//! those that have the lane" is drawn where the plan has the actor, and a member's lane is
//! its model's) or with an offset or target, a lane change of members whose model is the IDM
//! (created keeping their lanes: it changes none), `lane(n, at: start)` (each member in lane
//! n at the phase's first instant), other modifiers than `speed(v)`, `lane(n)`,
//! `keep_lane()` and `avoid_collisions(true)` (`avoid_collisions(false)` asks what the model
//! cannot do), and the group's position, path, orientation, acceleration and gap actions (a
//! motion of each member the model defines; the group has no formation to place).

use scenario::{
    ControllerAction, ControllerDomains, DynamicsDimension, DynamicsShape, LaneChangeTarget,
    LateralAction, LongitudinalAction, ModelAcceleration, PrivateAction, RateWithin, SpeedOf,
    SpeedTarget, SpeedTargetValueType, TransitionDynamics,
};

use super::action_args::positive;
use super::lateral_actions::{num_of_lanes, DEFAULT_LATERAL_SPEED};
use super::motion::{check_accel, check_speed};
use super::planner::Planner;
use super::random_traffic::LANE_STEP;
use super::runtime::speed_at_rate_check;
use super::speed_actions::{speed_target, step_speed};
use super::types::{Planned, When, MAX_SPEED};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{arg, Action, Arg, At, Invoke, ModKind, Modifier, Phase, Val};
use crate::road::PlanRoad;

/// What an action of random traffic asks of each member's model.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Ask {
    /// Nothing new (a drive without a speed).
    Nothing,
    /// This desired speed (m/s).
    Desired(f64),
    /// The speed each member has at the phase start as its desired speed.
    Keep,
    /// A lane change this many lanes to the left (right: negative) of the member's own lane,
    /// or of another actor's (`change_lane(n, side[, reference: x])`), made by the model.
    Lane(i32, Option<String>),
}

/// The lane `lane(…)` beside a later action of random traffic asks of each member.
enum LaneAsk {
    /// Lane n (from the left) of the member's direction of travel, and the modifier's place.
    Numbered(i64, bool, Site),
    /// The lane `by` lanes left (right: negative) of another actor `x`'s lane, in x's
    /// direction: for the members driving x's way (the others keep their lanes).
    Beside(String, i32),
}

/// What a later action of random traffic asks (`ask`): of each member's model, whether the
/// members keep their lanes over the phase, and the action's own duration.
struct Asked {
    ask: Ask,
    /// `follow_lane()`, `keep_lane()`: no lane change over the phase (the model's lateral
    /// domain taken back for it: `Planner::plan_random_traffic_action`).
    hold_lane: bool,
    /// The action's `duration:`.
    own: Option<f64>,
    /// `lane(n [, from: left])` at: all or end: each member changed to the lane so numbered
    /// in its direction of travel where it is at the phase start, kept there over the phase
    /// (`hold_lane`).
    lane: Option<LaneAsk>,
}

/// §8.7.18.1's words, which every refusal of a later action of random traffic gives.
const BEHAVIOUR: &str = "§8.7.18.1: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\"";

/// Checks the `avoid_collisions(…)` of random traffic `g`: `true` is what its members' model
/// does already; `false` an error at the modifier.
pub(super) fn check_avoid(g: &str, m: &Modifier) -> Result<(), Error> {
    match m.arg("avoid").map(Arg::eval).transpose()? {
        Some(Val::Bool(false)) => Err(m.site.err(
            K::Unsatisfiable,
            format!("expected avoid_collisions(true) on random traffic `{g}` (its members' driver model follows the vehicle ahead: it avoids collisions), found avoid_collisions(false)"),
        )),
        _ => Ok(()),
    }
}

/// The absolute `speed(v)` of `m` for random traffic `g`, within (0, MAX_SPEED] (`None`: a
/// speed relative to another actor or without a value, which the caller refuses).
pub(super) fn desired(g: &str, m: &Modifier) -> Result<Option<f64>, Error> {
    let relative = ["faster_than", "slower_than", "same_as"]
        .iter()
        .any(|k| m.arg(k).is_some());
    let Some(v) = m.arg("speed").filter(|_| !relative) else {
        return Ok(None);
    };
    let v = v.number()?;
    if !(v > 0.0 && v <= MAX_SPEED) {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a desired speed above 0 and up to {MAX_SPEED} m/s for random traffic `{g}`, found {v} m/s"),
        ));
    }
    Ok(Some(v))
}

/// The lane change `change_lane(num_of_lanes, side [, reference])` asks of each member of
/// random traffic `g`: n lanes to the left (right: negative) of its own lane or of the
/// reference's; what names no lane relative to the member an error at its argument.
fn lane_change(p: &Phase, inv: &Invoke) -> Result<Ask, Error> {
    let g = &inv.actor;
    let n = num_of_lanes(inv)?;
    // Right-hand traffic: the centre line is on the left of either direction.
    let left = match arg(&inv.args, "side").map(|a| (a, a.eval())) {
        None => {
            return Err(p.site.err(
                K::Argument,
                format!("expected a side (left, right, inside, outside) in change_lane(…) of random traffic `{g}`, found none: the side among those that have the lane is drawn from where the plan has an actor, and each member's lane is its driver model's"),
            ))
        }
        Some((a, v)) => match v? {
            Val::Enum(m) if m == "left" || m == "inside" => true,
            Val::Enum(m) if m == "right" || m == "outside" => false,
            _ => {
                return Err(a.site.err(
                    K::Argument,
                    format!("expected left, right, inside or outside in change_lane(…) of random traffic `{g}` (a lane beside each member's), found another value"),
                ))
            }
        },
    };
    let reference = match arg(&inv.args, "reference") {
        Some(r) => Some(r.path.clone().ok_or_else(|| {
            r.site.err(
                K::Argument,
                "expected an actor as the reference of change_lane(…)",
            )
        })?),
        None => None,
    };
    for key in ["offset", "target"] {
        if let Some(a) = arg(&inv.args, key) {
            return Err(a.site.err(
                K::Argument,
                format!("expected no {key} in change_lane(…) of random traffic `{g}` (each member's driver model changes into the lane's centre with its own lateral shape, {BEHAVIOUR}), found one"),
            ));
        }
    }
    let n = n as i32;
    Ok(Ask::Lane(if left { n } else { -n }, reference))
}

/// The plan's lane change without a rate or duration: sinusoidal at a peak lateral speed of
/// [`DEFAULT_LATERAL_SPEED`].
fn default_dynamics() -> TransitionDynamics {
    TransitionDynamics {
        dynamics_shape: DynamicsShape::Sinusoidal,
        dynamics_dimension: DynamicsDimension::Rate,
        value: DEFAULT_LATERAL_SPEED,
        following_mode: None,
    }
}

/// A LaneChangeAction to the lane `by` lanes left (right: negative) of `x`'s, at its centre,
/// sinusoidal at the plan's default peak lateral speed: the engine's when the default
/// controller holds the domain, the target alone when a model does (its own lateral shape).
fn lane_change_to(x: &str, by: i32) -> PrivateAction {
    PrivateAction::Lateral(LateralAction::LaneChange {
        target_lane_offset: None,
        dynamics: default_dynamics(),
        target: LaneChangeTarget::Relative {
            entity_ref: x.to_string(),
            value: by,
        },
    })
}

/// The ActivateControllerAction that gives a member's driver back its lateral domain (`on`)
/// or takes it away for the default controller (`!on`).
fn lateral(on: bool) -> PrivateAction {
    PrivateAction::Controller(Box::new(ControllerAction::Activate {
        object_controller_ref: None,
        domains: ControllerDomains {
            lateral: Some(on),
            ..ControllerDomains::default()
        },
    }))
}

/// What action `inv` of random traffic after its creation asks of each member's model
/// (`idm`: its members keep their lanes, their model changes none), its own duration if any;
/// bad input at the place of what no model takes.
fn ask(p: &Phase, inv: &Invoke, idm: bool) -> Result<Asked, Error> {
    let g = &inv.actor;
    for key in ["rate_profile", "rate_peak"] {
        if let Some(a) = arg(&inv.args, key) {
            return Err(a.site.err(
                K::Unsatisfiable,
                format!("expected no {key} in {}(…) of random traffic `{g}` (each member's driver model changes its speed and lane at the model's own rate: {BEHAVIOUR}), found one", inv.action),
            ));
        }
    }
    let mut hold_lane = false;
    let mut lane = None;
    let mut ask = match inv.kind {
        Action::Move => Ask::Nothing,
        Action::ChangeSpeed | Action::AssignSpeed => Ask::Desired(speed_target(inv, p)?),
        Action::KeepSpeed => Ask::Keep,
        Action::RemainStationary => Ask::Desired(0.0),
        Action::ChangeLane if idm => {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected no change_lane(…) of random traffic `{g}`, whose members keep their lanes (keep_lane(), follow_lane() or lane(…) at: all where it was created: their driver model, the IDM, changes no lane; {BEHAVIOUR}), found one"),
            ))
        }
        Action::ChangeLane => lane_change(p, inv)?,
        Action::FollowLane => {
            for key in ["offset", "target"] {
                if let Some(a) = arg(&inv.args, key) {
                    return Err(a.site.err(
                        K::Argument,
                        format!("expected no {key} in follow_lane(…) of random traffic `{g}` (each member keeps the lane it is in, at its centre: {BEHAVIOUR}), found one"),
                    ));
                }
            }
            hold_lane = true;
            Ask::Nothing
        }
        _ => {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected drive(), move(), change_speed(…), assign_speed(…), keep_speed(), remain_stationary(), change_lane(…) or follow_lane() of random traffic `{g}` after its creation (a desired speed, a lane change or the lane kept, what its members' driver model takes), found {}(…): a place, path, orientation, acceleration or gap asked of the whole group is a motion of each member that the group does not give ({BEHAVIOUR}; the group has no formation to place)", inv.action),
            ))
        }
    };
    for m in &inv.modifiers {
        match m.kind {
            ModKind::AvoidCollisions => check_avoid(g, m)?,
            // Implied by the action itself (keep_speed(), remain_stationary()).
            ModKind::KeepSpeed | ModKind::KeepPosition if m.name == inv.action => {}
            ModKind::KeepLane => hold_lane = true,
            ModKind::Lane => {
                lane = Some(numbered_lane(g, m)?);
                hold_lane = true;
            }
            ModKind::Speed if inv.kind == Action::Move && m.at != At::End => match desired(g, m)? {
                Some(v) => ask = Ask::Desired(v),
                None => return Err(refused(g, m)),
            },
            _ => return Err(refused(g, m)),
        }
    }
    if (hold_lane || lane.is_some()) && matches!(ask, Ask::Lane(..)) {
        return Err(p.site.err(
            K::Unsatisfiable,
            format!("expected a lane change or the lane kept by random traffic `{g}` in one phase, found both"),
        ));
    }
    Ok(Asked {
        ask,
        hold_lane,
        own: positive(inv, "duration")?,
        lane,
    })
}

/// The lane `lane(n [, from: left])` `m` beside a later action of random traffic `g` asks:
/// (n, from the left, its place), or the lane beside another actor. At: start is bad input:
/// it asks each member in lane n as the phase starts, where its model has put it.
fn numbered_lane(g: &str, m: &Modifier) -> Result<LaneAsk, Error> {
    if m.at == At::Start {
        return Err(m.site.err(
            K::Modifier,
            format!("expected lane(n) at: all or end beside an action of random traffic `{g}` after its creation (each member changed to lane n and kept there), found at: start: it asks each member in lane n as the phase starts, where its driver model has put it ({BEHAVIOUR})"),
        ));
    }
    let n = m.arg("lane").map(Arg::number).transpose()?.unwrap_or(1.0);
    if n < 1.0 || n.fract() != 0.0 {
        return Err(m.site.err(
            K::Modifier,
            format!(
                "expected a lane number of 1 or more in lane(…) of random traffic `{g}`, found {n}"
            ),
        ));
    }
    // Relative to another actor: n lanes to its side (same_as: its own lane).
    for key in ["same_as", "left_of", "right_of", "side_of"] {
        let Some(a) = m.arg(key) else { continue };
        let x = a.path.clone().ok_or_else(|| {
            a.site.err(
                K::Argument,
                format!("expected an actor for `{key}:` in lane(…)"),
            )
        })?;
        return Ok(LaneAsk::Beside(x, side_sign(key, m)? * n as i32));
    }
    let from_left =
        matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
    Ok(LaneAsk::Numbered(n as i64, from_left, m.site.clone()))
}

/// The side of another actor's lane that `lane(…, key: x)` `m` counts to: 0 for `same_as`, 1
/// left (`left_of`, `side_of` without `side: right`), -1 right.
pub(super) fn side_sign(key: &str, m: &Modifier) -> Result<i32, Error> {
    Ok(match key {
        "same_as" => 0,
        "left_of" => 1,
        "right_of" => -1,
        _ => match m.arg("side").map(Arg::eval).transpose()? {
            Some(Val::Enum(s)) if s == "right" => -1,
            _ => 1,
        },
    })
}

/// The error at modifier `m`, which no member's model takes after the group's creation.
fn refused(g: &str, m: &Modifier) -> Error {
    m.site.err(
        K::Modifier,
        format!("expected speed(v) on a drive, lane(n), keep_lane() or avoid_collisions(true) beside an action of random traffic `{g}` after its creation (a desired speed or the lane kept, what its members' driver model takes), found `{}(…)`: it constrains a motion of each member that the model defines ({BEHAVIOUR})", m.name),
    )
}

impl Planner<'_> {
    /// Plans action `inv` (phase `p`, starting at `t0`) of random traffic `inv.actor` after
    /// its creation into `out` (module doc): per member a SpeedAction (a step) or a
    /// LaneChangeAction, which the engine hands to the member's model, a lane for its model
    /// to reach and keep (a mandatory lane, released at the phase end: `after`), or, to keep
    /// the lanes, the model's lateral domain taken back at the phase start and given back at
    /// its end. Returns the phase's end when the action sets it.
    pub(super) fn plan_random_traffic_action(
        &self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
        out: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        let members = &self.groups[&inv.actor];
        let idm = members.iter().all(|m| self.driver_model(m) == Some("idm"));
        let Asked {
            ask,
            hold_lane,
            own,
            lane,
        } = ask(p, inv, idm)?;
        // Lane n of each direction a member drives, which each member changes to as it is
        // numbered where the member is when the phase starts (the plan does not know where
        // that is: the lane must be there all along the plan's roads in its direction).
        let numbered = match &lane {
            Some(LaneAsk::Numbered(n, from_left, site)) => {
                for back in [false, true] {
                    let Some(m) = members
                        .iter()
                        .find(|m| self.entities[self.index[*m]].against == back)
                    else {
                        continue;
                    };
                    let view = if back {
                        self.against_road.as_ref()
                    } else {
                        Some(&self.road)
                    };
                    self.numbered_all_along(view, (*n, *from_left), site, m)?;
                }
                Some((u32::try_from(*n).unwrap_or(u32::MAX), *from_left))
            }
            _ => None,
        };
        // Beside another actor x: x's direction of travel, which the members driving its way
        // take the lane from.
        let beside = match &lane {
            Some(LaneAsk::Beside(x, by)) => {
                let Some(&ix) = self.index.get(x) else {
                    return Err(p.site.err(
                        K::Argument,
                        format!("expected an actor as the reference of lane(…) beside random traffic `{}`, found `{x}`", inv.actor),
                    ));
                };
                Some((x.clone(), *by, self.entities[ix].against))
            }
            _ => None,
        };
        if let Ask::Lane(_, Some(x)) = &ask {
            if !self.index.contains_key(x) {
                return Err(p.site.err(
                    K::Argument,
                    format!("expected an actor as the reference of change_lane(…) of random traffic `{}`, found `{x}`", inv.actor),
                ));
            }
        }
        for (i, m) in members.iter().enumerate() {
            let name = |what: &str| format!("{}/{m}/{}:{what}", p.path, i + 1);
            // The lane it is in, at its centre (a change the model was making ends there), or
            // lane n of its direction, or x's lane or the one beside it.
            let back = self.entities[self.index[m]].against;
            let target = match (&numbered, &beside) {
                (_, Some((x, by, x_back))) if *x_back == back => Some(LaneChangeTarget::Relative {
                    entity_ref: x.clone(),
                    value: *by,
                }),
                (Some((n, from_left)), _) => Some(LaneChangeTarget::Numbered {
                    entity_ref: m.clone(),
                    lane: *n,
                    from_left: *from_left,
                }),
                _ => None,
            };
            // The lane is the member's model's mandatory lane, reached lane by lane into gaps
            // MOBIL's safety criterion accepts and kept, released at the phase end: `mobil`
            // keeps its lateral domain for it; the `idm`, which holds none, is handed it by
            // the engine (controller/strategy.rs) and decides when each change starts.
            let mandatory = target.is_some();
            if let Some(target) = target {
                let lane = |target| PrivateAction::Lateral(LateralAction::MandatoryLane { target });
                out.push(Planned::with_phase(
                    m,
                    name("lane"),
                    lane(Some(target)),
                    &p.site,
                ));
                after.push(Planned::with_phase(
                    m,
                    name("lane_end"),
                    lane(None),
                    &p.site,
                ));
            }
            let kept = (!mandatory && hold_lane && !idm).then(|| lane_change_to(m, 0));
            // The IDM holds no lateral domain: a member it drives keeps its lane already.
            if hold_lane && !idm && !mandatory {
                out.push(Planned::with_phase(
                    m,
                    name("keep_lane"),
                    lateral(false),
                    &p.site,
                ));
                after.push(Planned::with_phase(
                    m,
                    name("keep_lane_end"),
                    lateral(true),
                    &p.site,
                ));
            }
            if let Some(change) = kept {
                out.push(Planned::with_phase(m, name("lane"), change, &p.site));
            }
            let action = match &ask {
                Ask::Nothing => continue,
                Ask::Desired(v) => step_speed(SpeedTarget::Absolute(*v)),
                Ask::Keep => step_speed(SpeedTarget::Relative {
                    entity_ref: m.clone(),
                    value: 0.0,
                    speed_target_value_type: SpeedTargetValueType::Delta,
                    continuous: false,
                }),
                // The model's own lateral shape: the dynamics are the plan's default change's,
                // which the model does not follow.
                Ask::Lane(by, x) => lane_change_to(x.as_deref().unwrap_or(m), *by),
            };
            out.push(Planned::with_phase(m, name(&inv.action), action, &p.site));
        }
        let instant = matches!(
            inv.kind,
            Action::ChangeSpeed | Action::AssignSpeed | Action::ChangeLane
        );
        Ok(match own {
            Some(d) => Some(self.ends(t0, d, "", p)),
            None if instant => Some(self.ends(t0, 0.0, "", p)),
            None => None,
        })
    }

    /// Checks that `view` (the plan's roads in one direction of travel; `None`: no view against
    /// s) has a driving lane numbered `n` (from the left: `from_left`) all along it, where
    /// member `m` of random traffic may be when the phase starts; an error at `site` where it
    /// has none.
    fn numbered_all_along(
        &self,
        view: Option<&PlanRoad<'_>>,
        (n, from_left): (i64, bool),
        site: &Site,
        m: &str,
    ) -> Result<(), Error> {
        let side = if from_left { "left" } else { "right" };
        let missing = |at: String| {
            site.err(
                K::Unsatisfiable,
                format!("expected a driving lane numbered {n} from the {side} all along the plan's roads in the direction of `{m}` of random traffic (each member changes to that lane as numbered where it is when the phase starts, which its driver model decides: {BEHAVIOUR}), found none {at}"),
            )
        };
        let Some(view) = view else {
            return Err(missing(
                "against s (the plan's roads have no lanes driven in −s all along)".into(),
            ));
        };
        let steps = (view.length() / LANE_STEP).floor() as usize;
        for k in 0..=steps {
            let u = (k as f64 * LANE_STEP).min(view.length());
            if view.numbered(n, from_left, u, false).is_none() {
                return Err(missing(format!("{u:.1} m along its direction of travel")));
            }
        }
        Ok(())
    }

    /// Refuses a member's own `follow_trajectory(…)` or `replay_trajectory(…)` (phase `p`,
    /// invocation `inv`) as bad input: a trajectory timed by its points sets the member's
    /// speed at every point (the FollowTrajectoryAction with a time reference holds both
    /// motion domains), and the member's speed is its driver model's (§8.7.18.1), which takes
    /// no trajectory (handed to it, the engine would ignore it: engine
    /// controller/strategy.rs). Its path without the times, `follow_path(…)`, runs at the
    /// speed the model gives.
    pub(super) fn check_member_trajectory(
        &self,
        p: &Phase,
        inv: &Invoke,
        target: &str,
    ) -> Result<(), Error> {
        if !matches!(
            inv.kind,
            Action::FollowTrajectory | Action::ReplayTrajectory
        ) {
            return Ok(());
        }
        Err(p.site.err(
            K::Unsatisfiable,
            format!("expected no {}(…) of `{target}`, a member of random traffic: its trajectory's times would set the speed its driver model sets ({BEHAVIOUR}); follow_path(…) along its points runs at the speed the model gives", inv.action),
        ))
    }

    /// A member's own path action (`follow_path`, `replay_path`, `change_position`: a
    /// FollowTrajectoryAction without a time reference, which holds the lateral domain only),
    /// of phase `p` planned at `out[at..]` for `target`: where its driver model holds the lateral domain
    /// (`mobil`) the engine would hand the path to the model, which takes none, so the
    /// model's lateral domain is taken back before the action (the default controller
    /// follows the path at the speed the model gives) and given back at the phase end
    /// (`after`), as `follow_lane()` of random traffic does (module doc). The `idm` holds no
    /// lateral domain: nothing to take.
    pub(super) fn member_path_lateral(
        &self,
        (p, inv): (&Phase, &Invoke),
        target: &str,
        name: &mut dyn FnMut(&str) -> String,
        at: usize,
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) {
        let path = matches!(
            inv.kind,
            Action::FollowPath | Action::ReplayPath | Action::ChangePosition
        );
        if !path || !self.random_member(target) || self.driver_model(target) != Some("mobil") {
            return;
        }
        let site = &p.site;
        let take = Planned::with_phase(target, name("path_lateral"), lateral(false), site);
        out.insert(at, take);
        after.push(Planned::with_phase(
            target,
            name("path_lateral_end"),
            lateral(true),
            site,
        ));
    }

    /// The driver model of member `m` of random traffic (`idm`, `mobil`), if it has one.
    fn driver_model(&self, m: &str) -> Option<&str> {
        let c = self.entities[*self.index.get(m)?].driver.as_ref()?;
        c.properties
            .properties
            .iter()
            .find(|(k, _)| k == "model")
            .map(|(_, v)| v.as_str())
    }
}

impl Planner<'_> {
    /// A member's own `acceleration(a)` or `acceleration(a, same_as/faster_than/slower_than:
    /// x)` (x outside its group: relative to a member it is bad input,
    /// `random_traffic_relations`) alone in a phase of its own, which starts on a run-time
    /// condition (a member's phase at a time the plan knows is refused before): its driver
    /// model's free-road acceleration over the phase (oscsim's
    /// `LongitudinalAction::ModelAcceleration`, as `name.0`), released at the phase end (as
    /// `name.1`). The model holds the longitudinal domain (§8.7.18.1); the engine's `idm`
    /// puts the acceleration in place of its free-road term a·(1 − (v/v0)^δ) and still
    /// subtracts its interaction term toward the leader (engine controller/car_following.rs),
    /// so on a free road the member accelerates at it and behind a leader the IDM's braking
    /// wins where the gap asks for it; released, the model's own term is back. Relative to x:
    /// x's acceleration read by the model at every step (at: all or end, the default), or
    /// once when the phase starts (at: start, `track: projected`), plus a for `faster_than`,
    /// less a for `slower_than`.
    pub(super) fn member_acceleration(
        &self,
        m: &Modifier,
        target: &str,
        name: (String, String),
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<(), Error> {
        let free = self.member_free(m)?;
        let action =
            |target| PrivateAction::Longitudinal(LongitudinalAction::ModelAcceleration { target });
        out.push(Planned::with_phase(
            target,
            name.0,
            action(Some(free)),
            &m.site,
        ));
        after.push(Planned::with_phase(target, name.1, action(None), &m.site));
        Ok(())
    }

    /// A member's own `acceleration(…)` `q` as the rate of its own speed change `m`
    /// (`speed(v, at: end)` or `change_speed(v)` beside a drive or move) in a phase of its own,
    /// which starts on a run-time condition: its driver model's rate toward v (oscsim's
    /// `ModelAcceleration::Toward`, as `names.1`): desired speed v and a free-road term of
    /// magnitude a (or x's acceleration ± a, as [`member_acceleration`](Self::member_acceleration)
    /// reads it) signed toward v until the member's speed reaches v, the step that reaches it
    /// cut to end there, then the model's own free-road term toward v (engine
    /// controller/car_following.rs, "A rate toward a speed"); the interaction term toward its
    /// leader still subtracted (§8.7.18.1: the model defines the behaviour within the group).
    /// The phase's end does not end it: the model has v from then on, as after a group's
    /// `change_speed(v)`. With a fixed rate and a phase length `len`, the engine checks as for
    /// any actor that the change fits the phase from the member's speed then (as `names.0`).
    /// v relative to another actor y (`speed(δ, faster_than/slower_than/same_as: y, at: end)`)
    /// is y's speed ± δ as an ordinary actor's change at that rate reads it
    /// (`start_relative_speed_at_rate`): with `track: projected` y's speed as the phase starts,
    /// fixed, then as v above; else read at every step, the model's desired speed following it
    /// at the rate (engine "A rate toward another's speed"), the braking toward the leader still
    /// winning, released at the phase end (`after`; the desired speed last read stays), as the
    /// ordinary actor's SpeedAction following y is stopped there.
    pub(super) fn member_rate(
        &mut self,
        (m, q): (&Modifier, &Modifier),
        target: &str,
        len: Option<f64>,
        names: (String, String),
        (out, after): (&mut Vec<Planned>, &mut Vec<Planned>),
    ) -> Result<(), Error> {
        let (v1, relative) = self.speed_value(m, None)?;
        let rate = self.member_free(q)?;
        // The speed toward which, as the engine's check at the start reads it (the ordinary
        // actor's targets), and what the model is handed.
        let (to, speed, of) = match relative {
            None => {
                check_speed(m, v1)?;
                (SpeedTarget::Absolute(v1), v1, None)
            }
            Some((x, delta)) => {
                let to = match m.projected {
                    true => SpeedTarget::RelativeAtStart {
                        entity_ref: x.clone(),
                        value: delta,
                    },
                    false => SpeedTarget::Relative {
                        entity_ref: x.clone(),
                        value: delta,
                        speed_target_value_type: SpeedTargetValueType::Delta,
                        continuous: true,
                    },
                };
                let of = SpeedOf {
                    entity_ref: x,
                    projected: m.projected,
                };
                (to, delta, Some(of))
            }
        };
        if let (ModelAcceleration::Absolute(a), Some(l)) = (&rate, len.filter(|l| *l > 0.0)) {
            out.push(speed_at_rate_check(
                target,
                (&q.name, &q.site),
                (to, a.abs(), RateWithin::Time(l)),
                names.0,
            ));
        }
        let (absolute, followed) = (of.is_none(), of.as_ref().is_some_and(|o| !o.projected));
        let target_speed = ModelAcceleration::Toward {
            speed,
            rate: Box::new(rate),
            of,
        };
        let action =
            |target| PrivateAction::Longitudinal(LongitudinalAction::ModelAcceleration { target });
        out.push(Planned::with_phase(
            target,
            names.1.clone(),
            action(Some(target_speed)),
            &m.site,
        ));
        if followed {
            let end = format!("{}_end", names.1);
            after.push(Planned::with_phase(target, end, action(None), &m.site));
        }
        if absolute {
            self.last_v.insert(target.to_string(), v1);
        }
        Ok(())
    }

    /// The free-road acceleration a member's own `acceleration(…)` `m` hands its model:
    /// a, or x's acceleration ± a read at every step (at: all or end) or once (at: start,
    /// `track: projected`).
    fn member_free(&self, m: &Modifier) -> Result<ModelAcceleration, Error> {
        Ok(match self.followed_acceleration(m, (None, 0.0))? {
            Some((x, delta, _)) => {
                check_accel(m, delta)?;
                ModelAcceleration::Relative {
                    entity_ref: x,
                    value: delta,
                    continuous: m.at != At::Start && !m.projected,
                }
            }
            None => {
                let a = self.acceleration_value(m, (None, 0.0))?;
                check_accel(m, a)?;
                ModelAcceleration::Absolute(a)
            }
        })
    }
}
