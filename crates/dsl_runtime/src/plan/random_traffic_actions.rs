//! The actions of a `random_traffic_vehicle_group` (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1,
//! non-normative: "the group defines the initial conditions of actors in the scenario, meaning
//! their creation and destruction. The behavioral model assigned to each vehicle defines the
//! actual behavior of the vehicle within the group").
//!
//! The group's first phase creates its members (`random_traffic` places them; what the phase
//! asks, `Planner::creation`, is read here): `drive()`, `move()`,
//! `follow_lane()` (`drive() with: keep_lane()`, §8.8.3.2) or `remain_stationary()` (placed
//! standing, desired speed 0), starting with the run or at a later time the plan knows
//! (`random_traffic_late`: created then). From then on each member's driver model
//! drives it, so a later action of the group is given to every member's model as what that
//! model takes from it — its desired speed v0 (the engine hands a SpeedAction on a domain a
//! model holds to the model, `engine::controller::strategy`):
//!
//! | action on the group | each member's model | the phase ends |
//! | --- | --- | --- |
//! | `drive()`/`move()` with `speed(v)` | v0 = v | by its duration or `until` |
//! | `drive()`/`move()` without | unchanged | by its duration or `until` |
//! | `change_speed(v)`, `assign_speed(v)` | v0 = v: the model gets there at its own rate (the IDM's a and b), behind a slower leader not at all | at once (the members' models have the target), or by the action's `duration:` |
//! | `keep_speed()` | v0 = the speed the member has at the phase start (a SpeedAction to its own speed) | by its duration or `until` |
//! | `remain_stationary()` | v0 = 0: the model brakes at its comfortable deceleration b to a stop and stands | by its duration or `until` |
//!
//! What the model does not take is an error at its place: `rate_profile`/`rate_peak` of a
//! speed change (the model's rate is its own), other modifiers than `speed(v)` and
//! `avoid_collisions(true)` (the model avoids collisions: `avoid_collisions(false)` asks what
//! it cannot do), and the group's other actions (lane, position and path actions: a member's
//! model drives its lane and place).

use scenario::{SpeedTarget, SpeedTargetValueType};

use super::action_args::positive;
use super::place::DEFAULT_SPEED;
use super::planner::Planner;
use super::speed_actions::{speed_target, step_speed};
use super::types::{Beside, Creation, Planned, When, MAX_SPEED};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Along, Arg, At, Invoke, ModKind, Modifier, Phase, Route, Val};

impl Planner<'_> {
    /// The lane `c` asks for, relative to another actor `x` there: x driving against s
    /// (`back`), in lane `lx` at s `sx` (u against s): the direction and lane id the members
    /// are dealt to, or an error at the modifier when x is not in the plan or no driving lane
    /// lies there.
    pub(super) fn beside_lane(
        &self,
        g: &str,
        b: &Beside,
        x_at: Option<(bool, i32, f64)>,
    ) -> Result<(bool, i32), Error> {
        let Some((back, lx, sx)) = x_at else {
            return Err(b.site.err(
                K::Unsupported,
                format!("expected `{}` placed by the plan before random traffic `{g}` is created beside it, found it placed from the members or moved by the engine then", b.x),
            ));
        };
        let view = if back {
            self.against_road.as_ref().unwrap_or(&self.road)
        } else {
            &self.road
        };
        let lane = if b.by == 0 {
            Some(lx)
        } else {
            view.beside(lx, b.by > 0, b.by.abs(), sx)
        };
        lane.map(|l| (back, l)).ok_or_else(|| {
            b.site.err(
                K::Unsatisfiable,
                format!("expected a driving lane {} lanes to the {} of `{}`'s lane {lx} for random traffic `{g}`, found none there", b.by.abs(), if b.by > 0 { "left" } else { "right" }, b.x),
            )
        })
    }
}

/// What an action of random traffic asks of each member's model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Ask {
    /// Nothing new (a drive without a speed).
    Nothing,
    /// This desired speed (m/s).
    Desired(f64),
    /// The speed each member has at the phase start as its desired speed.
    Keep,
}

/// Checks the `avoid_collisions(…)` of random traffic `g`: `true` is what its members' model
/// does already; `false` an error at the modifier.
fn check_avoid(g: &str, m: &Modifier) -> Result<(), Error> {
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
fn desired(g: &str, m: &Modifier) -> Result<Option<f64>, Error> {
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

/// What action `inv` of random traffic after its creation asks of each member's model, its
/// own duration if any; an error at the place of what no model takes.
fn ask(p: &Phase, inv: &Invoke) -> Result<(Ask, Option<f64>), Error> {
    let g = &inv.actor;
    for key in ["rate_profile", "rate_peak"] {
        if let Some(a) = arg(&inv.args, key) {
            return Err(a.site.err(
                K::Unsatisfiable,
                format!("expected no {key} in {}(…) of random traffic `{g}` (each member's driver model changes its speed at the model's own rate), found one", inv.action),
            ));
        }
    }
    let mut ask = match inv.kind {
        Action::Move => Ask::Nothing,
        Action::ChangeSpeed | Action::AssignSpeed => Ask::Desired(speed_target(inv, p)?),
        Action::KeepSpeed => Ask::Keep,
        Action::RemainStationary => Ask::Desired(0.0),
        _ => {
            return Err(p.site.err(
                K::Unsupported,
                format!("expected drive(), move(), change_speed(…), assign_speed(…), keep_speed() or remain_stationary() of random traffic `{g}` after its creation (each member's driver model takes a desired speed from them), found {}(…)", inv.action),
            ))
        }
    };
    for m in &inv.modifiers {
        match m.kind {
            ModKind::AvoidCollisions => check_avoid(g, m)?,
            // Implied by the action itself (keep_speed(), remain_stationary()).
            ModKind::KeepSpeed | ModKind::KeepPosition if m.name == inv.action => {}
            ModKind::Speed if inv.kind == Action::Move && m.at != At::End => match desired(g, m)? {
                Some(v) => ask = Ask::Desired(v),
                None => return Err(refused(g, m)),
            },
            _ => return Err(refused(g, m)),
        }
    }
    Ok((ask, positive(inv, "duration")?))
}

/// The error at modifier `m`, which no member's model takes after the group's creation.
fn refused(g: &str, m: &Modifier) -> Error {
    m.site.err(
        K::Unsupported,
        format!("expected speed(v) on a drive or avoid_collisions(true) beside an action of random traffic `{g}` after its creation (its members' driver model takes a desired speed), found `{}(…)`", m.name),
    )
}

impl Planner<'_> {
    /// What the creating phase `inv` of random traffic `g` asks (module doc): the desired
    /// speed (its `speed(v)`, 0 for `remain_stationary()`, else the default), whether an
    /// `along(r)` on a route the runtime chooses (the plan's roads in +s, where the members
    /// then are) keeps the members to that route's direction, the lane `lane(n [, from:
    /// left])` puts them in, and whether they keep their lanes (`keep_lane()`, `follow_lane()`,
    /// `lane(n)` at: all); any other modifier is an error at it.
    pub(super) fn creation(&self, g: &str, inv: Option<&Invoke>) -> Result<Creation, Error> {
        let mut c = Creation {
            v0: DEFAULT_SPEED,
            along: false,
            lane: None,
            keep_lane: false,
            beside: None,
        };
        let Some(inv) = inv else {
            return Ok(c);
        };
        for m in &inv.modifiers {
            match (m.kind, &m.along) {
                (ModKind::Speed, _) if m.at != At::End => match desired(g, m)? {
                    Some(v) => c.v0 = v,
                    None => return Err(self.refused_at_creation(g, m)),
                },
                (ModKind::KeepPosition, _) if m.name == inv.action => c.v0 = 0.0,
                (ModKind::KeepLane, _) => c.keep_lane = true,
                (ModKind::AvoidCollisions, _) => check_avoid(g, m)?,
                (ModKind::Lane, _) if m.at != At::End && self.lane_beside(m).is_some() => {
                    let (key, x) = self.lane_beside(m).unwrap_or_default();
                    let n = m.arg("lane").map(Arg::number).transpose()?.unwrap_or(1.0);
                    let left = match key {
                        "same_as" => 0,
                        "left_of" => 1,
                        "right_of" => -1,
                        _ => match m.arg("side").map(Arg::eval).transpose()? {
                            Some(Val::Enum(s)) if s == "right" => -1,
                            _ => 1,
                        },
                    };
                    if n < 1.0 || n.fract() != 0.0 {
                        return Err(m.site.err(
                            K::Modifier,
                            format!("expected a number of lanes of 1 or more in lane(…) of random traffic `{g}`, found {n}"),
                        ));
                    }
                    c.beside = Some(Beside {
                        x,
                        by: left * n as i64,
                        site: m.site.clone(),
                    });
                    c.keep_lane |= m.at == At::All;
                }
                (ModKind::Lane, _) if m.at != At::End && m.args.len() <= 2 => {
                    let n = m.arg("lane").map(Arg::number).transpose()?;
                    let from = m.arg("from").map(Arg::eval).transpose()?;
                    let (Some(n), true) = (n, m.args.len() == 1 || from.is_some()) else {
                        return Err(self.refused_at_creation(g, m));
                    };
                    let from_left = matches!(from, Some(Val::Enum(f)) if f == "left");
                    if n < 1.0 || n.fract() != 0.0 {
                        return Err(m.site.err(
                            K::Modifier,
                            format!("expected a lane number of 1 or more in lane(…) of random traffic `{g}`, found {n}"),
                        ));
                    }
                    c.lane = Some((n as i64, from_left));
                    c.keep_lane |= m.at == At::All;
                }
                // A route field the scenario leaves to the runtime and nothing binds: the
                // plan's roads, all of whose driving lanes the members may use.
                (
                    ModKind::Along,
                    Some(Along {
                        route:
                            Route::Free {
                                field,
                                one_lane: false,
                            },
                        ..
                    }),
                ) if !self.route_lanes.contains_key(field)
                    && !self.route_roads.contains_key(field)
                    && !self.against_routes.contains_key(field) =>
                {
                    c.along = true;
                }
                _ => return Err(self.refused_at_creation(g, m)),
            }
        }
        Ok(c)
    }

    /// The reference of `lane(…)` `m` to another actor of the plan (not of random traffic):
    /// the key (`same_as`, `side_of`, `left_of`, `right_of`) and the actor.
    fn lane_beside(&self, m: &Modifier) -> Option<(&'static str, String)> {
        ["same_as", "side_of", "left_of", "right_of"]
            .into_iter()
            .find_map(|k| {
                let x = m.arg(k)?.path.clone()?;
                (self.index.contains_key(&x) && !self.random_member(&x)).then_some((k, x))
            })
    }

    /// The error at modifier `m` of the phase that creates random traffic `g`.
    fn refused_at_creation(&self, g: &str, m: &Modifier) -> Error {
        m.site.err(
            K::Unsupported,
            format!("expected speed(v), lane(n [, from: left]) or lane(same_as/side_of/left_of/right_of: x) at: start or all, keep_lane(), avoid_collisions(true) or along(r) on a route the runtime chooses on the phase that creates random traffic `{g}` (its members' desired speed, lanes and roads; the engine's driver model does the rest), found `{}(…)`", m.name),
        )
    }

    /// Plans action `inv` (phase `p`, starting at `t0`) of random traffic `inv.actor` after
    /// its creation: a SpeedAction (a step) per member, which the engine hands to the
    /// member's model as its desired speed, into `out`. Returns the phase's end when the
    /// action sets it (module doc).
    pub(super) fn plan_random_traffic_action(
        &self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
        out: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        let (ask, own) = ask(p, inv)?;
        let members = &self.groups[&inv.actor];
        for (i, m) in members.iter().enumerate() {
            let target = match ask {
                Ask::Nothing => continue,
                Ask::Desired(v) => SpeedTarget::Absolute(v),
                Ask::Keep => SpeedTarget::Relative {
                    entity_ref: m.clone(),
                    value: 0.0,
                    speed_target_value_type: SpeedTargetValueType::Delta,
                    continuous: false,
                },
            };
            out.push(Planned::with_phase(
                m,
                format!("{}/{m}/{}:{}", p.path, i + 1, inv.action),
                step_speed(target),
                &p.site,
            ));
        }
        let instant = matches!(inv.kind, Action::ChangeSpeed | Action::AssignSpeed);
        Ok(match own {
            Some(d) => Some(self.ends(t0, d, "", p)),
            None if instant => Some(self.ends(t0, 0.0, "", p)),
            None => None,
        })
    }
}
