//! The actions that put an actor somewhere or turn it (ASAM OpenSCENARIO DSL 2.1 §8.8.2.4
//! `assign_position`, §8.8.2.5 `assign_orientation`, §8.8.2.11 `change_position`), as the
//! standard's tables say when each starts and ends:
//!
//! | action | lowered to | ends |
//! | --- | --- | --- |
//! | `assign_position(position \| route_point \| odr_point)` | TeleportAction to the lane position of the place on the plan road | at once (given its own `duration:`, the phase lasts it: `schedule`) |
//! | `assign_orientation(target)` | TeleportAction to where the actor is, the orientation absolute (world yaw, pitch, roll); the actor must stand (at a start the plan knows, its track's speed then; after a run-time condition the engine's check at the start, `runtime_kept::standing_check`: the plan's last speed is not a member of random traffic's, whose model moves it) | at once |
//! | `change_position(target, on_road_network: true)` | along its lane at its speed to the target's s, into the target's lane (LaneChangeAction) or offset (LaneOffsetAction), sinusoidal over exactly that time | when the actor is there |
//! | `change_position(target, interpolation)` | FollowTrajectoryAction along the straight line from where the actor is to the target (at a known start a six-dimensional Polyline that leaves the actor facing along the target's lane where it ends, `path_shape::line_ending_along`), or (`smooth`) the cubic Hermite curve from the actor's heading along its lane into the lane's heading at the target (`path_shape`), at its speed (after a run-time condition the same line from where the engine finds the actor when the action starts, oscsim's LineFromActor shape, or the curve from the actor's pose then, oscsim's SmoothFromActor shape) | when the actor is there |
//!
//! Exactly one of the three arguments is given (none is a missing argument, two contradict).
//! The place must be in a driving lane of the plan road (the road the planner moves actors on):
//! an `odr_point` names the road, lane, s and t (from the lane's centre); a `route_point` is s and
//! t on the route, which the runtime binds to the plan road (t from its reference line); a
//! `position_3d` is projected onto the road (z is the road surface's). The engine gets the lane
//! position, so the actor goes on along that lane with the speed it had. The engine puts it there
//! at the end of the step the action runs in, in place of that step's motion, as for a 1.x
//! TeleportAction; the plan does the same.
//!
//! For an actor driving against s (`crate::road`) the plan road is the view of its direction:
//! the place is located there (u along its travel, t to its left, a lane driven its way, else
//! an error), an `odr_point` on any of the plan's roads in OpenDRIVE's own s and t, a
//! `route_point` along its route (a route field bound against s: u and t to its left; else
//! the plan road in +s), and the TeleportAction's LanePosition is turned back to the road's s
//! and t (`PlanRoad::lane_position`).
//!
//! On a vehicle group (the library's group forms, non-normative §8.7.18) `assign_position` and
//! `change_position` move the formation as a whole: member 0 to the place, each other member to
//! the place shifted by its offset from member 0 at the action's start (`formation_place`);
//! after a run-time condition the offset the plan last knows, which the engine checks then.
//! For a group driving against s the offsets are the view's (along the direction of travel and
//! to the drivers' left), and the check carries the direction (`Planner::chain`).

use std::f64::consts::PI;

use scenario::{
    DynamicsShape, FollowingMode, LaneChangeAt, LaneChangeTarget, LaneOffsetTarget, LateralAction,
    Orientation, Position, PositionKind, PrivateAction, ReferenceContext, SpeedGap, StateCheck,
};

use super::action_args::timed;
use super::path_shape;
use super::planner::Planner;
use super::runtime_kept::standing_check;
use super::speed_actions::Slot;
use super::types::{Planned, When, LATERAL_TOLERANCE, MAX_ACCELERATION, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{arg, Action, Invoke, Phase, Place, PlaceArg, Val};

impl Planner<'_> {
    /// Plans `inv`'s position action for one actor; returns when it ends on its own.
    pub(super) fn plan_position_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            out,
            formation,
            ..
        } = slot;
        if inv.kind == Action::AssignOrientation {
            return self.plan_orientation(p, inv, target, t0, out, name);
        }
        if inv.kind == Action::ChangePosition {
            return self.plan_change_position(p, inv, (target, formation), t0, out, name);
        }
        if inv.kind != Action::AssignPosition {
            return Ok(None);
        }
        let given = &inv.places;
        let place = match given.as_slice() {
            [] => {
                return Err(p.site.err(
                    K::Argument,
                    "expected a position, route_point or odr_point in assign_position(…) (one is mandatory), found none",
                ))
            }
            [one] => one,
            [a, b, ..] => {
                return Err(b.site.err(
                    K::Argument,
                    format!(
                        "expected one of position, route_point and odr_point in assign_position(…), found `{}` and `{}`",
                        a.param, b.param
                    ),
                ))
            }
        };
        let (lane, s, offset) = self.formation_place(
            p,
            inv,
            (target, formation),
            (self.lane_position(place)?, &place.site),
            out,
        )?;
        let n = name("assign_position");
        // On the road that holds s, in its own s and t (against s the plan's s is u, its t −t).
        let (road, road_s, road_offset) = self.road.lane_position(s, offset);
        out.push(Planned::with_phase(
            target,
            n.clone(),
            PrivateAction::Teleport(Position {
                kind: PositionKind::Lane {
                    road_id: road.id.clone(),
                    lane_id: lane.to_string(),
                    s: road_s,
                    offset: Some(road_offset),
                    orientation: None,
                },
                pos: place.site.pos.clone(),
            }),
            &p.site,
        ));
        if let Some(t) = t0 {
            // The engine puts the actor there at the end of the step the action runs in, in
            // place of that step's motion (as a 1.x TeleportAction).
            let dt = self.settings.dt;
            let ahead = self.s_at(target, t + dt);
            // The track's distance runs along its lane at time 0 (`Track::s_on`), followed
            // along its links to `ahead`: the jump is measured on from there.
            let lane0 = self.lane_now(target, 0.0);
            let lane0 = self.road.lane_along(lane0, self.s_at(target, 0.0), ahead);
            let d = self.road.lane_distance(lane0, ahead, s);
            let tr = self.track_mut(target);
            tr.jump(t, d);
            tr.set_lane(t, lane);
            tr.set_offset(t, offset);
        }
        Ok(Some(self.ends(t0, 0.0, &n, p)))
    }

    /// `assign_orientation(target)`: a TeleportAction to where the actor is, with the
    /// orientation as absolute yaw, pitch and roll.
    fn plan_orientation(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        target: &str,
        t0: Option<f64>,
        out: &mut Vec<Planned>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Some(PlaceArg {
            place: Place::Orientation { yaw, pitch, roll },
            site,
            ..
        }) = inv.places.first()
        else {
            return Err(p.site.err(
                K::Argument,
                "expected a target in assign_orientation(…) (a mandatory argument, an orientation_3d), found none",
            ));
        };
        // A moving vehicle goes on along its lane while the engine keeps the heading it was
        // given: a sideways-facing vehicle driving straight on, which no scenario means.
        match t0 {
            Some(t) => {
                let v = self.track(target).at(t).1;
                if v.abs() > 1e-9 {
                    return Err(p.site.err(
                        K::Unsatisfiable,
                        format!("expected `{target}` standing at the start of assign_orientation(…) (a moving vehicle follows its lane), found it at {v:.2} m/s"),
                    ));
                }
            }
            // After a run-time start the speed is the run's: the plan's last speed is not the
            // actor's after a gap action, nor ever a member of random traffic's (its driver
            // model's), so the engine checks it then, before the turn.
            None => out.push(standing_check(
                target,
                ("assign_orientation", &p.site),
                name("check"),
            )),
        }
        let n = name("assign_orientation");
        out.push(Planned::with_phase(
            target,
            n.clone(),
            PrivateAction::Teleport(Position {
                kind: PositionKind::RelativeObject {
                    entity_ref: target.to_string(),
                    dx: 0.0,
                    dy: 0.0,
                    dz: None,
                    orientation: Some(Orientation {
                        h: *yaw,
                        p: *pitch,
                        r: *roll,
                        reference: Some(ReferenceContext::Absolute),
                    }),
                },
                pos: site.pos.clone(),
            }),
            &p.site,
        ));
        Ok(Some(self.ends(t0, 0.0, &n, p)))
    }

    /// `change_position(target, interpolation)`: a FollowTrajectoryAction along the straight
    /// line (or, `smooth`, the Hermite curve from the actor's heading along its lane into the
    /// lane's heading at the target) from where the actor is to the target, at the speed it
    /// has (no time reference), ending there.
    fn plan_change_position(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        (target, formation): (&str, Option<(f64, f64)>),
        t0: Option<f64>,
        out: &mut Vec<Planned>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Some(place) = inv.places.first() else {
            return Err(p.site.err(
                K::Argument,
                "expected a target in change_position(…) (a mandatory argument, a position_3d), found none",
            ));
        };
        let smooth =
            match arg(&inv.args, "interpolation") {
                Some(a) => match a.eval()? {
                    Val::Enum(m) if m == "straight_line" => false,
                    Val::Enum(m) if m == "smooth" => true,
                    _ => return Err(a.site.err(
                        K::Argument,
                        "expected an interpolation (straight_line, smooth), found another value",
                    )),
                },
                None => false,
            };
        let on_road = match arg(&inv.args, "on_road_network") {
            Some(a) => match a.eval()? {
                Val::Bool(b) => Some((a, b)),
                _ => {
                    return Err(a
                        .site
                        .err(K::Argument, "expected a bool, found another value"))
                }
            },
            None => None,
        };
        let (lane, s1, offset) = self.formation_place(
            p,
            inv,
            (target, formation),
            (self.lane_position(place)?, &place.site),
            out,
        )?;
        if let Some((a, true)) = on_road {
            if smooth {
                return Err(a.site.err(
                    K::Argument,
                    "expected on_road_network: true without interpolation: smooth (on the road network the actor follows its lanes), found both",
                ));
            }
            let Some(t) = t0 else {
                return self.change_position_on_road_at_run_time(
                    p,
                    target,
                    (lane, s1, offset),
                    out,
                    name,
                );
            };
            return self.change_position_on_road(p, target, t, (lane, s1, offset), out, name);
        }
        let road = &self.road;
        let Some(t) = t0 else {
            // After a run-time condition the path starts where the engine finds the actor: the
            // smooth curve from its pose then (oscsim's SmoothFromActor, whose tangents the
            // engine scales with the chord it finds), or the straight line from its point then
            // (oscsim's LineFromActor: facing along the line, then along the target's lane
            // where it ends, as at a known start), at the speed it has then; the phase ends
            // with the action.
            let Some(end) = road.world_pose(s1, road.lane_center(lane, s1) + offset) else {
                return Err(off_road(&place.site, road.id(), s1, "its length"));
            };
            let n = name("change_position");
            let mode = FollowingMode::Position;
            let action = path_shape::from_actor(&n, end, smooth, mode, &place.site);
            out.push(Planned::with_phase(target, n.clone(), action, &p.site));
            return Ok(Some(self.ends(None, 0.0, &n, p)));
        };
        let tr = self.track(target);
        let (lane0, v) = (self.lane_now(target, t), tr.at(t).1);
        let s0 = self.s_at(target, t);
        let start = road.world_pose(s0, road.lane_center(lane0, s0) + tr.offset(t));
        let end = road.world_pose(s1, road.lane_center(lane, s1) + offset);
        let (Some(from), Some(to)) = (start, end) else {
            return Err(off_road(&place.site, road.id(), s1, "its length"));
        };
        let ((x0, y0, _), (x1, y1, _)) = (from, to);
        // Smooth: from the actor's heading along its lane into the lane's heading at the target
        // (the target has no orientation of its own; the actor drives on along that lane).
        let length = if smooth {
            path_shape::length(&[from, to])
        } else {
            (x1 - x0).hypot(y1 - y0)
        };
        if v <= 0.0 && length > 0.0 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` moving at the start of change_position(…) (it moves at the speed it has), found it standing"),
            ));
        }
        let n = name("change_position");
        out.push(Planned::with_phase(
            target,
            n.clone(),
            if smooth && length > 0.0 {
                path_shape::smooth(&n, &[from, to], None, FollowingMode::Position, &place.site)
            } else if length > 0.0 {
                // Facing along the line, then along the target's lane where it ends (issue
                // 27: the default controller keeps the heading it is handed, so a line's
                // heading kept would drive the actor on crabwise along its lane).
                path_shape::line_ending_along(&n, (x0, y0), to, &place.site)
            } else {
                path_shape::polyline(
                    &n,
                    &[(x0, y0), (x1, y1)],
                    None,
                    FollowingMode::Position,
                    &place.site,
                )
            },
            &p.site,
        ));
        // Along the line at v: there after length / v s; the track's distance along its lane
        // is then set to the target's s.
        let span = if length > 0.0 { length / v } else { 0.0 };
        let tr = self.track_mut(target);
        tr.jump(t + span, s1 - (s0 + v * span));
        tr.set_lane(t + span, lane);
        tr.set_offset(t + span, offset);
        tr.add_move(t, t + span);
        Ok(Some(self.ends(t0, span, &n, p)))
    }

    /// `change_position(target, on_road_network: true)`: along the road network to the target.
    /// The actor drives on along its lane at its speed to the target's s, moving sideways into
    /// the target's lane and offset over exactly the time T it takes to get there (the lane
    /// distance, at v along its path less the sideways part): a
    /// LaneChangeAction to the target lane (absolute id, targetLaneOffset), or in its own lane a
    /// LaneOffsetAction, sinusoidal over T, so that it arrives across the road when it arrives
    /// along it. The target must be ahead, and the sinusoid within the vehicle's lateral
    /// acceleration (π²Δ/(2T²) ≤ 10 m/s²).
    /// `change_position(…, on_road_network: true)` of `target` to (`lane`, plan s `s1`,
    /// `offset`) after a run-time condition: the engine's lane change that arrives there
    /// (`LateralAction::LaneChangeAt`), sinusoidal over the distance along the actor's lane
    /// from where it is then to s1, at the speed it has; the phase ends with the action (the
    /// actor there). On a plan over several roads s1 is the plan's s, and the engine measures
    /// the way along the actor's lane across the roads' joints.
    fn change_position_on_road_at_run_time(
        &mut self,
        p: &Phase,
        target: &str,
        (lane, s1, offset): (i32, f64, f64),
        out: &mut Vec<Planned>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        // On a plan over several roads the engine measures the way in the plan's s, across
        // the roads' joints; on one road in the road's own s.
        let roads = self.chain();
        let s = match roads.chain.is_empty() {
            true => self.road.road_at(s1).1,
            false => s1,
        };
        let n = name("change_position");
        let at = LaneChangeAt {
            target: LaneChangeTarget::Absolute(lane.to_string()),
            target_lane_offset: (offset != 0.0).then_some(offset),
            shape: DynamicsShape::Sinusoidal,
            s,
            roads,
            what: format!("change_position(…) at {}", p.site.at()),
        };
        out.push(Planned::with_phase(
            target,
            n.clone(),
            PrivateAction::Lateral(LateralAction::LaneChangeAt(Box::new(at))),
            &p.site,
        ));
        Ok(Some(self.ends(None, 0.0, &n, p)))
    }

    fn change_position_on_road(
        &mut self,
        p: &Phase,
        target: &str,
        t: f64,
        (lane, s1, offset): (i32, f64, f64),
        out: &mut Vec<Planned>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let road = &self.road;
        let tr = self.track(target);
        let (lane0, o0, v) = (self.lane_now(target, t), tr.offset(t), tr.at(t).1);
        let s0 = self.s_at(target, t);
        if s1 <= s0 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected the target of change_position(…, on_road_network: true) ahead of `{target}` (s = {s0:.2} m), found it at s = {s1:.2} m: on the road network an actor drives forward"),
            ));
        }
        if v <= 0.0 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` moving at the start of change_position(…) (it moves at the speed it has), found it standing"),
            ));
        }
        let distance = road.lane_distance(lane0, s0, s1);
        // Its lane at s1: the one it is in followed along its links (a lane section between
        // may renumber it).
        let lane0 = road.lane_along(lane0, s0, s1);
        let delta = road.lane_center(lane, s1) + offset - (road.lane_center(lane0, s1) + o0);
        // The engine moves the actor at v along its path, so along the road at
        // √(v² − ẏ²) while the sinusoid ẏ = (πΔ/2T)·sin(πt/T) moves it sideways: T solves
        // T·∫₀¹ √(v² − (πΔ/2T)² sin²(πu)) du = distance (a fixed point from distance / v,
        // a contraction while the lateral speed stays well below v).
        let mut span = distance / v;
        for _ in 0..50 {
            let lateral = PI * delta.abs() / (2.0 * span);
            if lateral >= v {
                break;
            }
            let along =
                path_shape::integrate01(|u| (v * v - (lateral * (PI * u).sin()).powi(2)).sqrt());
            let next = distance / along;
            let done = (next - span).abs() < 1e-12;
            span = next;
            if done {
                break;
            }
        }
        let peak = super::motion::sinusoid_peak_acceleration(delta, span);
        if peak > MAX_ACCELERATION + 1e-9 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected change_position(…, on_road_network: true) within the vehicle's ±{MAX_ACCELERATION} m/s² lateral acceleration, found it needs {peak:.2} m/s² to move {:.2} m sideways in {span:.2} s", delta.abs()),
            ));
        }
        let n = name("change_position");
        let action = if lane != lane0 {
            LateralAction::LaneChange {
                target_lane_offset: (offset != 0.0).then_some(offset),
                dynamics: timed(DynamicsShape::Sinusoidal, span),
                target: LaneChangeTarget::Absolute(lane.to_string()),
            }
        } else {
            LateralAction::LaneOffset {
                continuous: false,
                dynamics_shape: DynamicsShape::Sinusoidal,
                max_lateral_acc: Some(peak),
                target: LaneOffsetTarget::Absolute(offset),
            }
        };
        if lane != lane0 || delta.abs() > 1e-9 {
            out.push(Planned::with_phase(
                target,
                n.clone(),
                PrivateAction::Lateral(action),
                &p.site,
            ));
        }
        let tr = self.track_mut(target);
        tr.set_lane(t + span, lane);
        tr.set_offset(t + span, offset);
        tr.add_move(t, t + span);
        // Ends when it is there: at the planned time (the lateral action ends with it).
        Ok(Some(self.ends(Some(t), span, "", p)))
    }

    /// The lane, s and offset from the lane's centre of `place` on the plan road.
    pub(super) fn lane_position(&self, place: &PlaceArg) -> Result<(i32, f64, f64), Error> {
        let site = &place.site;
        let road = &self.road;
        // Against s (`crate::road`) the view's s is u = L − s and its t is −t.
        let sign = if road.is_against() { -1.0 } else { 1.0 };
        let (s, t) = match &place.place {
            Place::Lane {
                road: id,
                lane,
                s,
                t,
            } => {
                let Some(u) = road.plan_s(id, *s) else {
                    return Err(site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected a place on one of roads {} (the roads the plan drives on), found road {id}",
                            road.ids().join(", ")
                        ),
                    ));
                };
                let within = (0.0..=road.length()).contains(&u);
                if !within || !road.driving_lanes(u).contains(lane) {
                    let why = format!("lane {lane}{}", its_lanes(road, u));
                    return Err(off_road(site, id, *s, &why));
                }
                (u, road.lane_center(*lane, u) + sign * t)
            }
            // s and t on its route: the plan road's in +s, or along a route field bound to
            // the plan's roads against s (`against::bind_routes`) and to its left; turned to
            // this view where the two directions differ.
            Place::Route { s, t, route } => {
                let back = route
                    .as_ref()
                    .is_some_and(|r| self.against_routes.contains_key(r));
                if back == road.is_against() {
                    (*s, *t)
                } else {
                    (road.length() - s, -t)
                }
            }
            Place::World { x, y, .. } => road
                .locate(*x, *y)
                .map(|(lane, s, offset)| (s, road.lane_center(lane, s) + offset))
                .ok_or_else(|| {
                    site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected a position the plan road {} projects, found none",
                            road.id()
                        ),
                    )
                })?,
            Place::Orientation { .. }
            | Place::Trajectory { .. }
            | Place::Path { .. }
            | Place::RoadPath { .. }
            | Place::Relative { .. } => {
                return Err(site.err(K::Argument, "expected a place, found another value"))
            }
        };
        self.lane_at(site, s, t)
    }

    /// The driving lane holding the road point (s, t) of the plan road, with the offset from
    /// its centre; an error at `site` where there is none.
    fn lane_at(&self, site: &Site, s: f64, t: f64) -> Result<(i32, f64, f64), Error> {
        let road = &self.road;
        if !(0.0..=road.length()).contains(&s) {
            return Err(off_road(site, road.id(), s, "its length"));
        }
        let lane = road.lane_holding(s, t).ok_or_else(|| {
            // Named in the road's own s and t (against s the view's are u and −t).
            let (on, road_s, road_t) = road.lane_position(s, t);
            let why = format!("t = {road_t:.2} m{}", its_lanes(road, s));
            off_road(site, &on.id, road_s, &why)
        })?;
        Ok((lane, s, t - road.lane_center(lane, s)))
    }

    /// The place of `target` when `inv` on a vehicle group moves its formation as a whole:
    /// member 0 goes to `place` (lane, s, offset), every other member to `place` shifted by its
    /// own offset from member 0 along and across the road at the action's start (`formation`,
    /// from the plan), so that the members keep their places in the formation (and do not all
    /// go to one point). Not a group's action: `place` itself.
    ///
    /// After a run-time condition (`formation` `None`) the offset is the one the plan last
    /// knows, and the engine checks it when the action starts, before any member moves
    /// (oscsim's StateCheck on `target`, first among the phase's actions in `out`: its s less
    /// member 0's within 0.5 m, its t less member 0's within 1 cm); a formation that has
    /// changed since is an error record and a failed run, never a member moved by an offset
    /// it no longer has.
    fn formation_place(
        &self,
        p: &Phase,
        inv: &Invoke,
        (target, formation): (&str, Option<(f64, f64)>),
        ((lane, s, offset), site): ((i32, f64, f64), &Site),
        out: &mut Vec<Planned>,
    ) -> Result<(i32, f64, f64), Error> {
        let Some(lead) = self.groups.get(&inv.actor).and_then(|m| m.first()) else {
            return Ok((lane, s, offset));
        };
        if lead == target {
            return Ok((lane, s, offset));
        }
        let (ds, dt) = match formation {
            Some(f) => f,
            None => {
                let (check, (ds, dt)) = self.formation_check(inv, &p.site, target)?;
                let name = format!("{}/{target}/formation:check", p.path);
                let action = PrivateAction::Check(check);
                out.insert(0, Planned::with_phase(target, name, action, &p.site));
                (ds, dt)
            }
        };
        let (s1, t1) = (s + ds, self.road.lane_center(lane, s) + offset + dt);
        self.lane_at(site, s1, t1).map_err(|_| {
            site.err(
                K::Unsatisfiable,
                format!(
                    "expected `{target}` in a driving lane of road {} when {}(…) moves group `{}` as a whole (its offset from `{lead}`: {ds:.2} m along the road, {dt:.2} m across it), found s = {s1:.2} m, t = {t1:.2} m outside them",
                    self.road.id(),
                    inv.action,
                    inv.actor
                ),
            )
        })
    }
}

impl Planner<'_> {
    /// After a run-time condition, member `target` of group `inv.actor` is taken at the offset
    /// (ds, dt) from member 0 the plan last knows; the engine's check of it when the action at
    /// `site` starts (oscsim's StateCheck on `target`: its s less member 0's within 0.5 m, its
    /// t less member 0's within 1 cm), and the offset. On a plan of one road (the engine
    /// measures s on the road the actor is on).
    pub(super) fn formation_check(
        &self,
        inv: &Invoke,
        site: &Site,
        target: &str,
    ) -> Result<(Box<StateCheck>, (f64, f64)), Error> {
        let lead = self
            .groups
            .get(&inv.actor)
            .and_then(|m| m.first())
            .map_or(target, String::as_str);
        if self.road.ids().len() > 1 {
            return Err(site.err(
                K::Unsatisfiable,
                format!("expected a plan on one road for {}(…) on group `{}` after a run-time condition (the engine checks each member's offset from `{lead}` in road coordinates on the road it is on), found {} roads", inv.action, inv.actor, self.road.ids().len()),
            ));
        }
        let t = self.last_known();
        let (ds, dt) = (
            self.s_at(target, t) - self.s_at(lead, t),
            self.t_at(target, t) - self.t_at(lead, t),
        );
        let check = StateCheck {
            what: format!(
                "`{target}`'s offset from `{lead}` in group `{}`, {ds:.2} m along the road and {dt:.2} m across it as at {t:.2} s, kept by {}(…) at {}",
                inv.actor,
                inv.action,
                site.at()
            ),
            gap: Some((
                SpeedGap {
                    entity_ref: lead.to_string(),
                    ahead: ds > 0.0,
                    time: 0.0,
                    at_least: ds.abs(),
                },
                POSITION_TOLERANCE,
            )),
            beside: Some((lead.to_string(), dt, LATERAL_TOLERANCE)),
            // Against s the offset is along the direction of travel and to the drivers' left
            // (the view's u and t): the engine measures it so with the direction.
            roads: self.chain(),
            ..StateCheck::default()
        };
        Ok((Box::new(check), (ds, dt)))
    }
}

/// For an actor driving against s, the lanes it may be in at the view's s `u` (an error's
/// note); nothing in +s.
fn its_lanes(road: &crate::road::PlanRoad<'_>, u: f64) -> String {
    if road.is_against() {
        format!(
            " (the actor drives against s, in lanes {:?})",
            road.driving_lanes(u)
        )
    } else {
        String::new()
    }
}

/// The error of a place outside the plan road's driving lanes.
fn off_road(site: &Site, road: &str, s: f64, what: &str) -> Error {
    site.err(
        K::Unsatisfiable,
        format!("expected a place in a driving lane of road {road}, found s = {s:.2} m, {what} outside them"),
    )
}
