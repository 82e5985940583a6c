//! The group forms of the actions along given points (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16
//! `follow_path`, §8.8.2.17 `follow_trajectory`, and `replay_path` / `replay_trajectory`) on a
//! vehicle group (§8.7.18, non-normative: it declares no group actions; oscsim's library does,
//! in `groups.osc`).
//!
//! A single-lane group (a column) follows the path in file: every member drives the same path,
//! entering it where member 0 does (the path's start, where member 0 must be), its spacing
//! kept. Member i, d m behind member 0 along its lane at the action's start, gets its own
//! straight lead-in along its lane prepended to the path: points on its lane's centre every
//! [`LEAD_IN_STEP`] m of s or less, from its own place to the path's start. The engine's
//! FollowTrajectoryAction then starts it where it is (a pursuit from its own pose, or the
//! placement at the trajectory's start), never with a cut across to the path's first point.
//!
//! - untimed (`follow_path`, `replay_path`): each member at its own speed along its path;
//! - timed (`follow_trajectory`, `replay_trajectory`): member i's time stamps are member 0's
//!   shifted by d / v₀, v₀ the group's speed (member 0's) at the start, and its lead-in points
//!   are reached at d_k / v₀ after the first stamp (d_k along the lead-in): it passes each
//!   point of the trajectory when member 0 did plus its headway d / v₀.
//!
//! A group spread over several lanes (a common-route group): each member's path is member 0's
//! moved across the road by its offset from member 0 in the road frame (each point to the same
//! s at t + the offset), and, in a row behind, its lead-in as above. Where the road is straight
//! under the path that move is one translation: the same path beside member 0's, of the same
//! length and time stamps. Where the road bends under it the points would move by different
//! vectors, and the path moved is no parallel of member 0's (a bend's parallel curve is longer
//! on its outside and shorter inside, a smooth curve's parallel is no cubic, a corner's is an
//! arc): the members would not keep their places, so that is an error naming the alternatives
//! (a single-lane group, or each member its own path: `g.vehicles[i].follow_path(…)`).
//!
//! A start the plan does not know (after a run-time condition) and `start_offset` /
//! `end_offset` (member 0 would enter or leave the path where the others do not) are errors.

use super::path_shape::{segment_lengths, Pose2};
use super::planner::Planner;
use super::types::{LATERAL_TOLERANCE, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Invoke, Phase, Place, PlaceArg};

/// The largest step in s between the points of a member's lead-in along its lane (m): a chord
/// of 1 m on a lane of radius R leaves it by 1/(8R) m, 2.5 mm at R = 50 m.
const LEAD_IN_STEP: f64 = 1.0;

/// One member's share of a group's path action, at a start the plan knows.
#[derive(Debug, Clone, Copy)]
pub(super) struct Member {
    /// Its offset from member 0 along and across the road (m).
    pub formation: (f64, f64),
    /// The group's speed (member 0's) at the start (m/s).
    pub group_speed: f64,
}

impl Planner<'_> {
    /// Checks that `inv`, a path or trajectory action on group `inv.actor`, can run: a start
    /// the plan knows, no offsets.
    pub(super) fn check_group_path(
        &self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
    ) -> Result<(), Error> {
        let g = &inv.actor;
        if t0.is_none() {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected a start the plan knows for {}(…) on group `{g}` (its members enter the path one behind the other from their places then), found one after a run-time condition", inv.action),
            ));
        }
        for param in ["start_offset", "end_offset"] {
            if let Some(a) = arg(&inv.args, param) {
                return Err(a.site.err(
                    K::Unsupported,
                    format!("expected no {param} in {}(…) on group `{g}` (its members enter the path where member 0 does, at its start, and leave it at its end), found one; give the path the points to follow, or each member its own (`{g}.vehicles[i].{}(…)`)", inv.action, inv.action),
                ));
            }
        }
        Ok(())
    }

    /// The path or trajectory `member` of a group follows when the group follows `given`: its
    /// lead-in along its lane from its place at `t0` to the path's start, where member 0 must
    /// be, then the path; a trajectory's stamps shifted by the lead-in's length over the
    /// group's speed. `None` for member 0 (the path itself).
    pub(super) fn column_place(
        &self,
        inv: &Invoke,
        given: &PlaceArg,
        (target, t0): (&str, f64),
        Member {
            formation: (ds, dt),
            group_speed,
        }: Member,
    ) -> Result<Option<PlaceArg>, Error> {
        let g = &inv.actor;
        let (points, times, smooth) = match &given.place {
            Place::Path { points, smooth } => (points, None, *smooth),
            Place::Trajectory {
                points,
                times,
                smooth,
            } => (points, Some(times), *smooth),
            _ => return Ok(None),
        };
        let Some(&(x0, y0, _)) = points.first() else {
            return Ok(None);
        };
        // Member 0's place at the start: the path's start, where every member enters it.
        let (s, t) = (self.s_at(target, t0), self.t_at(target, t0));
        let (s_lead, t_lead) = (s - ds, t - dt);
        let lead = self.road.world_pose(s_lead, t_lead);
        let away = lead.map_or(f64::INFINITY, |(x, y, _)| (x - x0).hypot(y - y0));
        if away > POSITION_TOLERANCE {
            return Err(given.site.err(
                K::Unsatisfiable,
                format!("expected `{g}.vehicles[0]` at the start of the path when group `{g}` follows it in file (every member enters it there), found it {away:.2} m from ({x0:.2}, {y0:.2})"),
            ));
        }
        // A member beside member 0: the path moved across the road by its offset.
        let moved = (dt.abs() > LATERAL_TOLERANCE)
            .then(|| self.moved_across(inv, given, points, (target, dt)))
            .transpose()?;
        let points = moved.as_deref().unwrap_or(points);
        if ds.abs() <= POSITION_TOLERANCE {
            return Ok(moved.map(|points| PlaceArg {
                place: match times {
                    None => Place::Path { points, smooth },
                    Some(times) => Place::Trajectory {
                        points,
                        times: times.clone(),
                        smooth,
                    },
                },
                ..given.clone()
            }));
        }
        // The lead-in: the member's lane centre (its own t) from its s towards member 0's,
        // facing the lane's driving direction, the path's start its last point.
        let lane = self.track(target).lane(t0);
        let turn = if lane > 0 { std::f64::consts::PI } else { 0.0 };
        let n = ((s_lead - s).abs() / LEAD_IN_STEP).ceil().max(1.0) as usize;
        let mut lead_in: Vec<Pose2> = Vec::with_capacity(n + points.len());
        for k in 0..n {
            let at = s + (s_lead - s) * k as f64 / n as f64;
            let (x, y, h) = self.road.world_pose(at, t).ok_or_else(|| {
                given.site.err(
                    K::Unsatisfiable,
                    format!("expected `{target}` on the plan's roads behind the path's start, found s = {at:.2} m off them"),
                )
            })?;
            lead_in.push((x, y, h + turn));
        }
        let first = lead_in.len();
        lead_in.extend_from_slice(points);
        let along: Vec<f64> = segment_lengths(&lead_in[..=first], smooth)
            .iter()
            .scan(0.0, |d, l| {
                *d += l;
                Some(*d)
            })
            .collect();
        let place = match times {
            None => Place::Path {
                points: lead_in,
                smooth,
            },
            Some(times) => {
                if group_speed <= 0.0 {
                    return Err(given.site.err(
                        K::Unsatisfiable,
                        format!("expected group `{g}` moving at the start of {}(…) (member i's time stamps are shifted by its distance behind member 0 over the group's speed), found it standing", inv.action),
                    ));
                }
                // along[first - 1] is the lead-in's length: the member's distance to the start.
                let t_first = times[0];
                let shift = along[first - 1] / group_speed;
                let mut stamps = Vec::with_capacity(lead_in.len());
                stamps.push(t_first);
                stamps.extend(along[..first - 1].iter().map(|d| t_first + d / group_speed));
                stamps.extend(times.iter().map(|t| t + shift));
                Place::Trajectory {
                    points: lead_in,
                    times: stamps,
                    smooth,
                }
            }
        };
        Ok(Some(PlaceArg {
            place,
            ..given.clone()
        }))
    }
}

impl Planner<'_> {
    /// `points` moved `dt` m across the road (`target`'s offset from member 0): each point to
    /// the same s at t + dt. Where the road is straight under the path that is one translation,
    /// the same path beside member 0's; where it bends, the points would move by different
    /// vectors and the path would be no parallel of member 0's: an error.
    fn moved_across(
        &self,
        inv: &Invoke,
        given: &PlaceArg,
        points: &[Pose2],
        (target, dt): (&str, f64),
    ) -> Result<Vec<Pose2>, Error> {
        let g = &inv.actor;
        let bends = || {
            given.site.err(
                K::Unsupported,
                format!("expected the road straight under the path when group `{g}`, spread over several lanes, follows it in {}(…) (each member's path is member 0's moved across the road by its offset, `{target}` {dt:.2} m), found it bending there: the path moved by its offset in the road frame is no parallel of member 0's (a bend's parallel is longer outside, shorter inside; a smooth curve's parallel is no cubic), so the members would not keep their places; use a single-lane group, or give each member its own (`{g}.vehicles[i].{}(…)`)", inv.action, inv.action),
            )
        };
        let mut by: Option<(f64, f64)> = None;
        let mut out = Vec::with_capacity(points.len());
        for &(x, y, h) in points {
            let (lane, s, offset) = self.road.locate(x, y).ok_or_else(bends)?;
            let t = self.road.lane_center(lane, s) + offset;
            let (x1, y1, _) = self.road.world_pose(s, t + dt).ok_or_else(bends)?;
            let (dx, dy) = (x1 - x, y1 - y);
            match by {
                None => by = Some((dx, dy)),
                Some((bx, by)) if (bx - dx).hypot(by - dy) > TRANSLATION_TOLERANCE => {
                    return Err(bends());
                }
                Some(_) => {}
            }
            let (bx, by) = by.unwrap_or((dx, dy));
            out.push((x + bx, y + by, h));
        }
        Ok(out)
    }
}

/// How far the moves of a path's points across a straight road may differ and still be one
/// translation (m): the road's geometry evaluated at two places.
const TRANSLATION_TOLERANCE: f64 = 1e-6;

/// Whether `kind` moves an actor along given points: the path and trajectory actions.
pub(super) fn along_points(kind: Action) -> bool {
    matches!(
        kind,
        Action::FollowTrajectory
            | Action::FollowPath
            | Action::ReplayTrajectory
            | Action::ReplayPath
    )
}
