//! The group forms of the path and trajectory actions (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16
//! `follow_path`, §8.8.2.17 `follow_trajectory`, `replay_path` / `replay_trajectory`; §8.7.18
//! vehicle groups, non-normative) in a phase that starts on a run-time condition
//! (`group_path` has them at a start the plan knows).
//!
//! After a run-time condition the plan knows no member's place. A group over several lanes
//! still moves as a block: member 0 follows the part as the actor's form does, and member i
//! the part's points at most [`STEP`] m apart, each a RelativeRoadPosition on member i itself
//! at the point's road coordinates less those of the part's start, which the engine resolves
//! when the action starts: the same path as at a known start when member 0 stands at the
//! part's start, which the engine checks then (oscsim's StateCheck: its lane, its s and its
//! offset within 0.5 m; a failure is an error record and a failed run), its stamps member 0's
//! (on a plan of one road: the engine measures s on the road the member is on).
//!
//! A column: member 0 checked at the part's start as above, member i taken at the offset from
//! member 0 the plan last knows, which the engine checks too
//! (`position_actions::formation_check`), its lead-in from there. On a trajectory member i's
//! stamps are shifted by its distance d behind member 0 (the lead-in's length) over the
//! group's speed v₀ at the start, and its lead-in is driven at v₀, as at a known start: the
//! plan does not know v₀, so the engine reads member 0's speed when the action starts and
//! adds each point's distance over it to its stamp (oscsim's FollowTrajectoryAtSpeed,
//! [`ColumnTimes`]); member 0 standing then is an error record and a failed run.
//!
//! A member of random traffic's own `follow_path`/`replay_path` (its own phases start at run
//! time) follows the part between the offsets as member 0 does, its phase ending on the
//! action's completion, with member 0's check for `follow_path` only (`member_path`).
//!
//! A group driving against s (`against`) runs the same on its view: member 0's check is in the
//! view's u = L − s and offset to the drivers' left, which the engine measures so (the check
//! carries the direction, `Planner::chain`), a column member's offset along the direction of
//! travel (`formation_check`), and a block member's RelativeRoadPositions, which are in the road
//! frame, the view's (Δu, Δt) from the part's start turned to (−Δu, −Δt).

use scenario::{PositionKind, StateCheck};

use super::group_path::{followed_part, lead_in_along, place_of, Part, STEP};
use super::path_part::samples;
use super::path_shape::segment_lengths;
use super::planner::Planner;
use super::types::POSITION_TOLERANCE;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Action, Invoke, PlaceArg};

/// The stamps of a column member's trajectory after a run-time start, a + b / v₀ with v₀ the
/// group's speed (member 0's) when the action starts, which the engine reads then (oscsim's
/// FollowTrajectoryAtSpeed): a the part's stamps, the lead-in's all at the first; b the
/// distance along the lead-in to each of its points, then its whole length d at each point of
/// the part. So the lead-in is driven at v₀ and the part's stamps are shifted by d / v₀, as
/// at a known start (`group_path`).
pub(super) struct ColumnTimes {
    /// The entity whose speed at the start the distances are covered at: member 0.
    pub lead: String,
    /// The distance (m) per point.
    pub distances: Vec<f64>,
}

/// What a member of a group over several lanes follows after a run-time start.
pub(super) enum RunTimePlace {
    /// Member 0: the engine's check that it stands at the part's start (the other members'
    /// paths are placed from where they are, as if it did), and the part of the path between
    /// the offsets (`None`: the path as given). Also a member of random traffic's own path
    /// (`member_path`), with the check for `follow_path` only.
    Lead(Option<Box<StateCheck>>, Option<PlaceArg>),
    /// Member i of a column: the engine's check of its offset from member 0 as the plan last
    /// knows it, and its lead-in from there and the part; for a trajectory, the path's stamps
    /// with the lead-in's at the first, and a distance per point (`ColumnTimes`).
    Column(Box<StateCheck>, PlaceArg, Option<ColumnTimes>),
    /// Member i: positions relative to itself, resolved when the action starts, and their
    /// time stamps for a trajectory.
    Relative(Vec<PositionKind>, Option<Vec<f64>>),
}

impl Planner<'_> {
    /// At a run-time start, what `target`, a member of group `inv.actor` (over several lanes),
    /// follows when the group follows `given`: member 0 the part between the offsets, after the
    /// engine's check that it stands at the part's start (0.5 m along and across); member i
    /// that part's points at most [`STEP`] m apart, each a RelativeRoadPosition on member i
    /// itself, (s − s₀, t − t₀) from it, (s, t) the point's road coordinates and (s₀, t₀)
    /// those of the part's first point, which the engine resolves when the action starts:
    /// member i's path is member 0's moved to its place in the road frame when member 0 stands
    /// at the part's start, as at a known start. A column's member i: `run_time_column`.
    pub(super) fn run_time_place(
        &self,
        given: &PlaceArg,
        inv: &Invoke,
        target: &str,
    ) -> Result<Option<RunTimePlace>, Error> {
        if self.random_member(target) && !self.groups.contains_key(&inv.actor) {
            return self.member_path(given, inv, target);
        }
        let Some(lead) = self.groups.get(&inv.actor).and_then(|m| m.first()) else {
            return Ok(None);
        };
        let Some(part) = followed_part(inv, given)? else {
            return Ok(None);
        };
        if lead == target {
            let what = format!(
                "the start of group `{}`'s path in {}(…) at {}",
                inv.actor,
                inv.action,
                given.site.at()
            );
            let check = self.part_start_check(given, &part, what)?;
            let part = part
                .cut
                .then(|| place_of(given, part.points, part.times, part.smooth));
            return Ok(Some(RunTimePlace::Lead(Some(Box::new(check)), part)));
        }
        if !self.across.contains(&inv.actor) {
            return self
                .run_time_column(inv, given, (target, lead), part)
                .map(Some);
        }
        let length: f64 = segment_lengths(&part.points, part.smooth).iter().sum();
        let (dense, stamps) = samples(
            &part.points,
            part.times.as_deref(),
            part.smooth,
            (0.0, length),
            STEP,
        );
        let mut road = Vec::with_capacity(dense.len());
        for &(x, y, _) in &dense {
            let (lane, s, offset) = self.road.locate(x, y).ok_or_else(|| {
                given.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected the path on the plan's roads, found ({x:.2}, {y:.2}) off them"
                    ),
                )
            })?;
            road.push((s, self.road.lane_center(lane, s) + offset));
        }
        let (s0, t0) = road[0];
        // A RelativeRoadPosition is in the road frame: against s the view's u and t (along
        // the direction of travel, to its left) both run the other way.
        let k = if self.road.is_against() { -1.0 } else { 1.0 };
        let kinds = road
            .iter()
            .map(|&(s, t)| PositionKind::RelativeRoad {
                entity_ref: target.to_string(),
                ds: k * (s - s0),
                dt: k * (t - t0),
                orientation: None,
            })
            .collect();
        Ok(Some(RunTimePlace::Relative(kinds, stamps)))
    }

    /// At a run-time start, the path member `target` (i) of a column led by `lead` (member 0)
    /// follows: its lead-in along its lane from member 0's entry point less its offset from
    /// member 0 as the plan last knows it, then the part; with the engine's check of that
    /// offset (`formation_check`), member 0's of the entry point being its own
    /// (`run_time_place`). On a trajectory, its stamps to be completed by the engine with
    /// member 0's speed then ([`ColumnTimes`]).
    fn run_time_column(
        &self,
        inv: &Invoke,
        given: &PlaceArg,
        (target, lead): (&str, &str),
        part: Part,
    ) -> Result<RunTimePlace, Error> {
        let (lane, s, offset) = self.part_start(given, &part)?;
        let t = self.road.lane_center(lane, s) + offset;
        let (check, (ds, dt)) = self.formation_check(inv, &given.site, target)?;
        let member_lane = self.lane_now(target, self.last_known());
        let mut points = self.lead_in(given, target, member_lane, (s + ds, s, t + dt))?;
        let first = points.len();
        points.extend_from_slice(&part.points);
        let Some(times) = part.times else {
            return Ok(RunTimePlace::Column(
                check,
                place_of(given, points, None, part.smooth),
                None,
            ));
        };
        // The lead-in's points along it (its last length, d, to the part's first point).
        let along = lead_in_along(&points, first, part.smooth);
        let d = along[first - 1];
        let mut stamps = vec![times[0]; first];
        stamps.extend_from_slice(&times);
        let mut distances = Vec::with_capacity(points.len());
        distances.push(0.0);
        distances.extend_from_slice(&along[..first - 1]);
        distances.resize(points.len(), d);
        Ok(RunTimePlace::Column(
            check,
            place_of(given, points, Some(stamps), part.smooth),
            Some(ColumnTimes {
                lead: lead.to_string(),
                distances,
            }),
        ))
    }

    /// A member of random traffic's own `follow_path` or `replay_path` after a run-time
    /// condition (the only start its own phases have): where it is and its speed are its
    /// model's (§8.7.18.1), so the plan neither times the phase nor knows where the member
    /// joins the path. It follows the part between the offsets, and its phase ends when the
    /// engine has it at the part's end (the action's completion), at whatever speed its model
    /// gives it (an end_offset timed by the plan's speed ended it elsewhere, or refused a
    /// member the plan had standing). `follow_path` steers from the member's pose onto the
    /// nearest point ahead of the part (the engine's pursuit): from anywhere but the part's
    /// start it would join the path part-way, or, past its end, end at once off it; so the
    /// engine checks then that the member stands at the part's start, as a group's member 0
    /// (0.5 m along and across), a failure an error record and a failed run. `replay_path`
    /// places the member on the part's start at once (following mode `position`).
    fn member_path(
        &self,
        given: &PlaceArg,
        inv: &Invoke,
        target: &str,
    ) -> Result<Option<RunTimePlace>, Error> {
        if !inv.kind.along_path() {
            return Ok(None);
        }
        let Some(part) = followed_part(inv, given)? else {
            return Ok(None);
        };
        let check = match inv.kind {
            Action::FollowPath => {
                let what = format!(
                    "the start of `{target}`'s path in {}(…) at {}",
                    inv.action,
                    given.site.at()
                );
                Some(Box::new(self.part_start_check(given, &part, what)?))
            }
            _ => None,
        };
        let part = part
            .cut
            .then(|| place_of(given, part.points, part.times, part.smooth));
        Ok(Some(RunTimePlace::Lead(check, part)))
    }

    /// The engine's check, named `what`, that an actor stands at `part`'s start: its lane, s
    /// and offset within [`POSITION_TOLERANCE`].
    fn part_start_check(
        &self,
        given: &PlaceArg,
        part: &Part,
        what: String,
    ) -> Result<StateCheck, Error> {
        let (lane, s, offset) = self.part_start(given, part)?;
        let (road, _) = self.road.road_at(s);
        Ok(StateCheck {
            what,
            lane: Some((road.id.clone(), lane)),
            // The view's s and offset, which the engine measures as the roads say: on one
            // road its own s in +s, u = L - s against s; on several the plan's.
            s: Some((s, POSITION_TOLERANCE)),
            offset: Some((offset, POSITION_TOLERANCE)),
            roads: self.chain(),
            ..StateCheck::default()
        })
    }

    /// Where `part` starts on the plan's roads: lane, s, offset from the lane's centre.
    fn part_start(&self, given: &PlaceArg, part: &Part) -> Result<(i32, f64, f64), Error> {
        let (x, y, _) = part.points[0];
        self.road.locate(x, y).ok_or_else(|| {
            given.site.err(
                K::Unsatisfiable,
                format!("expected the path's start on the plan's roads, found ({x:.2}, {y:.2}) off them"),
            )
        })
    }
}
