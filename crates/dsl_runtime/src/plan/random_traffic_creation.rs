//! What the phase creating a `random_traffic_vehicle_group` asks (ASAM OpenSCENARIO DSL 2.1
//! §8.7.18.1, non-normative: "the group defines the initial conditions of actors in the
//! scenario, meaning their creation and destruction. The behavioral model assigned to each
//! vehicle defines the actual behavior of the vehicle within the group"): its modifiers read
//! as where and how the members are created, never as a motion of theirs (`random_traffic`
//! deals them, `random_traffic_late` creates them later).
//!
//! | modifier on the creating phase | the members |
//! | --- | --- |
//! | `speed(v)` | desired speed v (start speeds drawn around it) |
//! | `position(d, at: start)` | dealt only from d on, along each lane's direction of travel (u ≥ d: the place the group's noise begins; the standard's position of one actor, its s along the route, is where the group starts) |
//! | `lane(n [, from: left])`, `lane(…: x)` at: start or all | dealt to that lane of each direction, or x's lane or the one beside it in x's direction (x may drive against s); at: all kept there |
//! | `keep_lane()` | kept in their lanes (the IDM without MOBIL) |
//! | `avoid_collisions(true)` | what their model does |
//! | `along(r)` | r free: the plan's roads (+s only); r a lane field: only that lane, in its direction (bound by another actor along it, or by the map's modifiers: then over its lane section's stretch only); r a road the map's modifiers bound: only its lane over its stretch; r bound against s (`routes_are_opposite`): only the lanes driven in −s |
//!
//! Bad input (`ErrorKind::Modifier`, at the modifier): `position` at: all or end, or relative
//! to another actor (a group of noise vehicles has no one place to hold or to put ahead of
//! x), `lateral`, `distance`, `yaw`/`orientation`, `acceleration` and every other motion
//! modifier: each member's motion is its model's.

use super::place::DEFAULT_SPEED;
use std::collections::HashMap;

use super::place::Start;
use super::planner::Planner;
use super::random_traffic_actions::{check_avoid, desired, side_sign};
use super::types::{Beside, Creation, RouteOnly};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Along, Arg, At, Invoke, ModKind, Modifier, Route, Val};

impl Planner<'_> {
    /// The lane `c` asks for, relative to another actor `x` there: x driving against s
    /// (`back`), in lane `lx` at s `sx` (u against s): the direction and lane id the members
    /// are dealt to, or an error at the modifier when x is placed from members of random
    /// traffic (`x_at` `None`: a cycle) or no driving lane lies there.
    pub(super) fn beside_lane(
        &self,
        g: &str,
        b: &Beside,
        x_at: Option<(bool, i32, f64)>,
    ) -> Result<(bool, i32), Error> {
        let Some((back, lx, sx)) = x_at else {
            let why = match self.random.keys().find(|h| self.groups[*h].contains(&b.x)) {
                Some(h) if h == g => "a member of that group (dealt beside itself)".to_string(),
                Some(h) => format!("a member of random traffic `{h}`, dealt after `{g}` (the groups are dealt in the order of their names)"),
                None => "placed from members of random traffic (each would wait for the other's place)".to_string(),
            };
            return Err(b.site.err(
                K::Unsatisfiable,
                format!("expected `{}` placed before random traffic `{g}` is dealt beside it, found it {why}", b.x),
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
            from_u: None,
            route: None,
            lane_field: None,
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
                // Implied by keep_speed() creating the group (each member's speed as drawn).
                (ModKind::KeepSpeed, _) if m.name == inv.action => {}
                (ModKind::Position, _) => c.from_u = Some(position_from(g, m)?),
                (ModKind::KeepLane, _) => c.keep_lane = true,
                (ModKind::AvoidCollisions, _) => check_avoid(g, m)?,
                (ModKind::Lane, _) if m.at != At::End && self.lane_beside(m).is_some() => {
                    let (key, x) = self.lane_beside(m).unwrap_or_default();
                    let n = m.arg("lane").map(Arg::number).transpose()?.unwrap_or(1.0);
                    let left = i64::from(side_sign(key, m)?);
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
                (ModKind::Lane, _) if m.at != At::End => {
                    let n = m.arg("lane").map(Arg::number).transpose()?;
                    let from = m.arg("from").map(Arg::eval).transpose()?;
                    // `at:` is the modifier's moment, no lane's argument.
                    let others = m
                        .args
                        .iter()
                        .any(|(k, _)| !matches!(k.as_str(), "lane" | "from" | "at"));
                    let (Some(n), false) = (n, others) else {
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
                                map_route: None,
                            },
                        ..
                    }),
                ) if !self.route_lanes.contains_key(field)
                    && !self.route_roads.contains_key(field)
                    && !self.against_routes.contains_key(field) =>
                {
                    c.along = true;
                }
                (ModKind::Along, Some(Along { route, .. })) => match self.route_of(g, m, route)? {
                    Some(r) => c.route = Some(r),
                    None => {
                        if let Route::Free { field, .. } = route {
                            c.lane_field = Some(field.clone());
                        }
                    }
                },
                _ => return Err(self.refused_at_creation(g, m)),
            }
        }
        Ok(c)
    }

    /// The reference of `lane(…)` `m` to another actor (a member of random traffic too): the
    /// key (`same_as`, `side_of`, `left_of`, `right_of`) and the actor.
    fn lane_beside(&self, m: &Modifier) -> Option<(&'static str, String)> {
        ["same_as", "side_of", "left_of", "right_of"]
            .into_iter()
            .find_map(|k| {
                let x = m.arg(k)?.path.clone()?;
                self.index.contains_key(&x).then_some((k, x))
            })
    }

    /// The route of `along(r)` `m` on the phase creating random traffic `g`: a lane field
    /// (its lane of the plan road), a road field the map's modifiers bound (its lane over its
    /// stretch of the plan's roads), or the plan's roads driven against s; anything else is
    /// an error at the modifier.
    /// `None`: a lane field not bound yet, which another actor along it binds.
    fn route_of(&self, g: &str, m: &Modifier, route: &Route) -> Result<Option<RouteOnly>, Error> {
        let (field, one_lane) = match route {
            Route::Free {
                field, one_lane, ..
            } => (field, *one_lane),
            _ => return Err(self.refused_at_creation(g, m)),
        };
        if let Some((lane, _)) = self.route_lanes.get(field) {
            // A lane the map's modifiers bound: its lane section's stretch of the plan.
            let span = self.lane_roads.get(field).and_then(|(_, span)| *span);
            return Ok(Some(RouteOnly {
                lane: Some(*lane),
                span,
                against: *lane > 0,
            }));
        }
        if let Some((lane, span, _)) = self.route_roads.get(field) {
            return Ok(Some(RouteOnly {
                lane: Some(*lane),
                span: Some(*span),
                against: *lane > 0,
            }));
        }
        if self.against_routes.contains_key(field) {
            return Ok(Some(RouteOnly {
                lane: None,
                span: None,
                against: true,
            }));
        }
        if one_lane {
            return Ok(None);
        }
        Err(self.refused_at_creation(g, m))
    }

    /// Binds creation `c`'s lane field (`along(r)`, r a `lane` no actor had bound when the
    /// creation was read) to the lane bound since, else to the lane another actor along r
    /// starts in (`starts`: the placed actors' starts); none: an error at the group `site`.
    pub(super) fn bind_lane_field(
        &self,
        g: &str,
        c: &mut Creation,
        starts: Option<&HashMap<String, Start>>,
        site: &Site,
    ) -> Result<(), Error> {
        let Some(field) = c.lane_field.take() else {
            return Ok(());
        };
        let bound = self.route_lanes.get(&field).map(|(l, _)| *l).or_else(|| {
            let starts = starts?;
            self.first_leaf.iter().find_map(|(actor, leaf)| {
                let along = self.alongs.get(leaf)?;
                let on = along
                    .iter()
                    .any(|(_, a)| matches!(&a.route, Route::Free { field: f, .. } if *f == field));
                (on && !self.random_member(actor)).then(|| starts.get(actor).map(|st| st.lane))?
            })
        });
        let Some(lane) = bound else {
            return Err(site.err(
                K::Modifier,
                format!("expected the lane `{field}` that random traffic `{g}` goes along bound by another actor along it (its members are dealt to that lane), found no actor along it"),
            ));
        };
        c.route = Some(RouteOnly {
            lane: Some(lane),
            span: None,
            against: lane > 0,
        });
        Ok(())
    }

    /// The error at modifier `m` of the phase that creates random traffic `g`: bad input, a
    /// place or motion the members' driver model defines (§8.7.18.1).
    fn refused_at_creation(&self, g: &str, m: &Modifier) -> Error {
        m.site.err(
            K::Modifier,
            format!("expected speed(v), position(d, at: start), lane(n [, from: left]) or lane(same_as/side_of/left_of/right_of: x) at: start or all, keep_lane(), avoid_collisions(true) or along(r) on the phase that creates random traffic `{g}` (its members' desired speed, lanes and roads: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\", §8.7.18.1, so no modifier sets a member's motion), found `{}(…)`", m.name),
        )
    }
}

/// The `d` of `position(d, at: start)` on the phase creating random traffic `g`; at: all or
/// end, or relative to another actor, an error at the modifier (module doc).
fn position_from(g: &str, m: &Modifier) -> Result<f64, Error> {
    let relative = ["ahead_of", "behind"].iter().any(|k| m.arg(k).is_some());
    if m.at != At::Start || relative {
        return Err(m.site.err(
            K::Modifier,
            format!("expected position(d, at: start) on the phase that creates random traffic `{g}` (the members dealt from d on), found it {} (a group of noise vehicles has no one place to hold or to put relative to another actor: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\", §8.7.18.1)", if relative { "relative to another actor" } else { "at: all or end" }),
        ));
    }
    let d = m
        .arg("distance")
        .map(Arg::number)
        .transpose()?
        .ok_or_else(|| {
            m.site.err(
                K::Modifier,
                format!("expected a distance in position(…) of random traffic `{g}`, found none"),
            )
        })?;
    if d < 0.0 {
        return Err(m.site.err(
            K::Modifier,
            format!("expected a distance of 0 m or more in position(…) of random traffic `{g}`, found {d} m"),
        ));
    }
    Ok(d)
}
