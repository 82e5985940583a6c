//! The group forms of the actions along given points (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16
//! `follow_path`, §8.8.2.17 `follow_trajectory`, and `replay_path` / `replay_trajectory`) on a
//! vehicle group (§8.7.18, non-normative: it declares no group actions; oscsim's library does,
//! in `groups.osc`).
//!
//! The part of the path the group follows is the part between `start_offset` and `end_offset`
//! (m along the path as given, both 0 unless given): member 0 enters the path there, where it
//! must be at the action's start, and leaves it there; every member enters and leaves its own
//! path (below) at the points that match them, so each member's action ends on its own when it
//! has left its path, as the actor's form ends. A polyline's part is exact (its vertices kept);
//! a smooth path's part is its points at most [`STEP`] m apart (`path_part`).
//!
//! A single-lane group (a column) follows the path in file: every member drives the same path,
//! entering it where member 0 does, its spacing kept. Member i, d m behind member 0 along its
//! lane at the action's start, gets its own lead-in along its lane prepended to the path:
//! points on its lane's centre every [`STEP`] m of s or less, from its own place to where member
//! 0 enters the path. The engine's FollowTrajectoryAction then starts it where it is (a pursuit
//! from its own pose, or the placement at the trajectory's start), never with a cut across to
//! the path's first point.
//!
//! - untimed (`follow_path`, `replay_path`): each member at its own speed along its path;
//! - timed (`follow_trajectory`, `replay_trajectory`): member i's time stamps are member 0's
//!   shifted by d / v₀, v₀ the group's speed (member 0's) at the start, and its lead-in points
//!   are reached at d_k / v₀ after the first stamp (d_k along the lead-in): it passes each
//!   point of the trajectory when member 0 did plus its headway d / v₀.
//!
//! A group spread over several lanes (members beside member 0 at the start) moves as a block:
//! member i's path is member 0's moved to its place in the formation in the road frame, each
//! point at road coordinates (s, t) to (s + Δs, t + Δt), (Δs, Δt) member i's offset from member
//! 0 at the start, with member 0's time stamps: at every time each member is where member 0 is
//! moved by its offset, so the block keeps its shape along the road. Where the move is one
//! translation (the road straight under the path and its moved copy) that is the path itself
//! moved, of any shape, exact. Where the road bends, the moved path is no parallel of member
//! 0's (a bend's parallel is longer outside, shorter inside; a smooth curve's parallel is no
//! cubic), so it is member 0's path's points at most [`STEP`] m apart, each moved: the polyline
//! through them leaves the moved curve by at most its sagitta h²κ/8, 1.4 mm for steps of 1.03 m
//! on lane −3's radius of 108.75 m on `bend.xodr`. A member that is faster outside a bend (its
//! path longer in the same time) is checked against the vehicle's speed like any trajectory; a
//! moved point off the plan's roads is an error at the path.
//!
//! After a run-time condition a block follows as positions relative to each member, a column
//! its lead-in and the path from its checked offset, a trajectory's stamps completed by the
//! engine with the group's speed then (`group_path_runtime`).
//!
//! For a group driving against s (`against`) the plan road is the view of its direction, so the
//! offsets, lead-ins and moved paths above are in u along the direction of travel and t to the
//! drivers' left; after a run-time condition too, the engine's checks carrying the direction
//! and a block's relative positions turned to the road frame (`group_path_runtime`).

use super::path_part::{cut, samples, Samples};
use super::path_shape::{segment_lengths, Pose2};
use super::planner::Planner;
use super::types::{LATERAL_TOLERANCE, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Action, Invoke, Phase, Place, PlaceArg};

/// The largest step between the points of a member's lead-in along its lane (in s), of a
/// smooth path's part and of a path moved round a bend (along member 0's path) (m): a chord of
/// h on a curve of radius R leaves it by h²/(8R), 2.5 mm for 1 m at R = 50 m.
pub(super) const STEP: f64 = 1.0;

/// One member's share of a group's path action, at a start the plan knows.
#[derive(Debug, Clone, Copy)]
pub(super) struct Member {
    /// Its offset from member 0 along and across the road (m).
    pub formation: (f64, f64),
    /// The group's speed (member 0's) at the start (m/s).
    pub group_speed: f64,
}

impl Planner<'_> {
    /// Checks that `inv`, a path or trajectory action on group `inv.actor`, can run: after a
    /// run-time condition, a plan on one road (the engine places each member's path in road
    /// coordinates from where it is then).
    pub(super) fn check_group_path(
        &self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
    ) -> Result<(), Error> {
        let g = &inv.actor;
        if t0.is_none() && self.road.ids().len() > 1 {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected a plan on one road for {}(…) on group `{g}` after a run-time condition (each member's path is placed in road coordinates from where it is then, on the road it is on), found {} roads", inv.action, self.road.ids().len()),
            ));
        }
        Ok(())
    }

    /// The path or trajectory `member` of a group follows when the group follows `given`:
    /// the part between the offsets; for a member of a column, its lead-in along its lane from
    /// its place at `t0` to where member 0 enters the path, a trajectory's stamps shifted by
    /// the lead-in's length over the group's speed; for a member of a group over several
    /// lanes, the part moved by its offset in the road frame. `None` where that is `given`.
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
        let Some(part) = followed_part(inv, given)? else {
            return Ok(None);
        };
        let (points, times, smooth) = (&part.points[..], part.times.as_deref(), part.smooth);
        let &(x0, y0, _) = &points[0];
        // Member 0's place at the start: where every member enters the path.
        let (s, t) = (self.s_at(target, t0), self.t_at(target, t0));
        let (s_lead, t_lead) = (s - ds, t - dt);
        let lead = self.road.world_pose(s_lead, t_lead);
        let away = lead.map_or(f64::INFINITY, |(x, y, _)| (x - x0).hypot(y - y0));
        if away > POSITION_TOLERANCE {
            let at = if part.start_offset > 0.0 {
                format!("{:.2} m along the path", part.start_offset)
            } else {
                "at the start of the path".to_string()
            };
            return Err(given.site.err(
                K::Unsatisfiable,
                format!("expected `{g}.vehicles[0]` {at} when group `{g}` follows it (every member enters it where member 0 does), found it {away:.2} m from ({x0:.2}, {y0:.2})"),
            ));
        }
        let place = |points: Vec<Pose2>, times: Option<Vec<f64>>, smooth: bool| {
            place_of(given, points, times, smooth)
        };
        if ds.abs() <= POSITION_TOLERANCE && dt.abs() <= LATERAL_TOLERANCE {
            // Member 0: the part, where the offsets cut it.
            return Ok(part
                .cut
                .then(|| place(part.points.clone(), part.times.clone(), false)));
        }
        if self.members_beside(g, t0) {
            let ((p, t), smooth) =
                self.moved_in_formation(inv, given, (points, times, smooth), (target, ds, dt))?;
            return Ok(Some(place(p, t, smooth)));
        }
        // The lead-in: the member's lane centre (its own t) from its s towards member 0's,
        // facing the lane's driving direction, member 0's entry point its last point.
        let lane = self.lane_now(target, t0);
        let mut lead_in = self.lead_in(given, target, lane, (s, s_lead, t))?;
        let first = lead_in.len();
        lead_in.extend_from_slice(points);
        let along = lead_in_along(&lead_in, first, smooth);
        let Some(times) = times else {
            return Ok(Some(place(lead_in, None, smooth)));
        };
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
        Ok(Some(place(lead_in, Some(stamps), smooth)))
    }

    /// The points of `target`'s lead-in on its lane `lane`: its lane's centre (t) from its s
    /// towards member 0's, at most [`STEP`] m of s apart, facing the lane's driving direction;
    /// member 0's entry point (the path's, appended by the caller) ends it.
    pub(super) fn lead_in(
        &self,
        given: &PlaceArg,
        target: &str,
        lane: i32,
        (s, s_lead, t): (f64, f64, f64),
    ) -> Result<Vec<Pose2>, Error> {
        let turn = if lane > 0 { std::f64::consts::PI } else { 0.0 };
        let n = ((s_lead - s).abs() / STEP).ceil().max(1.0) as usize;
        let mut lead_in: Vec<Pose2> = Vec::with_capacity(n);
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
        Ok(lead_in)
    }

    /// Whether some member of group `g` is beside member 0 (t differs) at `t0`: a group over
    /// several lanes, which moves as a block.
    fn members_beside(&self, g: &str, t0: f64) -> bool {
        let Some(members) = self.groups.get(g) else {
            return false;
        };
        let t_lead = self.t_at(&members[0], t0);
        members
            .iter()
            .any(|m| (self.t_at(m, t0) - t_lead).abs() > LATERAL_TOLERANCE)
    }

    /// The part `points` (with `times`) of member 0 moved to `target`'s place in the
    /// formation, (ds, dt) from member 0 in the road frame: the part translated where every
    /// point moves by one vector, else its points at most [`STEP`] m apart each moved, a
    /// polyline with member 0's stamps.
    fn moved_in_formation(
        &self,
        inv: &Invoke,
        given: &PlaceArg,
        (points, times, smooth): (&[Pose2], Option<&[f64]>, bool),
        (target, ds, dt): (&str, f64, f64),
    ) -> Result<(Samples, bool), Error> {
        let g = &inv.actor;
        let off = |x: f64, y: f64| {
            given.site.err(
                K::Unsatisfiable,
                format!("expected the path moved to `{target}`'s place in group `{g}` ({ds:.2} m along the road, {dt:.2} m across it from member 0) on the plan's roads, found the point ({x:.2}, {y:.2}) moved off them"),
            )
        };
        // (x, y) moved (ds, dt) in the road frame, and the road's turn between the two places.
        let moved = |x: f64, y: f64| -> Result<(f64, f64, f64), Error> {
            let (lane, s, offset) = self.road.locate(x, y).ok_or_else(|| off(x, y))?;
            let t = self.road.lane_center(lane, s) + offset;
            let (_, _, h0) = self.road.world_pose(s, t).ok_or_else(|| off(x, y))?;
            let (x1, y1, h1) = self
                .road
                .world_pose(s + ds, t + dt)
                .ok_or_else(|| off(x, y))?;
            Ok((x1, y1, h1 - h0))
        };
        let length: f64 = segment_lengths(points, smooth).iter().sum();
        let (dense, stamps) = samples(points, times, smooth, (0.0, length), STEP);
        let mut moves = Vec::with_capacity(dense.len());
        for &(x, y, h) in &dense {
            let (x1, y1, turn) = moved(x, y)?;
            moves.push((x1, y1, h + turn));
        }
        let by = (moves[0].0 - dense[0].0, moves[0].1 - dense[0].1);
        let translation = dense
            .iter()
            .zip(&moves)
            .all(|(a, b)| (b.0 - a.0 - by.0).hypot(b.1 - a.1 - by.1) <= TRANSLATION_TOLERANCE);
        if translation {
            let p = points.iter().map(|&(x, y, h)| (x + by.0, y + by.1, h));
            return Ok(((p.collect(), times.map(<[f64]>::to_vec)), smooth));
        }
        Ok(((moves, stamps), false))
    }
}

/// The part of a group's path its members follow: the points between the offsets (a polyline
/// of them where the offsets cut the path), their stamps, whether smooth.
pub(super) struct Part {
    pub points: Vec<Pose2>,
    pub times: Option<Vec<f64>>,
    pub smooth: bool,
    /// The offsets cut the path (`points` is a part of it).
    pub cut: bool,
    /// The start_offset (m).
    pub start_offset: f64,
}

/// The [`Part`] of `given`'s path or trajectory that a group follows in `inv`: the part
/// between `start_offset` and `end_offset` (exact for a polyline, points [`STEP`] m apart on a
/// smooth curve). `None` for a place that is no path, or one the actor's form reports as wrong.
pub(super) fn followed_part(inv: &Invoke, given: &PlaceArg) -> Result<Option<Part>, Error> {
    let (points, times, smooth) = match &given.place {
        Place::Path { points, smooth } => (points, None, *smooth),
        Place::Trajectory {
            points,
            times,
            smooth,
        } => (points, Some(times.as_slice()), *smooth),
        _ => return Ok(None),
    };
    if points.len() < 2 || times.is_some_and(|t| t.len() != points.len()) {
        return Ok(None);
    }
    let c = cut(inv, points, smooth, true)?;
    if c.start_offset <= 0.0 && c.end_offset <= 0.0 {
        return Ok(Some(Part {
            points: points.clone(),
            times: times.map(<[f64]>::to_vec),
            smooth,
            cut: false,
            start_offset: 0.0,
        }));
    }
    let step = if smooth { STEP } else { f64::INFINITY };
    let to = c.start_offset + c.length;
    let (p, t) = samples(points, times, smooth, (c.start_offset, to), step);
    Ok(Some(Part {
        points: p,
        times: t,
        smooth: false,
        cut: true,
        start_offset: c.start_offset,
    }))
}

/// `given` with the path (`times`: the trajectory) through `points`.
pub(super) fn place_of(
    given: &PlaceArg,
    points: Vec<Pose2>,
    times: Option<Vec<f64>>,
    smooth: bool,
) -> PlaceArg {
    PlaceArg {
        place: match times {
            None => Place::Path { points, smooth },
            Some(times) => Place::Trajectory {
                points,
                times,
                smooth,
            },
        },
        ..given.clone()
    }
}

/// The distance (m) along `points`, a lead-in of `first` points followed by the path, from
/// its first point to each of its points 1 to `first` (the last, the path's first point: the
/// lead-in's length).
pub(super) fn lead_in_along(points: &[Pose2], first: usize, smooth: bool) -> Vec<f64> {
    segment_lengths(&points[..=first], smooth)
        .iter()
        .scan(0.0, |d, l| {
            *d += l;
            Some(*d)
        })
        .collect()
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
