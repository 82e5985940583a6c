//! The actions that move an actor along given points (ASAM OpenSCENARIO DSL 2.1 §8.8.2.17
//! `follow_trajectory`, §8.8.2.16 `follow_path`), as the standard's tables say when each starts
//! and ends:
//!
//! | action | lowered to | ends |
//! | --- | --- | --- |
//! | `follow_trajectory(absolute: trajectory)` | FollowTrajectoryAction along the polyline of the points (world x, y), or with `smooth` the Hermite curve through them (a Nurbs), each reached at its time stamp (a relative time reference from the action's start, offset by the first stamp), following mode `position` | at the last time stamp |
//! | `follow_path(absolute: path)` | FollowTrajectoryAction along the path (`map.create_path(points, interpolation)`, or `create_path_odr_points`/`create_path_route_points`, their points placed on the network by `road_path`: polyline or smooth) in following mode `follow` (steered within the vehicle's limits), no time reference: at the speed the actor has | when the engine has the actor at the path's end |
//!
//! | `replay_path(…)`, `replay_trajectory(…)` | as the two above in following mode `position` (exactly; "the dynamic limits may be violated") | as above |
//!
//! A trajectory's points must be at least two, as many as its time stamps, the stamps rising,
//! and (`follow_trajectory`) no segment's length over its time above the vehicle's maximum
//! speed. `relative:` paths and trajectories are placed against their reference
//! (`relative_path`); `start_offset` and `end_offset` cut the part followed (`Cut`): the
//! engine's initialDistanceOffset, and the phase's end that far before the end. With
//! `interpolation: straight_line` the points' orientations are not read (the heading is the
//! polyline's); with `smooth` the path is the cubic Hermite curve through the points with their
//! yaws as headings (`path_shape`), its consecutive points apart. The actor is where the
//! followed part starts at the action's start (the engine's FollowTrajectoryAction in
//! `position` mode puts it on the trajectory); the plan puts it in the lane and at the s of
//! the followed part's end.

use scenario::{FollowingMode, PrivateAction};

use super::group_path::Member;
use super::group_path_runtime::{ColumnTimes, RunTimePlace};
use super::path_part::cut;
use super::path_shape::{
    along, along_at_speed, polyline_through, segment_lengths, starting_at, Pose2,
};
use super::planner::Planner;
use super::speed_actions::Slot;
use super::types::{Planned, When, MAX_SPEED};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Action, Invoke, Phase, Place, PlaceArg};

impl Planner<'_> {
    /// Plans `inv`'s `follow_trajectory` or `follow_path` for one actor; returns when it ends.
    pub(super) fn plan_trajectory_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let resolved = self.absolute_place(p, inv, slot.t0)?;
        let given = resolved
            .as_ref()
            .or_else(|| inv.places.iter().find(|a| a.param == "absolute"));
        // A member of a column behind member 0: its lead-in, then the path (group_path).
        let column = match (given, slot.t0, slot.formation, slot.group_speed) {
            (Some(g), Some(t), Some(formation), Some(group_speed)) => self.column_place(
                inv,
                g,
                (slot.target, t),
                Member {
                    formation,
                    group_speed,
                },
            )?,
            _ => None,
        };
        let given = column.as_ref().or(given);
        // After a run-time condition, a member of a group over several lanes (group_path).
        let run_time = match (given, slot.t0) {
            (Some(g), None) => self.run_time_place(g, inv, slot.target)?,
            _ => None,
        };
        let given = match &run_time {
            Some(RunTimePlace::Lead(check, part)) => {
                if let Some(check) = check {
                    let n = name("check");
                    let action = PrivateAction::Check(check.clone());
                    slot.out
                        .push(Planned::with_phase(slot.target, n, action, &p.site));
                }
                part.as_ref().or(given)
            }
            Some(RunTimePlace::Column(check, lead_in, column_times)) => {
                let n = format!("{}/{}/formation:check", p.path, slot.target);
                let action = PrivateAction::Check(check.clone());
                slot.out
                    .insert(0, Planned::with_phase(slot.target, n, action, &p.site));
                if let (
                    Some(ColumnTimes { lead, distances }),
                    Place::Trajectory {
                        points,
                        times,
                        smooth,
                    },
                ) = (column_times, &lead_in.place)
                {
                    // The stamps the engine completes with member 0's speed then.
                    let n = name(&inv.action);
                    let what = format!("{}(…) at {}", inv.action, lead_in.site.at());
                    let action = along_at_speed(
                        &n,
                        (points, times, distances),
                        *smooth,
                        (lead, what),
                        &lead_in.site,
                    );
                    slot.out
                        .push(Planned::with_phase(slot.target, n.clone(), action, &p.site));
                    return Ok(Some(self.ends(None, 0.0, &n, p)));
                }
                Some(lead_in)
            }
            Some(RunTimePlace::Relative(kinds, times)) => {
                let n = name(&inv.action);
                let mode = match inv.kind {
                    Action::FollowPath => FollowingMode::Follow,
                    _ => FollowingMode::Position,
                };
                let site = given.map_or(&p.site, |g| &g.site);
                let action = polyline_through(&n, kinds.clone(), times.as_deref(), mode, site);
                slot.out
                    .push(Planned::with_phase(slot.target, n.clone(), action, &p.site));
                return Ok(Some(self.ends(None, 0.0, &n, p)));
            }
            None => given,
        };
        // A group's members follow the part between the offsets already (group_path), and so
        // does a member of random traffic after a run-time condition (`member_path`).
        let offsets = !self.groups.contains_key(&inv.actor)
            && !matches!(run_time, Some(RunTimePlace::Lead(..)));
        if inv.kind.along_path() {
            return self.plan_follow_path(p, inv, (given, offsets), slot, name);
        }
        let Slot {
            target, t0, out, ..
        } = slot;
        let Some(
            place @ PlaceArg {
                place:
                    Place::Trajectory {
                        points,
                        times,
                        smooth,
                    },
                site,
                ..
            },
        ) = given
        else {
            return Err(p.site.err(
                K::Argument,
                format!("expected a trajectory in {}(…) (absolute: or relative:, one is mandatory), found none", inv.action),
            ));
        };
        let rising = times.windows(2).all(|w| w[1] > w[0]);
        if points.len() < 2 || points.len() != times.len() || !rising {
            return Err(site.err(
                K::Argument,
                format!(
                    "expected two or more points with as many rising time stamps, found {} points and {} time stamps{}",
                    points.len(),
                    times.len(),
                    if rising { "" } else { " not rising" }
                ),
            ));
        }
        if *smooth {
            check_apart(points, site)?;
        }
        // replay_trajectory follows exactly, "the dynamic limits may be violated".
        if inv.kind == Action::FollowTrajectory {
            check_segment_speeds(points, times, *smooth, site)?;
        }
        let cut = cut(inv, points, *smooth, offsets)?;
        let time = |(k, u): (usize, f64)| times[k] + u * (times[k + 1] - times[k]);
        let span = time(cut.end) - time(cut.start);
        let end = self.end_of(place, cut.end_point)?;
        let n = name(&inv.action);
        let action = along(
            &n,
            points,
            Some(times),
            *smooth,
            FollowingMode::Position,
            site,
        );
        let action = starting_at(action, cut.start_offset);
        out.push(Planned::with_phase(target, n.clone(), action, &p.site));
        if let Some(t) = t0 {
            // At the end: the end point, at the speed the trajectory has there (length per unit
            // of the segment's parameter over its time; at a last point the chord over the time).
            let k = cut.end.0;
            let v = cut.end_rate / (times[k + 1] - times[k]);
            self.track_mut(target).ramp(t + span, t + span, v);
            self.arrive(target, t, span, end);
        }
        // With an end_offset the action would go on to the trajectory's end: the phase (and
        // with its Act the action) ends when the actor is end_offset before it.
        let event = if cut.end_offset > 0.0 { "" } else { n.as_str() };
        Ok(Some(self.ends(t0, span, event, p)))
    }

    /// `follow_path(absolute: path)`: a FollowTrajectoryAction along the path (polyline or
    /// smooth) in following mode `follow` (the vehicle steers along it within its limits,
    /// §8.8.2.16 "respecting the dynamic limits" where replay_path follows exactly), with no
    /// time reference: at the speed the actor has, ending when the engine has it at the path's
    /// end.
    fn plan_follow_path(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        (given, offsets): (Option<&PlaceArg>, bool),
        Slot {
            target, t0, out, ..
        }: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Some(
            place @ PlaceArg {
                place: Place::Path { points, smooth },
                site,
                ..
            },
        ) = given
        else {
            return Err(p.site.err(
                K::Argument,
                format!("expected a path in {}(…) (absolute: map.create_path(points: [...], interpolation: ...), or relative:; one is mandatory), found none", inv.action),
            ));
        };
        if points.len() < 2 {
            return Err(site.err(
                K::Argument,
                format!(
                    "expected two or more points in the path, found {}",
                    points.len()
                ),
            ));
        }
        if *smooth {
            check_apart(points, site)?;
        }
        let v = match t0 {
            Some(t) => self.track(target).at(t).1,
            None => self.last_v.get(target).copied().unwrap_or(0.0),
        };
        let cut = cut(inv, points, *smooth, offsets)?;
        // After a run-time condition a member of random traffic has the speed its model gives
        // it then (§8.7.18.1), which the plan does not know: the engine moves it along the
        // path at that speed (its own acceleration beside the path a free-road acceleration,
        // `member_acceleration`). Its part between the offsets is cut already
        // (`group_path_runtime::member_path`), so its phase ends on the action's completion.
        let model_speed = t0.is_none() && self.random_member(target) && cut.end_offset <= 0.0;
        if v <= 0.0 && !model_speed {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` moving at the start of {}(…) (it moves at the speed it has), found it standing", inv.action),
            ));
        }
        let end = self.end_of(place, cut.end_point)?;
        let n = name(&inv.action);
        // follow_path steers within the vehicle's limits; replay_path follows exactly.
        let mode = if inv.kind == Action::ReplayPath {
            FollowingMode::Position
        } else {
            FollowingMode::Follow
        };
        let action = along(&n, points, None, *smooth, mode, site);
        let action = starting_at(action, cut.start_offset);
        out.push(Planned::with_phase(target, n.clone(), action, &p.site));
        // The path's length between the offsets at v; the engine ends it at the path's end (the
        // phase ends on the action's completion), or, with an end_offset, the phase ends at
        // this time, end_offset before the end.
        let span = cut.length / v;
        if let Some(t) = t0 {
            self.arrive(target, t, span, end);
        }
        if cut.end_offset > 0.0 {
            return Ok(Some(self.ends(t0, span, "", p)));
        }
        Ok(Some(self.ends(None, 0.0, &n, p)))
    }

    /// The lane, s and offset from the lane's centre of the point (x, y) where a path or
    /// trajectory (`place`) ends, which must be in a driving lane of the plan road.
    fn end_of(&self, place: &PlaceArg, (x, y): (f64, f64)) -> Result<(i32, f64, f64), Error> {
        self.lane_position(&PlaceArg {
            place: Place::World { x, y, z: 0.0 },
            ..place.clone()
        })
    }

    /// From `t + span` on, `target` is at `end` (lane, s, offset), having moved sideways since
    /// `t`.
    pub(super) fn arrive(
        &mut self,
        target: &str,
        t: f64,
        span: f64,
        (lane, s1, offset): (i32, f64, f64),
    ) {
        let s_plan = self.s_at(target, t + span);
        let tr = self.track_mut(target);
        tr.jump(t + span, s1 - s_plan);
        tr.set_lane(t + span, lane);
        tr.set_offset(t + span, offset);
        tr.add_move(t, t + span);
    }
}

/// A smooth curve needs consecutive points apart: a segment of no length has no tangent.
pub(super) fn check_apart(points: &[Pose2], site: &Site) -> Result<(), Error> {
    match points
        .windows(2)
        .position(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1) < 1e-6)
    {
        Some(i) => Err(site.err(
            K::Argument,
            format!(
                "expected the points of a smooth path apart, found points {} and {} at the same place",
                i + 1,
                i + 2
            ),
        )),
        None => Ok(()),
    }
}

/// Each segment of a trajectory must be within the vehicle's [`MAX_SPEED`]: its length (the
/// chord, or the smooth curve's) over its time is the average speed the actor needs, which no
/// following of it can lower.
fn check_segment_speeds(
    points: &[Pose2],
    times: &[f64],
    smooth: bool,
    site: &Site,
) -> Result<(), Error> {
    let lengths = segment_lengths(points, smooth);
    for (k, (&length, t)) in lengths.iter().zip(times.windows(2)).enumerate() {
        let v = length / (t[1] - t[0]);
        if v > MAX_SPEED {
            return Err(site.err(
                K::Unsatisfiable,
                format!(
                    "expected a trajectory within the vehicle's {MAX_SPEED} m/s, found segment {} ({length:.2} m in {:.2} s) needs {v:.2} m/s",
                    k + 1,
                    t[1] - t[0]
                ),
            ));
        }
    }
    Ok(())
}
